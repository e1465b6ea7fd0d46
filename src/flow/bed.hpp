#pragma once
// Bed elevation z_b(x, y) from the case (spec 1; BedConfig): flat, plane slope, or a table in x.
#include <functional>

#include "core/vec.hpp"
#include "io/case.hpp"

namespace flotsam {

using BedFunction = std::function<double(const Vec2&)>;  // z_b [m] at a point [m]

/// z_b at p: flat: level; slope: level - S_x x - S_y y (S = BedConfig::slope, positive when the
/// bed falls along +x / +y); table: profile_x(x).
double bed_elevation(const BedConfig& bed, const Vec2& p);

/// The case's bed as a function.
BedFunction make_bed_function(const BedConfig& bed);

}  // namespace flotsam
