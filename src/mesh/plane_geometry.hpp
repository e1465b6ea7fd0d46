#pragma once
// Plane geometry on polygons and segments, exact in its predicates' signs where the inputs are:
// what the mesh generators check outlines, holes and lines with.
#include <optional>
#include <utility>
#include <vector>

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

/// Signed area of a ring (counter-clockwise positive) [m^2].
double signed_area(const std::vector<Vec2>& ring);

/// p strictly inside the ring (even-odd rule; points on the ring count as either).
bool inside_ring(const std::vector<Vec2>& ring, const Vec2& p);

/// The first two sides (i, j), i < j, of a ring that meet other than at their shared corner
/// (side i joins point i and point i+1, the last closes the ring), or none: a simple ring.
std::optional<std::pair<int, int>> ring_self_crossing(const std::vector<Vec2>& ring);

/// Two rings' boundaries meet, or one lies inside the other.
bool rings_overlap(const std::vector<Vec2>& a, const std::vector<Vec2>& b);

}  // namespace flotsam
