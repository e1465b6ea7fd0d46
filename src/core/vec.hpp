#pragma once
// Small fixed-size algebra: Eigen's, under plain names.
#include <Eigen/Dense>

namespace flotsam {

using Vec2 = Eigen::Vector2d;  // a point or a horizontal vector [m], [m/s], [N], ...
using Mat2 = Eigen::Matrix2d;  // a 2x2 tensor (velocity gradient [1/s], Jacobian [m])

/// z component of the 2D cross product a x b.
inline double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// k x a: a turned a quarter turn counter-clockwise.
inline Vec2 perp(const Vec2& a) {
  return {-a.y(), a.x()};
}

}  // namespace flotsam
