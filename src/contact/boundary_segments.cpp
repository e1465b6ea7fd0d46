#include "contact/boundary_segments.hpp"

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "core/error.hpp"

namespace flotsam {

void BoundarySegments::add_segment(const Vec2& a, const Vec2& b, int group_index) {
  start.push_back(a);
  end.push_back(b);
  normal.push_back(perp(b - a).normalized());
  group.push_back(group_index);
  if (!band_lower.empty()) {
    band_lower.push_back(-infinity);
    band_upper.push_back(infinity);
  }
}

void BoundarySegments::add_banded_segment(const Vec2& a, const Vec2& b, int group_index,
                                          double lower, double upper) {
  band_lower.resize(start.size(), -infinity);
  band_upper.resize(start.size(), infinity);
  add_segment(a, b, group_index);
  band_lower.back() = lower;
  band_upper.back() = upper;
}

void BoundarySegments::add_circle_hole(const Vec2& centre, double radius, int sides,
                                       int group_index) {
  // Clockwise around the centre, so that the water (outside) is on each segment's left.
  for (int k = 0; k < sides; ++k) {
    const double t0 = -2.0 * pi * k / sides, t1 = -2.0 * pi * (k + 1) / sides;  // [rad]
    add_segment(centre + radius * Vec2(std::cos(t0), std::sin(t0)),
                centre + radius * Vec2(std::cos(t1), std::sin(t1)), group_index);
  }
}

void BoundarySegments::build_grid(double requested_cell_size) {
  cell_start.assign(1, 0);
  cell_segments.clear();
  columns = rows = 0;
  if (start.empty()) return;
  Aabb extent{start[0], start[0]};
  double total_length = 0.0;  // [m]
  for (int s = 0; s < size(); ++s) {
    for (const Vec2& p : {start[s], end[s]}) {
      extent.lower = extent.lower.cwiseMin(p);
      extent.upper = extent.upper.cwiseMax(p);
    }
    total_length += (end[s] - start[s]).norm();
  }
  const double span = std::max((extent.upper - extent.lower).maxCoeff(), 1e-12);  // [m]
  cell_size = requested_cell_size > 0.0 ? requested_cell_size : total_length / size();
  cell_size = std::max(cell_size, span / 1000.0);
  grid_origin = extent.lower;
  columns = static_cast<int>((extent.upper.x() - extent.lower.x()) / cell_size) + 1;
  rows = static_cast<int>((extent.upper.y() - extent.lower.y()) / cell_size) + 1;

  // Counting sort of (cell, segment) entries: count, prefix sum, fill.
  auto cells_of = [&](int s, auto&& visit) {
    const Vec2 lo = (start[s].cwiseMin(end[s]) - grid_origin) / cell_size;
    const Vec2 hi = (start[s].cwiseMax(end[s]) - grid_origin) / cell_size;
    const int i0 = std::clamp(static_cast<int>(lo.x()), 0, columns - 1);
    const int i1 = std::clamp(static_cast<int>(hi.x()), 0, columns - 1);
    const int j0 = std::clamp(static_cast<int>(lo.y()), 0, rows - 1);
    const int j1 = std::clamp(static_cast<int>(hi.y()), 0, rows - 1);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) visit(j * columns + i);
    }
  };
  cell_start.assign(static_cast<std::size_t>(columns * rows) + 1, 0);
  for (int s = 0; s < size(); ++s) cells_of(s, [&](int c) { ++cell_start[c + 1]; });
  for (std::size_t c = 1; c < cell_start.size(); ++c) cell_start[c] += cell_start[c - 1];
  cell_segments.resize(static_cast<std::size_t>(cell_start.back()));
  std::vector<int> fill(cell_start.begin(), cell_start.end() - 1);
  for (int s = 0; s < size(); ++s) cells_of(s, [&](int c) { cell_segments[fill[c]++] = s; });
}

void BoundarySegments::query(const Aabb& box, std::vector<int>& found, std::vector<int>& stamp,
                             int& stamp_value) const {
  found.clear();
  if (columns == 0) return;
  if (stamp.size() != start.size()) stamp.assign(start.size(), 0), stamp_value = 0;
  ++stamp_value;
  const Vec2 lo = (box.lower - grid_origin) / cell_size, hi = (box.upper - grid_origin) / cell_size;
  if (hi.x() < 0.0 || hi.y() < 0.0 || lo.x() >= columns || lo.y() >= rows) return;
  const int i0 = std::max(static_cast<int>(lo.x()), 0);
  const int i1 = std::min(static_cast<int>(hi.x()), columns - 1);
  const int j0 = std::max(static_cast<int>(lo.y()), 0);
  const int j1 = std::min(static_cast<int>(hi.y()), rows - 1);
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      const int c = j * columns + i;
      for (int k = cell_start[c]; k < cell_start[c + 1]; ++k) {
        const int s = cell_segments[k];
        if (stamp[s] == stamp_value) continue;
        stamp[s] = stamp_value;
        found.push_back(s);
      }
    }
  }
  std::sort(found.begin(), found.end());
}

BoundarySegments extract_boundary_segments(const Mesh& mesh, const std::vector<int>& solid_groups) {
  BoundarySegments segments;
  segments.group_names = mesh.group_names;
  for (const BoundaryEdge& edge : mesh.boundary) {
    if (std::find(solid_groups.begin(), solid_groups.end(), edge.group) == solid_groups.end()) {
      continue;
    }
    // Elements are counter-clockwise, so the water is on the left of vertex k -> vertex k+1.
    const auto [a, b, mid] = mesh.edge_nodes(edge.element, edge.local_edge);
    const Vec2 pa = mesh.nodes[a], pb = mesh.nodes[b], pm = mesh.nodes[mid];
    const double bulge = std::abs(cross(pb - pa, pm - pa)) / (pb - pa).norm();  // [m]
    if (bulge > 1e-9 * (pb - pa).norm()) {  // curved P2 edge: split at its mid node
      segments.add_segment(pa, pm, edge.group);
      segments.add_segment(pm, pb, edge.group);
    } else {
      segments.add_segment(pa, pb, edge.group);
    }
  }
  segments.build_grid();
  return segments;
}

std::vector<int> solid_group_indices(const Mesh& mesh,
                                     const std::vector<BoundaryCondition>& conditions) {
  std::vector<int> groups;
  for (const BoundaryCondition& bc : conditions) {
    if (bc.kind != BoundaryCondition::Kind::wall && bc.kind != BoundaryCondition::Kind::noslip) {
      continue;
    }
    const int g = mesh.find_group(bc.group);
    if (g < 0) {
      std::string known;  // the mesh's groups, for the message
      for (const std::string& name : mesh.group_names)
        known += (known.empty() ? "'" : ", '") + name + "'";
      throw_input_error(
          "boundary condition for group '{}' (case line {}): mesh {} has no such group; its "
          "boundary groups are {}",
          bc.group, bc.line, mesh.source, known.empty() ? std::string("none") : known);
    }
    groups.push_back(g);
  }
  return groups;
}

}  // namespace flotsam
