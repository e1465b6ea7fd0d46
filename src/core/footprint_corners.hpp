#pragma once
// The corners of a body's footprint, the rectangle its output files draw (the bodies' .vtp, the
// debris GeoPackage's tracks and jams).
#include <array>
#include <cmath>

#include "core/vec.hpp"

namespace flotsam {

/// The four corners of a footprint, counter-clockwise: with e = (cos angle, sin angle) the length
/// axis and n = perp(e), centre -+ L/2 e -+ l/2 n, starting at the rear right (- L/2, - l/2).
/// `half_extents` = (L/2, l/2) [m].
inline std::array<Vec2, 4> footprint_corners(const Vec2& centre, const Vec2& half_extents,
                                             double angle) {
  const Vec2 e(std::cos(angle), std::sin(angle));  // the length axis
  const Vec2 a = half_extents.x() * e, b = half_extents.y() * perp(e);
  return {Vec2(centre - a - b), Vec2(centre + a - b), Vec2(centre + a + b), Vec2(centre - a + b)};
}

}  // namespace flotsam
