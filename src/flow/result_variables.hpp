#pragma once
// The variables both engines write to the UGRID results (docs/output-format.md "UGRID NetCDF"),
// named once: CF standard names as Delft3D FM and TELEMAC write them, and long names unique per
// variable (QGIS's MDAL keys its dataset groups on them and pairs vectors on ", x-component").
#include "io/ugrid_variable.hpp"

namespace flotsam::result_variables {

inline UgridVariable depth(UgridLocation at) {
  return {"depth", "water depth", "sea_floor_depth_below_sea_surface", "m", at, true};
}
inline UgridVariable water_level(UgridLocation at) {
  return {"water_level",
          "water surface elevation",
          "water_surface_height_above_reference_datum",
          "m",
          at,
          true};
}
inline UgridVariable velocity_x(UgridLocation at) {
  return {"ux", "flow velocity, x-component", "sea_water_x_velocity", "m s-1", at, true};
}
inline UgridVariable velocity_y(UgridLocation at) {
  return {"uy", "flow velocity, y-component", "sea_water_y_velocity", "m s-1", at, true};
}

}  // namespace flotsam::result_variables
