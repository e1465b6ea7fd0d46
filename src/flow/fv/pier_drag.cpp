#include "flow/fv/pier_drag.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "bridges/bridge_config.hpp"
#include "core/constants.hpp"

namespace flotsam {

namespace {

struct Segment {
  Vec2 a, b;
};

double distance_to(const Segment& s, const Vec2& p) {  // [m]
  const Vec2 d = s.b - s.a;
  const double t = std::clamp(d.dot(p - s.a) / d.squaredNorm(), 0.0, 1.0);
  return (s.a + t * d - p).norm();
}

// The outline's smallest width [m]: the least extent of its vertices along a direction, over
// directions a degree apart (within a factor 1 - cos(0.5 deg) of the exact one).
double smallest_width(const std::vector<Segment>& outline) {
  double width = std::numeric_limits<double>::max();
  for (int k = 0; k < 180; ++k) {
    const double angle = pi * k / 180.0;
    const Vec2 direction(std::cos(angle), std::sin(angle));
    double low = std::numeric_limits<double>::max(), high = -low;
    for (const Segment& s : outline) {
      low = std::min(low, direction.dot(s.a)), high = std::max(high, direction.dot(s.a));
    }
    width = std::min(width, high - low);
  }
  return width;
}

// The diameter of the circle through the outline's vertices when they all lie on one (a meshed
// circle, whose polygon is narrower than the pier it stands for), else 0.
double circle_diameter(const std::vector<Segment>& outline) {
  const std::size_t n = outline.size();
  if (n < 3) return 0.0;
  const Vec2 a = outline[0].a, b = outline[n / 3].a, c = outline[2 * n / 3].a;
  const double d = 2.0 * cross(b - a, c - a);
  if (d == 0.0) return 0.0;
  // The circumcentre of a, b, c, relative to a.
  const Vec2 ab = b - a, ac = c - a;
  const Vec2 centre = a + Vec2(ac.y() * ab.squaredNorm() - ab.y() * ac.squaredNorm(),
                               ab.x() * ac.squaredNorm() - ac.x() * ab.squaredNorm()) /
                              d;
  const double radius = (a - centre).norm();
  for (const Segment& s : outline)
    if (std::abs((s.a - centre).norm() - radius) > 1e-6 * radius) return 0.0;
  return 2.0 * radius;
}

bool is_pier(const std::string& group, const std::vector<BridgeConfig>& bridges) {
  if (group.starts_with("pier")) return true;
  for (const BridgeConfig& bridge : bridges)
    if (std::ranges::find(bridge.pier_groups, group) != bridge.pier_groups.end()) return true;
  return false;
}

}  // namespace

Vec2 PierDrag::total_impulse() const {
  Vec2 sum = Vec2::Zero();
  for (const int i : cells) sum += impulse[i];
  return sum;
}

Vec2 PierDrag::impulse_of(int p) const {
  Vec2 sum = Vec2::Zero();
  for (const int i : piers[p].ring) sum += (piers[p].density / density[i]) * impulse[i];
  return sum;
}

PierDrag find_pier_drag(const Mesh& mesh, const CellMesh& cells,
                        const std::vector<BridgeConfig>& bridges, double drag_coefficient) {
  PierDrag drag;
  if (drag_coefficient <= 0.0) return drag;
  // Each pier's outline: its group's boundary edges, from their left cells' corners; and those
  // cells, in its ring whatever their size (a pier narrower than the cells beside it).
  std::vector<std::vector<Segment>> outlines(mesh.group_names.size());
  std::vector<std::vector<int>> beside(mesh.group_names.size());
  for (const int e : cells.boundary_edges) {
    const int group = cells.group[e];
    if (!is_pier(mesh.group_names[group], bridges)) continue;
    const int i = cells.left[e], k = cells.left_slot[e];
    outlines[group].push_back(
        {mesh.nodes[cells.corners[i][k]], mesh.nodes[cells.corners[i][(k + 1) % 3]]});
    beside[group].push_back(i);
  }
  for (std::size_t group = 0; group < outlines.size(); ++group) {
    const std::vector<Segment>& outline = outlines[group];
    if (outline.empty()) continue;
    const double diameter = circle_diameter(outline);
    PierDrag::Pier pier;
    pier.name = mesh.group_names[group];
    pier.width = diameter > 0.0 ? diameter : smallest_width(outline);
    Vec2 low = outline.front().a, high = low;
    for (const Segment& s : outline) low = low.cwiseMin(s.a), high = high.cwiseMax(s.a);
    low -= Vec2::Constant(pier.width), high += Vec2::Constant(pier.width);
    std::vector<int>& ring = pier.ring;
    for (int i = 0; i < cells.cell_count; ++i) {
      const Vec2& c = cells.centroid[i];
      if (c.x() < low.x() || c.y() < low.y() || c.x() > high.x() || c.y() > high.y()) continue;
      const bool near =
          std::ranges::any_of(outline,
                              [&](const Segment& s) { return distance_to(s, c) <= pier.width; }) ||
          std::ranges::find(beside[group], i) != beside[group].end();
      if (!near) continue;
      ring.push_back(i);
      pier.ring_area += cells.area[i];
    }
    if (drag.density.empty()) drag.density.assign(cells.cell_count, 0.0);
    pier.density = drag_coefficient * pier.width / (2.0 * pier.ring_area);  // (M-25) C_d b / 2 A_r
    for (const int i : ring) drag.density[i] += pier.density;
    drag.piers.push_back(std::move(pier));
  }
  for (int i = 0; i < static_cast<int>(drag.density.size()); ++i)
    if (drag.density[i] > 0.0) drag.cells.push_back(i);
  if (!drag.cells.empty()) drag.impulse.assign(cells.cell_count, Vec2::Zero());
  return drag;
}

}  // namespace flotsam
