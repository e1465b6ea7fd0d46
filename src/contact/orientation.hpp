#pragma once
// The orientation predicate CCW(A, B, C) of the paper's section 5.4 (P-5.4), made exact, and the
// two tests built on it that spec 4.2 names: segment crossing and point in a convex polygon.
//
// The paper's CCW compares two products in floating point; for nearly parallel edges (two logs
// lying side by side, a log flat against a bank) the two products agree to the last bits and the
// answer is noise. orient2d below returns the sign of the exact determinant of its (double)
// arguments: a fast floating-point evaluation with Shewchuk's error bound decides almost every
// call, and the rare uncertain ones are re-evaluated exactly with expansion arithmetic.
#include <span>

#include "core/vec.hpp"

namespace flotsam {

/// Sign of (B - A) x (C - A), exactly: +1 when A, B, C turn counter-clockwise, -1 clockwise,
/// 0 when the three points are collinear. (P-5.4)
int orient2d(const Vec2& a, const Vec2& b, const Vec2& c);

/// The paper's CCW(A, B, C): true when A, B, C are in strict counter-clockwise order.
inline bool ccw(const Vec2& a, const Vec2& b, const Vec2& c) {
  return orient2d(a, b, c) > 0;
}

/// True when the closed segments AB and CD share at least one point (P-5.4, INTERSECTION, with
/// touching and collinear overlap counted).
bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);

/// True when p lies in the closed convex polygon whose vertices are given counter-clockwise.
bool point_in_convex_polygon(const Vec2& p, std::span<const Vec2> polygon);

/// True when two closed convex polygons (vertices counter-clockwise) share a point: an edge of
/// one crosses an edge of the other, or one holds a vertex of the other.
bool convex_polygons_touch(std::span<const Vec2> first, std::span<const Vec2> second);

}  // namespace flotsam
