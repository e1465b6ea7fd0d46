#pragma once
// A shared flow (issue 17): in one-way and frozen runs the bodies do not act on the water, so
// every run of a case whose flow inputs are the same has the same flow. An ensemble computes it
// once (record_shared_flow) and its members replay it (SharedFlowReplay) instead of computing
// it: the engine's state after each step, as its checkpoint holds it, read back in place of the
// step. The bodies sample the same flow bit for bit (tests/coupling/shared_flow_test.cpp).
//
// The file is an archive (io/binary_archive.hpp): "shared.mode" (CouplingMode), "shared.step" and
// "shared.end" [s] (the case's time.step and time.end), "shared.output" (1: recorded as a run
// that writes output does its steps), then in frozen mode the settled state "settled.*", in
// one-way mode the state after each step k, "k.*", the steps as Simulation takes them.
//
// Beside the file, the folder <file>.fields (shared_fields_folder) keeps what every run replaying
// the flow writes the same: its flow fields at each output time, written by the first run to get
// there and hard-linked into the folders of the others (RunOutput::share_flow_fields).
#include <filesystem>
#include <string>

#include "flow/flow_engine.hpp"
#include "io/binary_archive.hpp"
#include "io/case.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

/// The bodies of a case in this mode leave the water as it is: one-way or frozen.
bool flow_can_be_shared(const Case& run_case);

/// Runs the flow of `run_case` alone, from its initial state to time.end in its steps (the
/// steady state in frozen mode), and writes the states to `path`. A run that writes output
/// lets the engine drop what a restarted run would not have at each output time
/// (FlowEngine::after_checkpoint); `with_output` does the same, so that the recorded flow is
/// the flow of such runs bit for bit.
/// The folder of shared files beside it is made afresh (emptied when it was there).
void record_shared_flow(const Case& run_case, const Mesh& mesh, const std::string& path,
                        bool with_output);

/// The folder of the files every run replaying the shared flow at `flow_file` writes the same.
std::filesystem::path shared_fields_folder(const std::filesystem::path& flow_file);

/// Removes a shared flow's file and its folder of shared files (the runs keep their links).
void remove_shared_flow(const std::filesystem::path& flow_file);

/// A run's flow read from a shared flow's file: the file must have been recorded for the run's
/// mode, step and end time (a RunError naming the file otherwise).
class SharedFlowReplay {
 public:
  SharedFlowReplay(const std::string& path, const Case& run_case, bool with_output);
  /// Frozen mode: the settled flow, in place of FlowEngine::settle.
  void settle(FlowEngine& flow);
  /// One-way mode: the next step's state, in place of FlowEngine::step; it must end at t1 [s].
  void step(FlowEngine& flow, double t1);
  const std::string& path() const { return reader_.path(); }

 private:
  ArchiveReader reader_;
  double dt_ = 0.0;  // [s] the case's time.step
  long next_ = 0;    // the next step to read
};

}  // namespace flotsam
