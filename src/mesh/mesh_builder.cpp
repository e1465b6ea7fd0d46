// build_mesh: from the plain lists of a reader or generator to a validated P2 mesh.
//
//   1. check every triangle: 3 or 6 nodes, counter-clockwise, not degenerate;
//   2. check every node is used by some triangle;
//   3. renumber: corner nodes (P1 vertices) first, then mid nodes;
//   4. collect edges: at most two triangles per edge (manifold), neighbours across each;
//   5. mid nodes: shared by both triangles of an edge; taken from a 3-node boundary line (on the
//      curve) or created at the straight midpoint when no element or line provides one;
//   6. boundary edges: each must lie on a named physical line group;
//   7. the final numbering: nodes and elements along a space-filling curve (curve_order.hpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "core/error.hpp"
#include "mesh/curve_order.hpp"
#include "mesh/element_order.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {
namespace {

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

struct EdgeUse {
  int element[2] = {-1, -1};
  int local_edge[2] = {-1, -1};
  int count = 0;
  int mid = -1;  // raw index of the mid node, -1 until known
};

void check_triangles(const RawMesh& raw) {
  for (std::size_t t = 0; t < raw.triangles.size(); ++t) {
    const auto& tri = raw.triangles[t];
    const long tag = raw.triangle_tags.empty() ? static_cast<long>(t + 1) : raw.triangle_tags[t];
    if (tri.size() != 3 && tri.size() != 6)
      throw_input_error("{}: element {} has {} nodes; expected a 3- or 6-node triangle", raw.source,
                        tag, tri.size());
    for (int n : tri)
      if (n < 0 || n >= static_cast<int>(raw.nodes.size()))
        throw_input_error("{}: element {} refers to a node that does not exist", raw.source, tag);
    const Vec2 &a = raw.nodes[tri[0]], &b = raw.nodes[tri[1]], &c = raw.nodes[tri[2]];
    const double twice_area = cross(b - a, c - a);
    const double longest2 =
        std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    if (!(std::abs(twice_area) > 1e-12 * longest2))
      throw_input_error("{}: element {} is degenerate (area {:.3g} m^2 for edges up to {:.3g} m)",
                        raw.source, tag, 0.5 * twice_area, std::sqrt(longest2));
    if (twice_area < 0)
      throw_input_error("{}: element {} is inverted (its nodes run clockwise)", raw.source, tag);
  }
}

}  // namespace

