#include "mesh/simple_polygon.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace flotsam {

namespace {

// Corners off the line through the two farthest apart by less than this fraction of their
// distance are on it (a zone given with round-off in its corners).
constexpr double collinear_fraction = 1e-12;  // [-]

/// True when all the points lie on one line: the polygon they make has zero area (a bow tie's
/// signed area is zero too, but it is a polygon that intersects itself).
bool on_one_line(std::span<const Vec2> p) {
  std::size_t far = 0;  // the point farthest from p[0]
  for (std::size_t i = 1; i < p.size(); ++i)
    if ((p[i] - p[0]).squaredNorm() > (p[far] - p[0]).squaredNorm()) far = i;
  const Vec2 axis = p[far] - p[0];
  for (const Vec2& q : p)
    if (std::abs(cross(axis, q - p[0])) > collinear_fraction * axis.squaredNorm()) return false;
  return true;
}

}  // namespace

bool segments_meet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const double o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
    return true;
  return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) || on_segment(c, d, b);
}

double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double length2 = d.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
  return (p - (a + t * d)).norm();
}

std::optional<std::pair<int, int>> first_crossing(std::span<const Vec2> p) {
  const std::size_t n = p.size();
  // Sides i (p[i] -> p[i+1]) and j: neighbours share one end and must not fold back onto each
  // other; other sides must not meet at all.
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const Vec2 &a = p[i], &b = p[(i + 1) % n], &c = p[j], &d = p[(j + 1) % n];
      bool meet = false;
      if (j == i + 1)
        meet = on_segment(a, b, d) || on_segment(c, d, a);
      else if (i == 0 && j == n - 1)
        meet = on_segment(c, d, b) || on_segment(a, b, c);
      else
        meet = segments_meet(a, b, c, d);
      if (meet) return std::pair{static_cast<int>(i), static_cast<int>(j)};
    }
  return std::nullopt;
}

bool polygons_overlap(std::span<const Vec2> a, std::span<const Vec2> b) {
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j)
      if (segments_meet(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()])) return true;
  return polygon_contains(a, b.front()) || polygon_contains(b, a.front());
}

double signed_area(std::span<const Vec2> points) {
  const std::size_t n = points.size();
  double twice = 0.0;  // [m^2]
  for (std::size_t i = 0; i < n; ++i) twice += cross(points[i], points[(i + 1) % n]);
  return 0.5 * twice;
}

BoundingBox bounding_box(std::span<const Vec2> points) {
  BoundingBox box{points.front(), points.front()};
  for (const Vec2& p : points) {
    box.min = box.min.cwiseMin(p);
    box.max = box.max.cwiseMax(p);
  }
  return box;
}

std::string polygon_defect(std::span<const Vec2> p) {
  const std::size_t n = p.size();
  if (n < 3) return fmt::format("a polygon needs at least 3 points; got {}", n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (p[i] == p[j])
        return fmt::format("points {} and {} coincide at ({}, {}) m", j + 1, i + 1, p[i].x(),
                           p[i].y());
  if (on_one_line(p)) return "the polygon has zero area (its points lie on one line)";
  if (const auto crossing = first_crossing(p)) {
    const auto [i, j] = *crossing;
    return fmt::format(
        "the polygon intersects itself: side {} (points {} to {}) meets side {} (points {} to {})",
        i + 1, i + 1, (i + 1) % n + 1, j + 1, j + 1, (j + 1) % n + 1);
  }
  return "";
}

bool polygon_contains(std::span<const Vec2> points, const Vec2& p) {
  // Crossing number: a ray from p along +x crosses the boundary an odd number of times when p
  // is inside. A side counts when its ends lie on either side of the ray's line (half-open in
  // y, so that a corner on the line is counted once).
  bool inside = false;
  const std::size_t n = points.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2 &a = points[i], &b = points[j];
    if ((a.y() > p.y()) == (b.y() > p.y())) continue;
    const double x_cross = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());  // [m]
    if (p.x() < x_cross) inside = !inside;
  }
  return inside;
}

}  // namespace flotsam
