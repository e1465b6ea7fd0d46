#include "bridges/bridge.hpp"

#include <cmath>

namespace flotsam {

double footprint_half_extent_along(const BodySet& bodies, int i, const Vec2& direction) {
  const Vec2 a(std::cos(bodies.angle[i]), std::sin(bodies.angle[i]));
  const Vec2 h = bodies.half_extents(i);
  return h.x() * std::abs(a.dot(direction)) + h.y() * std::abs(perp(a).dot(direction));
}

}  // namespace flotsam
