#pragma once
// One run of a case (spec 5): the flow, the bodies and their contacts advanced together, flow
// step after flow step. step() reads as the pipeline of docs/architecture.md:
//
//   flow -> bodies (RKF45 sub-steps, contacts after each contact interval) -> outflow/release
//   -> reaction (two-way) -> diagnostics -> output
//
// Modes (TimeConfig::mode): `frozen` solves the flow to steady state once and moves the bodies
// in it; `one-way` advances the flow and the bodies feel it; `two-way` also gives the flow the
// bodies' reaction. A case without bodies is a flow-only run.
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bodies/body_integrator.hpp"
#include "bodies/body_set.hpp"
#include "bodies/release.hpp"
#include "contact/boundary_segments.hpp"
#include "contact/contact_world.hpp"
#include "core/thread_governor.hpp"
#include "coupling/backwater.hpp"
#include "coupling/jam_statistics.hpp"
#include "coupling/mesh_setup.hpp"
#include "coupling/run_output.hpp"
#include "coupling/shared_flow.hpp"
#include "coupling/stage_timer.hpp"
#include "flow/flow_engine.hpp"
#include "flow/probes.hpp"
#include "io/case.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

struct RunOptions {
  std::filesystem::path output_directory;  // "" : <output.directory>/<name> of the case
  bool overwrite = false;                  // or the case's output.overwrite
  bool write_output = true;                // false: compute only (tests, benchmarks)
  bool progress = true;                    // progress line on stderr
  bool restart = false;  // continue the run in the output folder from its last checkpoint
  bool accept_output_changes = false;  // a restart may change the output settings
                                       // (io/case_digest.hpp)
  /// One-way and frozen runs: the flow read from this file (record_shared_flow of the same
  /// case's flow, coupling/shared_flow.hpp) instead of computed; "": computed.
  std::filesystem::path shared_flow = {};
  /// What the run may take ready-made (prepare_mesh_setup on a mesh equal to the run's, which
  /// outlives it; coupling/mesh_setup.hpp), or nullptr: built by the run.
  std::shared_ptr<const MeshSetup> mesh_setup = nullptr;
  /// A run that is rerun from its start when interrupted (an ensemble's member, whose folder
  /// without member.txt is run again): its .pvd indexes are written once, when it ends
  /// (write_final_output; a run stopped by an error too), not rewritten at every output, and it
  /// writes no checkpoint at its start, only at its later outputs (a restart still continues it
  /// from its last one). Fewer files written and replaced (docs/performance.md, "Ensembles").
  bool rerun_whole = false;
  /// Each step on the thread count that takes the least wall time, from all of
  /// omp_get_max_threads() down (core/thread_governor.hpp): `flotsam run` and ensemble members;
  /// false: every step on all of them.
  bool adapt_threads = false;
  /// One flood split over MPI ranks (finite volumes, flow/fv/rank_split.hpp): this process is
  /// rank `rank` of `ranks`; each advances its part of the cells and holds the whole state after
  /// each flow step. Only rank 0 should write (write_output, progress).
  int rank = 0, ranks = 1;
};

class Simulation {
 public:
  /// Takes the case and its mesh; nothing is computed or written before initialize().
  Simulation(Case run_case, Mesh mesh, RunOptions options = {});

  /// Flow initial state (steady state in frozen mode), bodies placed and checked, the output
  /// folder prepared and the state at the start written.
  void initialize();
  bool done() const;
  /// One flow step [t, t + dt].
  void step();
  /// initialize(), step() until the end time, then the final output.
  void run();
  /// The final output, when the last output interval was not complete (run() ends with it; a
  /// caller stepping the run itself calls it once done()).
  void write_final_output();
  /// The end-of-run summary: water balance, bodies, integration and stage timings.
  std::string summary() const;

