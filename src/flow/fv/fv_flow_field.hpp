#pragma once
// FlowField (flow_field.hpp) for the finite-volume engine: a point is located by the neighbour
// walk (mesh/point_locator.hpp), its cell is the sub-triangle of the element holding it, and the
// flow there is the cell's limited linear reconstruction (reconstruction.hpp) in the two states
// that bracket the coupling step, interpolated linearly in time; du/dt is their difference over
// the step. The bed and its slope are the plane through the cell's three corners.
//
// Body reactions (spec 5, two-way): each body is shared among the wet cells whose centroid lies
// in its footprint, in proportion to their area (the wet cell holding its centre when none does):
// its added mass's part of -F_x as a force, its drag as a point-implicit drag at the cells' own
// velocity (body_drag.hpp); a body over dry cells gives nothing to the water (it rests on the
// bed). What each body exchanged over the flow step is measured from what its cells gave up.
#include <cstdint>
#include <memory>
#include <vector>

#include "flow/body_footprint.hpp"
#include "flow/flow_field.hpp"
#include "flow/fv/fv_solver.hpp"
#include "mesh/point_locator.hpp"

namespace flotsam {

class FvFlowField final : public FlowField {
 public:
  /// Keeps references to `solver` and `mesh`, which must outlive the field; `node_bed` [m] is
  /// the bed at every mesh node. `locator`: a point locator of the same mesh shared by several
  /// runs (its mesh must outlive the field), or nullptr: the field builds its own.
  FvFlowField(FiniteVolumeSolver& solver, const Mesh& mesh, std::vector<double> node_bed,
              std::shared_ptr<const PointLocator> locator = nullptr);

  /// The state now becomes the end of the current step, the previous end its beginning.
  void advance_to_state();
  /// Both ends of the step are the state now (a start, a restart, a steady flow).
  void reset_to_state();

  FlowSample sample(const Vec2& p, double t, int& hint) const override;
  /// fv_batch_sample.cpp: sample's reconstruction for the batch's points in vector loops.
  void sample_batch(const double* x, const double* y, const double* t, const bool* active,
                    int* hints, BatchFlow& out) const override;
  double time_begin() const override { return t0_; }
  double time_end() const override { return t1_; }
  void set_body_reactions(const std::vector<BodyReaction>& reactions) override;
  std::vector<Vec2> exchanged_forces() const override;
  /// Per cell, 1 under one of `bodies` (wet or dry), else 0; empty when there are none.
  std::vector<std::uint8_t> cells_under(const std::vector<BodyFootprint>& bodies) const;

  const std::vector<double>& node_bed() const { return node_bed_; }
  /// The cell holding p, or -1 outside the domain, walking from element `hint` (updated).
  int cell_of(const Vec2& p, int& hint) const;

 private:
  int cell_at(const Vec2& p, int& hint, FlowSample& out) const;

  FiniteVolumeSolver& solver_;
  const Mesh& mesh_;
  std::shared_ptr<const PointLocator> locator_;
  std::vector<double> node_bed_;  // [m] per mesh node
  std::vector<Vec2> bed_slope_;   // [-] grad z_b per cell
  CellField begin_, end_;
  double t0_ = 0.0, t1_ = 0.0;           // [s]
  std::vector<BodyReaction> reactions_;  // the last ones, and where each went
  FootprintShares shares_;
  double drag_start_ = 0.0;  // [s] the time they were set
};

}  // namespace flotsam
