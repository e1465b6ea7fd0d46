#pragma once
// FlowField (flow_field.hpp) for the FEM engine: samples the two states bracketing the current
// step at a point, located by the neighbour walk (mesh/point_locator.hpp), with P2 velocity and
// bed, P1 elevation, linear interpolation in time, du/dt = (u^{n+1} - u^n) / dt. Body reactions
// become per-element forces per unit mass, F_bodies = - F_x / (rho H A_fp) (spec 5), spread over
// the elements whose centroid lies in the footprint (the element holding the centre when none
// does), scaled so that sum_e rho (integral of H over e) F_e = - F_x to round-off.
#include <vector>

#include "flow/fem/shallow_water_solver.hpp"
#include "flow/flow_field.hpp"
#include "mesh/point_locator.hpp"

namespace flotsam {

class FemFlowField final : public FlowField {
 public:
  /// Keeps a reference to `solver`, which must outlive the field.
  explicit FemFlowField(ShallowWaterSolver& solver);

  FlowSample sample(const Vec2& p, double t, int& hint) const override;
  /// fem_batch_sample.cpp: sample's interpolation for the batch's points in vector loops.
  void sample_batch(const double* x, const double* y, const double* t, const bool* active,
                    int* hints, BatchFlow& out) const override;
  double time_begin() const override { return solver_.previous_state().time; }
  double time_end() const override { return solver_.time(); }
  void set_body_reactions(const std::vector<BodyReaction>& reactions) override;

 private:
  ShallowWaterSolver& solver_;
  PointLocator locator_;
  std::vector<Mat2> straight_inverse_;  // J^-T of each straight element (constant on it)
};

}  // namespace flotsam
