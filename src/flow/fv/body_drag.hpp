#pragma once
// The bodies' drag on the water, point-implicit (model.md "Two-way coupling", spec 5 step 3).
// A body b hands the cells under it its drag rate K_b [kg/s] (F_drag = K_b (u_f - u_p), (M-6))
// and its velocity v_b, shared by the cells' weights w_bi (their share of its footprint). Each
// cell's momentum then takes, after friction in every sub-step,
//   (hu)^{n+1} = ((hu)* + dt b_i) / (1 + dt a_i / h),
//   a_i = sum_b K_b w_bi / (rho A_i) [m/s],  b_i = sum_b K_b w_bi v_b / (rho A_i) [m^2/s^2],
// backward Euler in the velocity: stable at any K dt (a thick jam over little water relaxes the
// water to the bodies' velocity, never past it), where a force frozen over the coupling step
// overshoots. The cell gives up exactly dt sum_b K_b w_bi (u^{n+1} - v_b) rho-weighted; the time
// integral of u^{n+1} is kept so that each body's share is known after the step.
#include <vector>

#include "core/vec.hpp"

namespace flotsam {

struct ConservedState;

struct BodyDrag {
  std::vector<double> rate;         // a_i [m/s] per cell, 0 where no body lies
  std::vector<Vec2> target;         // b_i [m^2/s^2] per cell
  std::vector<Vec2> velocity_time;  // int u^{n+1} dt where the drag acted [m]
  std::vector<double> time;         // int dt where it acted [s]
  std::vector<int> cells;           // the cells under bodies (a > 0), ascending

  bool empty() const { return rate.empty(); }
  /// Per cell a and b as above, and zero integrals; n cells.
  void reset(int n);
  /// Cell i's drag over dt [s]; nothing where the water is at most `dry_depth` [m] deep (a body
  /// there rests on the bed).
  void apply(ConservedState& U, int i, double dt, double dry_depth);
};

}  // namespace flotsam
