#pragma once
// The paper's P2-P1 finite-element engine (shallow_water_solver.hpp) behind the FlowEngine
// interface: the solver, the field the bodies sample (fem_flow_field.hpp), its output,
// checkpoint and frozen-mode steady state. After every change of the solver's states the field
// packs them for the bodies (FemFlowField::pack_states).
#include <memory>

#include "flow/fem/fem_flow_field.hpp"
#include "flow/fem/shallow_water_solver.hpp"
#include "flow/flow_engine.hpp"

namespace flotsam {

class FemEngine final : public FlowEngine {
 public:
  /// Keeps references to `mesh` and `flow_case`, which must outlive the engine.
  FemEngine(const Mesh& mesh, const Case& flow_case);

  void initialize() override;
  void step(double dt) override;
  void settle(const TimeConfig& time) override;
  double time() const override { return solver_.time(); }
  FlowField& field() override { return field_; }
  const FlowState& nodal_state() const override { return solver_.state(); }
  const WaterBalance& water_balance() const override { return solver_.water_balance(); }
  double volume() const override { return solver_.volume(); }
  const Mesh& mesh() const override { return solver_.mesh(); }
  void write_fields(const std::string& path, double t) const override;
  ResultMesh result_mesh() const override;
  ResultFields result_fields() const override;
  std::string summary() const override;
  void save(ArchiveWriter& w, const std::string& prefix) const override;
  void restore(ArchiveReader& r, const std::string& prefix) override;
  /// The checkpoint holds the state before the step too (BDF2's history): a restore.
  void restore_step(ArchiveReader& r, const std::string& prefix) override { restore(r, prefix); }
  void after_checkpoint() override { solver_.start_fresh_factorisation(); }

  const ShallowWaterSolver& solver() const { return solver_; }

 private:
  ShallowWaterSolver solver_;
  FemFlowField field_;
};

}  // namespace flotsam
