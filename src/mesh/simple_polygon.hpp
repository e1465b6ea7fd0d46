#pragma once
// Simple polygons given by their corners in order (a `mesh.polygon` domain, a release zone): what
// makes one unusable, its area, and whether it holds a point.
//
// Corners and sides are numbered from 1 in messages, as a user counts them: side i joins corner
// i to corner i + 1, the last side closes the polygon. The predicates are plain floating point:
// they judge a user's corners, not the round-off of computed ones.
#include <optional>
#include <span>
#include <string>
#include <utility>

#include "core/vec.hpp"

namespace flotsam {

/// Orientation of c with respect to the line a -> b: > 0 left, < 0 right, 0 on it.
inline double orientation(const Vec2& a, const Vec2& b, const Vec2& c) {
  return cross(b - a, c - a);
}

/// p lies on the closed segment a-b.
inline bool on_segment(const Vec2& a, const Vec2& b, const Vec2& p) {
  return orientation(a, b, p) == 0 && (p - a).dot(p - b) <= 0;
}

/// Closed segments a-b and c-d share a point.
bool segments_meet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);

/// Distance from p to the closed segment a-b [m].
double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b);

/// The first two sides (i, j), i < j, counted from 0, that meet other than neighbours at their
/// common corner, or none.
std::optional<std::pair<int, int>> first_crossing(std::span<const Vec2> points);

/// Two polygons' sides meet, or one lies inside the other.
bool polygons_overlap(std::span<const Vec2> a, std::span<const Vec2> b);

/// What is wrong with the polygon, in words ("points 2 and 4 coincide at (1, 0) m"), or "" when
/// it is a simple polygon: at least 3 corners, no two alike, an area that is not zero, and no
/// two sides meeting except neighbours at their common corner.
std::string polygon_defect(std::span<const Vec2> points);

/// Signed area (shoelace formula), > 0 when the corners turn counter-clockwise [m^2].
double signed_area(std::span<const Vec2> points);

/// True when p is inside the polygon (crossing number; a point on a side may go either way).
bool polygon_contains(std::span<const Vec2> points, const Vec2& p);

/// Smallest axis-aligned box holding the corners: (x_min, y_min) and (x_max, y_max) [m].
struct BoundingBox {
  Vec2 min, max;
};
BoundingBox bounding_box(std::span<const Vec2> points);

}  // namespace flotsam
