// The finite-volume engine's UGRID results (flow/result_fields.hpp): the cells as faces, the
// state per cell at each output (dry cells hold NaN, which the file stores as its fill value and
// QGIS leaves transparent), the bed and the flood envelopes with their hazard as static fields.
#include <cmath>
#include <limits>

#include "flow/fv/fv_engine.hpp"
#include "flow/result_variables.hpp"

namespace flotsam {

ResultMesh FvEngine::result_mesh() const {
  return {solver_.cells().corners, field_->node_bed()};
}

ResultFields FvEngine::result_fields() const {
  namespace var = result_variables;
  const ConservedState& U = solver_.state();
  const int n = solver_.cells().cell_count;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> depth(n, nan), level(n, nan), ux(n, nan), uy(n, nan);
  for (int i = 0; i < n; ++i) {
    if (U.h[i] <= solver_.dry_depth()) continue;
    depth[i] = U.h[i];
    level[i] = U.h[i] + solver_.bed()[i];
    ux[i] = U.hu[i] / U.h[i];
    uy[i] = U.hv[i] / U.h[i];
  }
  // Envelopes: the arrival time and the classes only where the water arrived.
  std::vector<double> arrival = envelope_.arrival, rating = envelope_.hazard_rating_class(),
                      australian = envelope_.australian_class, vehicles = envelope_.vehicle_class;
  for (int i = 0; i < n; ++i)
    if (std::isnan(arrival[i])) rating[i] = australian[i] = vehicles[i] = nan;

  constexpr auto face = UgridLocation::face;
  ResultFields f;
  f.add(var::depth(face), std::move(depth));
  f.add(var::water_level(face), std::move(level));
  f.add(var::velocity_x(face), std::move(ux));
  f.add(var::velocity_y(face), std::move(uy));
  f.add({"bed", "bed elevation of the cells", "altitude", "m", face, false}, solver_.bed());
  f.add({"max_depth", "largest water depth", "", "m", face, false}, envelope_.max_depth);
  f.add({"max_speed", "largest flow speed", "", "m s-1", face, false}, envelope_.max_speed);
  f.add({"max_unit_discharge", "largest depth x velocity", "", "m2 s-1", face, false},
        envelope_.max_unit_discharge);
  f.add({"arrival_time", "arrival time of the water", "", "s", face, false}, std::move(arrival));
  f.add({"wet_duration", "wet duration", "", "s", face, false}, envelope_.wet_duration);
  f.add({"hazard_rating", "largest hazard rating HR (FD2321)", "", "1", face, false},
        envelope_.max_hazard_rating);
  f.add({"hazard_rating_class", "hazard rating class (1 low - 4 extreme)", "", "1", face, false},
        std::move(rating));
  f.add({"australian_hazard_class", "Australian hazard class (H1-H6)", "", "1", face, false},
        std::move(australian));
  f.add({"vehicle_class", "vehicles unstable (0 none - 3 large 4WDs)", "", "1", face, false},
        std::move(vehicles));
  return f;
}

}  // namespace flotsam
