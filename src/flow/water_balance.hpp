#pragma once
// Water volume balance (spec 6.2): V(t) - V(0) + (volume that left through the boundaries)
// - (volume added by sources) - (rain) + (infiltration) - (volume held in BDF2's time lag),
// relative to V(0) (or to the volume now or the rain fallen, when larger: a basin that starts
// dry). Rain and infiltration are the finite-volume engine's (docs/model.md (M-17)).
//
// Why it closes to round-off: the continuity rows (8)-(11) of element_assembly.hpp are solved
// exactly by the direct solver except on the elevation-Dirichlet rows. Summing all rows, the
// flux terms (9) cancel (sum_i grad q_i = 0), the time terms give (V^{n+1} - V^n)/dt, and what
// remains is the open-boundary outflow (10) plus the residuals r_i of the Dirichlet rows
// computed with the rows as assembled (the consistent boundary flux through elevation
// boundaries):  V^{n+1} - V^n = dt ( S - sum_i B_i + sum_{i in D} r_i ).
#include <algorithm>
#include <string>
#include <vector>

namespace flotsam {

struct WaterBalance {
  double initial_volume = 0.0;        // V(0) [m^3]
  double volume = 0.0;                // V(t) [m^3]
  double outflow = 0.0;               // volume out through all boundaries since t = 0 [m^3]
  double source = 0.0;                // volume added by source terms since t = 0 [m^3]
  double rain = 0.0;                  // volume of rain fallen on the domain since t = 0 [m^3]
  double sources = 0.0;               // volume let in by flow.sources since t = 0 [m^3]
  double infiltration = 0.0;          // volume infiltrated since t = 0 [m^3]
  double lag = 0.0;                   // volume in BDF2's time lag [m^3] (theta-scheme: 0)
  std::vector<double> group_outflow;  // per mesh boundary group [m^3] (inflow negative)
  std::vector<double> group_rate;     // outflow rate of the last step per group [m^3/s]

  /// V(t) - V(0) + outflow - source - rain - sources + infiltration - lag [m^3].
  double error() const {
    return volume - initial_volume + outflow - source - rain - sources + infiltration - lag;
  }
  /// The volume the error is measured against [m^3]: V(0), or V(t), the rain or the sources'
  /// when larger.
  double reference_volume() const { return std::max({initial_volume, volume, rain, sources}); }
  /// error() / reference_volume() [-] (0 when there is no water at all).
  double relative_error() const {
    const double V = reference_volume();
    return V > 0.0 ? error() / V : 0.0;
  }
};

class ArchiveWriter;
class ArchiveReader;

/// The balance's sums as records `prefix`.balance, .group_outflow, .group_rate of a checkpoint
/// (a checkpoint written before rain or sources were counted holds none: they read as 0).
void write_water_balance(ArchiveWriter& w, const std::string& prefix, const WaterBalance& b);
WaterBalance read_water_balance(ArchiveReader& r, const std::string& prefix);

}  // namespace flotsam
