#pragma once
// FlowField (flow_field.hpp) for the FEM engine: samples the two states bracketing the current
// step at a point, located by the neighbour walk (mesh/point_locator.hpp), with P2 velocity and
// bed, P1 elevation, linear interpolation in time, du/dt = (u^{n+1} - u^n) / dt. Body reactions
// become per-element accelerations, F_bodies = - F_x / (rho H A_fp) (spec 5), spread over the
// elements whose centroid lies in the footprint (the element holding the centre when none does),
// scaled so that sum_e rho (integral of H over e) F_e = - F_x to round-off; the drag part of F_x
// as -K (u - u_p) / (rho H A_fp), implicit in the velocity (model.md "Two-way coupling").
#include <vector>

#include "flow/body_footprint.hpp"
#include "flow/fem/shallow_water_solver.hpp"
#include "flow/flow_field.hpp"
#include "mesh/point_locator.hpp"

namespace flotsam {

/// One node's values as sample_batch reads them: 8 doubles, one cache line (the packs aligned to
/// lines), node n's at n * size.
struct NodePack {
  static constexpr int u0 = 0, v0 = 1, u1 = 2, v1 = 3;  // [m/s] velocity, the step's start, end
  static constexpr int bed = 4;                         // [m] z_b
  static constexpr int eta0 = 5, eta1 = 6;  // [m] elevation, start and end (a vertex; else 0)
  static constexpr int size = 8;
};

/// An element's J^-T (which sample reads) and its nodes' packs (sample_batch), in one cache line.
struct alignas(64) ElementRecord {
  double J[4];  // J^-T of a straight element, row by row (constant on it; 0 for a curved one)
  int pack[6];  // the six nodes' packs, node * NodePack::size
};

class FemFlowField final : public FlowField {
 public:
  /// Keeps a reference to `solver`, which must outlive the field.
  explicit FemFlowField(ShallowWaterSolver& solver);

  /// Copies the solver's two states into the nodes' packs that sample_batch reads. To be called
  /// whenever the solver's states change (FemEngine does after each step, initialize, settle and
  /// restore); sample_batch refuses a pack that is not of the states' times.
  void pack_states();

  FlowSample sample(const Vec2& p, double t, int& hint) const override;
  /// fem_batch_sample.cpp: sample's interpolation for the batch's points in vector loops.
  void sample_batch(const double* x, const double* y, const double* t, const bool* active,
                    int* hints, BatchFlow& out) const override;
  double time_begin() const override { return solver_.previous_state().time; }
  double time_end() const override { return solver_.time(); }
  /// Each body spread by the water's mass over the elements under it: the added mass's part of
  /// -F_x explicit, the drag implicit in the momentum equation, as friction is.
  void set_body_reactions(const std::vector<BodyReaction>& reactions) override;
  std::vector<Vec2> exchanged_forces() const override;

 private:
  ShallowWaterSolver& solver_;
  PointLocator locator_;
  std::vector<ElementRecord> elements_;
  std::vector<double> pack_storage_;               // the nodes' packs for sample_batch from pack_
  int pack_ = 0;                                   // (the first 64-byte boundary in the storage)
  double packed_begin_ = 0.0, packed_end_ = -1.0;  // [s] the states' times when packed
  std::vector<BodyReaction> reactions_;  // the last ones, and where each went (shares by water)
  FootprintShares shares_;
};

}  // namespace flotsam
