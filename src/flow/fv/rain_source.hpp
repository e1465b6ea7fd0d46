#pragma once
// Rain and infiltration on the finite-volume cells (docs/model.md "Rain and infiltration",
// (M-17)): in the continuity equation of cell i the source
//
//   dh_i/dt = w_i r(t) - f,  and never below h_i = 0 (f takes at most what the cell holds)
//
// with r(t) the case's intensity (a constant or a hyetograph, piecewise linear in t), w_i a
// weight per cell (the case's rain raster's pixel under the cell's centroid, else 1; or set) and
// f the constant infiltration. The solver adds the rain inside its Runge-Kutta stages and takes
// the infiltration after them (fv_solver.cpp).
#include <functional>
#include <span>
#include <vector>

#include "core/time_series.hpp"
#include "flow/fv/cell_mesh.hpp"
#include "io/case.hpp"

namespace flotsam {

class RainSource {
 public:
  /// The case's rain on the cells (none when `rain.enabled` is false), with the weights of its
  /// raster (nearest pixel to each centroid), or every weight 1. InputError naming the cell and
  /// its position where the raster has no value (outside it, nodata) or one < 0.
  RainSource(const RainConfig& rain, const CellMesh& cells);

  bool raining() const { return enabled_; }
  bool infiltrating() const { return f_ > 0.0; }
  /// One cell's loss of `loss` [m] (all its water when it has less), the discharges in
  /// proportion; returns the depth it lost, as stored [m].
  static double infiltrate_cell(double& h, double& hu, double& hv, double loss) {
    const double h_old = h;
    if (h_old <= loss) {
      h = hu = hv = 0.0;
      return h_old;
    }
    h = h_old - loss;
    const double keep = h / h_old;
    hu *= keep;
    hv *= keep;
    return h_old - h;
  }

  /// Sets the weight w_i [-] of each cell (one per cell, finite and >= 0; a programming error
  /// otherwise).
  void set_weights(std::vector<double> weights);
  const std::vector<double>& weights() const { return weight_; }
  /// sum_i A_i w_i [m^2]: the volume a rain depth d [m] brings is d times this.
  double weighted_area() const { return weighted_area_; }

  /// The depth of rain [m] that falls between t0 and t1 [s] on a cell of weight 1:
  /// int_t0^t1 r(t) dt, exact for the piecewise-linear hyetograph (0 without rain).
  double depth(double t0, double t1) const;
  /// f [m/s].
  double infiltration_rate() const { return f_; }

  /// Infiltration over dt [s] (M-17): each cell of `cells` (every cell when empty) loses
  /// min(h_i, f dt), the water leaving with the cell's velocity (hu, hv scaled with h; a cell
  /// emptied is at rest). `share`, when given, fills in the depth each other cell lost (over MPI
  /// ranks: from its owner). Returns the volume infiltrated [m^3], summed over every cell in cell
  /// order (the same on any number of threads and ranks).
  double infiltrate(std::vector<double>& h, std::vector<double>& hu, std::vector<double>& hv,
                    double dt, std::span<const int> cells = {},
                    const std::function<void(std::vector<double>&)>& share = {});

 private:
  bool enabled_ = false;
  TimeSeries intensity_;             // r(t) [m/s]
  double f_ = 0.0;                   // infiltration [m/s]
  std::vector<double> area_;         // [m^2] per cell
  std::vector<double> weight_;       // w_i [-]
  double weighted_area_ = 0.0;       // sum_i A_i w_i [m^2]
  std::vector<double> infiltrated_;  // [m] per cell, of the last call to infiltrate
};

}  // namespace flotsam