  double time() const { return time_; }
  long step_count() const { return step_count_; }
  const FlowEngine& flow() const { return *flow_; }
  const BodySet& bodies() const { return bodies_; }
  const StageTimer& timer() const { return timer_; }
  const Case& run_case() const { return case_; }
  bool has_bodies() const { return has_bodies_; }
  /// Jam statistics of the current state (spec 6.3); bodies only.
  JamStatistics jam_statistics() const;
  /// Water-surface rise upstream of each bridge against the reference flow without bodies
  /// (output.backwater in two-way runs); empty without a reference flow.
  std::vector<double> backwater_rise() const;
  const FlowEngine* reference_flow() const { return reference_flow_.get(); }
  /// The contact stage (bodies only): its last contacts and profile (largest overlap left).
  const ContactWorld& contacts() const { return *contacts_; }

 private:
  std::string discharge_summary() const;
  void on_chosen_threads(const std::function<void()>& stages);
  void advance_flow(double t1);
  void advance_bodies(double t0, double t1);
  void hand_bodies_to_flow();
  void take_exchanged_forces();
  void check_decks_stand_above_the_bed() const;  // InputError for a deck under the ground
  // The grid of the envelopes' rasters over the mesh (output.rasters); an InputError when its
  // pixels would not fit in memory.
  RasterGrid envelope_grid() const;
  void check_diagnostics();
  /// A flood split over ranks: what only the output reads, gathered on every rank (each rank
  /// calls it at the same points of the run).
  void synchronize_flows();
  void write_output_if_due(bool force);
  void open_probes(std::optional<CsvResume> resume);
  RunLayout run_layout() const;  // the open groups (1 inflow/outflow, 0 wall), rain or not
  std::filesystem::path output_directory() const;
  /// Opens the run's output (a new folder, or continued after `output_times` on a restart).
  void open_output(const std::vector<double>* output_times);
  // checkpoint.cpp: everything a run needs to continue bit for bit from an output time.
  void write_checkpoint(const std::string& path) const;
  void read_checkpoint(const std::string& path);
  /// The case's settings and the mesh's checksum, which a restart must find unchanged.
  std::vector<CaseSetting> run_settings() const;
  /// Refuses a restart whose case differs from the checkpoint's (io/case_digest.hpp), naming
  /// the keys that changed; true when output settings changed (and that was accepted).
  bool check_restart_case(const std::string& path) const;
  /// Refuses a restored state that is not physical (non-finite values, bodies far outside).
  void check_restored_state(const std::string& path, const std::vector<double>& output_times) const;
  /// Restarts only: the checkpoint, with the case checked against it (`output_changed` as
  /// check_restart_case returns).
  std::filesystem::path restart_checkpoint(bool& output_changed) const;

  Case case_;
  Mesh mesh_;
  mutable std::string mesh_checksum_;  // run_settings: computed once
  RunOptions options_;
  bool has_bodies_ = false;

  std::unique_ptr<FlowEngine> flow_;
  std::unique_ptr<FlowEngine> reference_flow_;     // the same flow without bodies
  std::unique_ptr<SharedFlowReplay> shared_flow_;  // RunOptions::shared_flow, when given
  BodySet bodies_;
  std::unique_ptr<BodyIntegrator> integrator_;
  std::unique_ptr<Releaser> releaser_;
  std::unique_ptr<ContactWorld> contacts_;
  BoundarySegments walls_;
  std::vector<int> outflow_groups_;
  std::vector<int> reaction_bodies_;  // the body of each reaction handed to the flow
  JamGeometry jam_geometry_;
  bool has_decks_ = false;  // some bridge has a deck: the contacts need the bodies' levels
  std::unique_ptr<BackwaterProbe> backwater_probe_;
  std::unique_ptr<RunOutput> output_;
  std::unique_ptr<ProbeWriter> probes_;  // output.probes, when the case has any

  double time_ = 0.0;  // [s]
  long step_count_ = 0;
  double next_output_ = 0.0;  // [s]
  IntegrationStats integration_totals_;
  StageTimer timer_;
  std::optional<ThreadGovernor> threads_;  // RunOptions::adapt_threads
};

}  // namespace flotsam
