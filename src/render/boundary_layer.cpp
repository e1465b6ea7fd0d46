#include "render/boundary_layer.hpp"

#include <algorithm>
#include <array>
#include <unordered_map>

#include "render/cairo_draw.hpp"

namespace flotsam {
namespace {

/// Appends edge b (from its first end to its second) to the current path. The P2 edge is the
/// parabola through ends A, C and mid node M: as a quadratic Bezier its control point is
/// Q = 2 M - (A + C) / 2; Cairo takes the equal cubic with controls A + 2/3 (Q - A) and
/// C + 2/3 (Q - C). The map to pixels is affine, so this holds in pixels too.
void append_edge(cairo_t* cr, const Mesh& mesh, const FrameLayout& layout, int b, bool start) {
  const BoundaryEdge& edge = mesh.boundary[b];
  const auto nodes = mesh.edge_nodes(edge.element, edge.local_edge);
  const Vec2 A = layout.to_pixel(mesh.nodes[nodes[0]]);
  const Vec2 C = layout.to_pixel(mesh.nodes[nodes[1]]);
  const Vec2 M = layout.to_pixel(mesh.nodes[nodes[2]]);
  if (start) cairo_move_to(cr, A.x(), A.y());
  const Vec2 Q = 2.0 * M - 0.5 * (A + C);
  const Vec2 c1 = A + 2.0 / 3.0 * (Q - A);
  const Vec2 c2 = C + 2.0 / 3.0 * (Q - C);
  cairo_curve_to(cr, c1.x(), c1.y(), c2.x(), c2.y(), C.x(), C.y());
}

BoundaryKind kind_of(const Scene& scene, int group) {
  if (!scene.boundary_kinds.empty()) return scene.boundary_kinds[group];
  return default_boundary_kind(scene.mesh->group_names[group]);
}

void stroke_style(cairo_t* cr, BoundaryKind kind, double f) {
  if (kind == BoundaryKind::wall) {
    set_colour(cr, wall_colour);
    cairo_set_line_width(cr, std::max(1.5, 0.2 * f));
    cairo_set_dash(cr, nullptr, 0, 0.0);
  } else {
    set_colour(cr, open_colour);
    cairo_set_line_width(cr, std::max(1.5, 0.2 * f));
    const double dashes[] = {0.7 * f, 0.4 * f};
    cairo_set_dash(cr, dashes, 2, 0.0);
  }
}

}  // namespace

std::vector<BoundaryLoop> boundary_loops(const Mesh& mesh) {
  // Pseudocode: index edges by their first vertex; from each unused edge follow "the edge that
  // starts where this one ends" until back at the start. Each vertex of a manifold boundary
  // starts exactly one edge.
  const int n = static_cast<int>(mesh.boundary.size());
  std::unordered_multimap<int, int> starting_at;
  std::vector<std::array<int, 3>> ends(n);
  for (int b = 0; b < n; ++b) {
    ends[b] = mesh.edge_nodes(mesh.boundary[b].element, mesh.boundary[b].local_edge);
    starting_at.emplace(ends[b][0], b);
  }
  std::vector<char> used(n, 0);
  std::vector<BoundaryLoop> loops;
  for (int first = 0; first < n; ++first) {
    if (used[first]) continue;
    BoundaryLoop loop;
    int b = first;
    while (b >= 0 && !used[b]) {
      used[b] = 1;
      loop.edges.push_back(b);
      // Shoelace over A -> M -> C: twice the area is sum cross(P_k, P_k+1).
      const Vec2& A = mesh.nodes[ends[b][0]];
      const Vec2& C = mesh.nodes[ends[b][1]];
      const Vec2& M = mesh.nodes[ends[b][2]];
      loop.signed_area += 0.5 * (cross(A, M) + cross(M, C));
      int next = -1;
      const auto [lo, hi] = starting_at.equal_range(ends[b][1]);
      for (auto it = lo; it != hi; ++it) {
        if (!used[it->second]) next = it->second;
      }
      b = next;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

void draw_boundaries(cairo_t* cr, const Scene& scene, const FrameLayout& layout) {
  const Mesh& mesh = *scene.mesh;
  const double f = layout.font_size;
  cairo_save(cr);
  cairo_rectangle(cr, layout.plot.x0, layout.plot.y0, layout.plot.width(), layout.plot.height());
  cairo_clip(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);

  const auto loops = boundary_loops(mesh);
  for (const BoundaryLoop& loop : loops) {
    if (!loop.is_hole()) continue;
    for (std::size_t k = 0; k < loop.edges.size(); ++k) {
      append_edge(cr, mesh, layout, loop.edges[k], k == 0);
    }
    cairo_close_path(cr);
    set_colour(cr, pier_colour);
    cairo_fill(cr);
  }
  // Runs of consecutive edges of one kind make one path each, so dashes flow along them.
  for (const BoundaryLoop& loop : loops) {
    const auto kind_at = [&](std::size_t k) {
      return loop.is_hole() ? BoundaryKind::wall
                            : kind_of(scene, mesh.boundary[loop.edges[k]].group);
    };
    std::size_t k = 0;
    while (k < loop.edges.size()) {
      const BoundaryKind kind = kind_at(k);
      append_edge(cr, mesh, layout, loop.edges[k], true);
      for (++k; k < loop.edges.size() && kind_at(k) == kind; ++k) {
        append_edge(cr, mesh, layout, loop.edges[k], false);
      }
      stroke_style(cr, kind, f);
      cairo_stroke(cr);
    }
  }
  // Decks: the pier colour, translucent, outlined as walls.
  for (const auto& deck : scene.decks) {
    for (std::size_t k = 0; k < deck.size(); ++k) {
      const Vec2 p = layout.to_pixel(deck[k]);
      k == 0 ? cairo_move_to(cr, p.x(), p.y()) : cairo_line_to(cr, p.x(), p.y());
    }
    cairo_close_path(cr);
    set_colour(cr, pier_colour, 0.45);
    cairo_fill_preserve(cr);
    stroke_style(cr, BoundaryKind::wall, 0.5 * f);
    cairo_stroke(cr);
  }
  cairo_restore(cr);
}

}  // namespace flotsam
