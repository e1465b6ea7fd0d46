#pragma once
// Friction that varies over the domain (flow.friction.raster and flow.friction.zones;
// docs/model.md "Friction over the domain", (M-19)): the friction law's coefficient (n, C or K)
// at given points, the finite-volume cells' centroids or the FEM elements' centroids, evaluated
// once when the run starts. At each point, each step replacing the one before where it applies:
//
//   1. the case's default, flow.friction.coefficient;
//   2. the raster's pixel holding the point (nearest pixel), where the raster has a value there
//      (inside its extent, not nodata);
//   3. each zone holding the point (inside its ring, in none of its holes), in the order listed:
//      where zones overlap, the last one listed wins.
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/vec.hpp"
#include "io/case.hpp"

namespace flotsam {

/// The coefficient at each point and where it came from.
struct FrictionCoefficients {
  std::vector<double> coefficient;  // n, C or K per point, > 0
  int from_raster = 0;              // points given the raster's value (zones may replace it)
  std::vector<int> in_zone;         // per zone: the points it holds
};

/// The coefficients of `flow`'s law at `points` [m]. `name_of(k)` names point k in messages
/// ("cell 12", "element 40"). An InputError naming the raster's key when the pixel under a point
/// holds a coefficient that is not > 0 (or infinite), or when the raster has a value under none
/// of the points (it lies elsewhere: another coordinate system?).
FrictionCoefficients friction_coefficients(const FlowConfig& flow, std::span<const Vec2> points,
                                           const std::function<std::string(int)>& name_of);

/// Tells (spdlog, info) how many of the points, named `what` ("cells"), the raster and the
/// zones gave their coefficient, and warns of zones that hold none (smaller than the mesh?).
void log_friction_map(const FrictionMapConfig& map, const FrictionCoefficients& k,
                      std::string_view what);

/// The name of the law's coefficient with its unit, for output fields: "n [s m^-1/3]",
/// "C [m^1/2 s^-1]", "K [m^1/3 s^-1]" ("" without friction).
std::string friction_field_name(FrictionLaw law);

/// The zone holds p: inside its ring and in none of its holes (a point on a side may go either
/// way).
bool zone_contains(const FrictionZone& zone, const Vec2& p);

}  // namespace flotsam
