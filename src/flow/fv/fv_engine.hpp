#pragma once
// The finite-volume flood engine (spec 7; docs/model.md "Finite-volume engine") behind the
// FlowEngine interface: the solver (fv_solver.hpp), the field the bodies sample
// (fv_flow_field.hpp), the nodal view for pictures, its output, checkpoint and summary.
#include <memory>
#include <vector>

#include "flow/flow_engine.hpp"
#include "flow/fv/fv_flow_field.hpp"
#include "flow/fv/fv_solver.hpp"
#include "io/case.hpp"

namespace flotsam {

class FvEngine final : public FlowEngine {
 public:
  /// Keeps references to `mesh` and `flow_case`, which must outlive the engine. `cells` and
  /// `locator`: built once on the same mesh and shared by several runs (an ensemble's members,
  /// coupling/mesh_setup.hpp), or nullptr: the engine builds its own.
  FvEngine(const Mesh& mesh, const Case& flow_case, std::shared_ptr<const CellMesh> cells = nullptr,
           std::shared_ptr<const PointLocator> locator = nullptr);

  void initialize() override;
  void step(double dt) override;
  void settle(const TimeConfig& time) override;
  double time() const override { return solver_.time(); }
  FlowField& field() override { return *field_; }
  const FlowState& nodal_state() const override;
  std::vector<std::uint8_t> wet_nodes() const override;
  const WaterBalance& water_balance() const override { return solver_.water_balance(); }
  double volume() const override { return solver_.volume(); }
  const Mesh& mesh() const override { return mesh_; }
  void write_fields(const std::string& path, double t) const override;
  ResultMesh result_mesh() const override;
  ResultFields result_fields() const override;
  void save(ArchiveWriter& w, const std::string& prefix) const override;
  void restore(ArchiveReader& r, const std::string& prefix) override;
  void restore_step(ArchiveReader& r, const std::string& prefix) override;
  void mark_debris(const std::vector<BodyFootprint>& bodies) override;
  std::string summary() const override;
  std::vector<std::string> write_envelope_rasters(const std::string& prefix,
                                                  const RasterGrid& grid) const override;
  const FloodEnvelope& envelope() const { return envelope_; }
  /// The cell holding p, or -1 outside the domain (walking from element `hint`, updated).
  int field_cell_of(const Vec2& p, int& hint) const { return field_->cell_of(p, hint); }

  const FiniteVolumeSolver& solver() const { return solver_; }
  /// Advance rank `rank` of `ranks`' part of the cells (rank_split.hpp); every rank holds the
  /// whole state after each step. InputError for what does not split yet (naming the key).
  void split_over_ranks(int rank, int ranks);
  void synchronize() override;

 private:
  std::string hazard_summary() const;
  std::string piers_summary() const;
  std::string ranks_summary() const;
  /// The solver's state, balance, sub-step counts and envelopes as save() wrote them; the
  /// envelopes' running hazard rating too when `own_rating` (not a shared flow's step).
  void restore_state(ArchiveReader& r, const std::string& prefix, bool own_rating);

  const Mesh& mesh_;
  const Case& case_;
  FiniteVolumeSolver solver_;
  std::shared_ptr<const PointLocator> locator_;  // for the field, or nullptr
  std::unique_ptr<FvFlowField> field_;
  FloodEnvelope envelope_;                 // per cell, updated after every sub-step
  std::vector<std::uint8_t> debris_;       // per cell: 1 under a body (mark_debris), or empty
  mutable std::vector<int> raster_cells_;  // the cell under each pixel of the envelopes' rasters
  mutable FlowState nodal_;                // the nodal view, computed when asked
  mutable std::vector<std::uint8_t> nodal_wet_;  // per node: a wet cell touches it
  mutable bool nodal_valid_ = false;
};

}  // namespace flotsam
