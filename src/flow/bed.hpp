#pragma once
// Bed elevation z_b(x, y) from the case (spec 1; BedConfig): flat, plane slope, a table in x, a
// formula in x and y, or a terrain raster sampled bilinearly (geo/raster.hpp), optionally edited
// by a formula in x, y and the raster's z (docs/case-format.md "bed").
#include <functional>
#include <vector>

#include "core/vec.hpp"
#include "io/case.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

using BedFunction = std::function<double(const Vec2&)>;  // z_b [m] at a point [m]

/// z_b at p: flat: level; slope: level - S_x x - S_y y (S = BedConfig::slope, positive when the
/// bed falls along +x / +y); table: profile_x(x); expression: the formula; raster: the raster's
/// bilinear value z, or the edit formula at (x, y, z). An InputError where the raster has no
/// value (outside it, or next to a nodata pixel) naming the point.
double bed_elevation(const BedConfig& bed, const Vec2& p);

/// The case's bed as a function.
BedFunction make_bed_function(const BedConfig& bed);

/// z_b at every node of the mesh. Where the bed has no value the InputError names the node, an
/// element holding it (the source file's tags) and its position.
std::vector<double> bed_at_nodes(const Mesh& mesh, const BedConfig& bed);

}  // namespace flotsam