Mesh build_mesh(const RawMesh& raw) {
  const int raw_count = static_cast<int>(raw.nodes.size());
  auto node_tag = [&](int n) { return raw.node_tags.empty() ? long{n + 1} : raw.node_tags[n]; };
  auto element_tag = [&](int t) {
    return raw.triangle_tags.empty() ? long{t + 1} : raw.triangle_tags[t];
  };
  if (raw.triangles.empty()) throw_input_error("{}: the mesh has no triangles", raw.source);
  check_triangles(raw);

  // 2-3. Usage and vertex-first renumbering.
  std::vector<char> is_vertex(raw_count, 0), is_used(raw_count, 0);
  for (const auto& tri : raw.triangles) {
    for (int k = 0; k < 3; ++k) is_vertex[tri[k]] = is_used[tri[k]] = 1;
    for (std::size_t k = 3; k < tri.size(); ++k) is_used[tri[k]] = 1;
  }
  for (const auto& line : raw.lines)  // a 3-node line's mid node (on the curve) is used too
    if (line.nodes.size() == 3 && line.nodes[2] >= 0 && line.nodes[2] < raw_count)
      is_used[line.nodes[2]] = 1;
  for (int n = 0; n < raw_count; ++n)
    if (!is_used[n])
      throw_input_error("{}: node {} is not used by any triangle", raw.source, node_tag(n));

  Mesh mesh;
  mesh.source = raw.source;
  std::vector<int> new_index(raw_count, -1);
  for (int n = 0; n < raw_count; ++n)
    if (is_vertex[n]) {
      new_index[n] = static_cast<int>(mesh.nodes.size());
      mesh.nodes.push_back(raw.nodes[n]);
      mesh.node_tags.push_back(node_tag(n));
    }
  mesh.vertex_count = static_cast<int>(mesh.nodes.size());
  for (int n = 0; n < raw_count; ++n)
    if (is_used[n] && !is_vertex[n]) {
      new_index[n] = static_cast<int>(mesh.nodes.size());
      mesh.nodes.push_back(raw.nodes[n]);
      mesh.node_tags.push_back(node_tag(n));
    }

  // 4-5. Edges, adjacency and shared mid nodes.
  const int element_count = static_cast<int>(raw.triangles.size());
  std::unordered_map<std::uint64_t, EdgeUse> edges;
  edges.reserve(static_cast<std::size_t>(element_count) * 2);
  for (int t = 0; t < element_count; ++t) {
    const auto& tri = raw.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      EdgeUse& use = edges[edge_key(a, b)];
      if (use.count == 2)
        throw_input_error(
            "{}: the edge between nodes {} and {} is shared by more than two elements ({}, {} and "
            "{}): the mesh is not manifold",
            raw.source, node_tag(a), node_tag(b), element_tag(use.element[0]),
            element_tag(use.element[1]), element_tag(t));
      use.element[use.count] = t;
      use.local_edge[use.count] = k;
      ++use.count;
      if (tri.size() == 6) {
        const int mid = tri[3 + k];
        if (use.mid >= 0 && use.mid != mid)
          throw_input_error(
              "{}: elements {} and {} share the edge between nodes {} and {} but not its mid node "
              "({} and {})",
              raw.source, element_tag(use.element[0]), element_tag(t), node_tag(a), node_tag(b),
              node_tag(use.mid), node_tag(mid));
        use.mid = mid;
      }
    }
  }

  // Boundary lines: their group name, and for 3-node lines the mid node on the curve.
  std::unordered_map<std::uint64_t, const RawMesh::Line*> line_of_edge;
  for (const auto& line : raw.lines) {
    if (line.nodes.size() < 2) continue;
    line_of_edge[edge_key(line.nodes[0], line.nodes[1])] = &line;
  }

  mesh.elements.resize(element_count);
  mesh.neighbours.resize(element_count);
  mesh.area.resize(element_count);
  mesh.element_tags.resize(element_count);
  for (int t = 0; t < element_count; ++t) {
    const auto& tri = raw.triangles[t];
    for (int k = 0; k < 3; ++k) mesh.elements[t][k] = new_index[tri[k]];
    mesh.element_tags[t] = element_tag(t);
  }

  // Edges visited in element order, each once (from its first element), so that the numbering
  // of created mid nodes and of boundary edges does not depend on the hash map's order.
  for (int t0 = 0; t0 < element_count; ++t0)
    for (int k0 = 0; k0 < 3; ++k0) {
      const int a = raw.triangles[t0][k0], b = raw.triangles[t0][(k0 + 1) % 3];
      const std::uint64_t key = edge_key(a, b);
      const EdgeUse& use = edges.at(key);
      if (use.element[0] != t0 || use.local_edge[0] != k0) continue;
      const RawMesh::Line* line = nullptr;
      if (auto it = line_of_edge.find(key); it != line_of_edge.end()) line = it->second;
      int mid = use.mid >= 0 ? new_index[use.mid] : -1;
      if (mid < 0 && line != nullptr && line->nodes.size() == 3) {
        // A 3-node line gives the mid node on the curve; it may belong to no triangle.
        const int raw_mid = line->nodes[2];
        mid = new_index[raw_mid];
        if (mid < 0) {
          mid = new_index[raw_mid] = static_cast<int>(mesh.nodes.size());
          mesh.nodes.push_back(raw.nodes[raw_mid]);
          mesh.node_tags.push_back(node_tag(raw_mid));
        }
      }
      if (mid < 0) {
        mid = static_cast<int>(mesh.nodes.size());
        mesh.nodes.push_back(0.5 * (raw.nodes[a] + raw.nodes[b]));
        mesh.node_tags.push_back(0);  // created here: no tag in the file
      }
      for (int s = 0; s < use.count; ++s)
        mesh.elements[use.element[s]][3 + use.local_edge[s]] = mid;
      if (use.count == 2) {
        mesh.neighbours[t0][k0] = use.element[1];
        mesh.neighbours[use.element[1]][use.local_edge[1]] = t0;
        continue;
      }
      // 6. A boundary edge needs a named group.
      if (line == nullptr || line->group.empty())
        throw_input_error(
            "{}: the boundary edge between nodes {} and {} (element {}) belongs to no named "
            "physical group; every boundary edge needs one (inflow, outflow, wall, ...)",
            raw.source, node_tag(a), node_tag(b), element_tag(t0));
      int group = mesh.find_group(line->group);
      if (group < 0) {
        group = static_cast<int>(mesh.group_names.size());
        mesh.group_names.push_back(line->group);
      }
      mesh.neighbours[t0][k0] = -(static_cast<int>(mesh.boundary.size()) + 1);
      mesh.boundary.push_back({t0, k0, group});
    }

  // Group names in a reproducible order too: by name.
  std::vector<std::string> names = mesh.group_names;
  std::sort(names.begin(), names.end());
  for (auto& edge : mesh.boundary)
    edge.group = static_cast<int>(
        std::find(names.begin(), names.end(), mesh.group_names[edge.group]) - names.begin());
  mesh.group_names = std::move(names);

  for (int t = 0; t < element_count; ++t) mesh.area[t] = 0.5 * mesh.jacobian(t).determinant();
  // Nodes along the curve, elements in Cuthill-McKee order from it (docs/mesh.md
  // "Numbering").
  return ordered_by_cuthill_mckee(ordered_along_curve(mesh));
}

}  // namespace flotsam
