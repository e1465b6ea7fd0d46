#pragma once
// `flotsam ensemble`: the case and its ensemble section read, the mesh generated once, the
// members dealt to the ranks (member m to rank m mod K) and run by `jobs` threads on each, the
// results gathered on rank 0, which writes the tables, the summary and the pictures.
//
//   DIR/ensemble.txt                     what the folder holds (the case's fingerprint): an
//                                        ensemble run again on the same folder resumes
//   DIR/member_NNNN.yaml                 each member's case file (`flotsam run` reruns it)
//   DIR/member_NNNN/                     its results, as `flotsam run` writes them, and
//   DIR/member_NNNN/member.txt           its statistics, written last (complete members)
//   DIR/ensemble_flow_R.bin              the shared flow of rank R while its members run
//                                        (one-way and frozen cases, coupling/shared_flow.hpp)
//   DIR/ensemble_summary.txt             the summary (also printed)
//   DIR/ensemble_members.csv, ensemble_blocking.csv, ensemble_bodies.csv
//   DIR/blocking_probability.png, jam_size.png, backwater_rise.png, stopping_points.png
//
// An interrupted ensemble resumes: members with a complete member.txt are kept, the others
// (never started, or stopped half-written) run again from the start.
#include <filesystem>
#include <string>

#include "ensemble/ensemble_config.hpp"
#include "ensemble/rank_world.hpp"
#include "io/case.hpp"

namespace flotsam {

struct EnsembleOptions {
  std::string case_file;
  std::string output;      // "" : <output.directory>/<name> of the case
  int members = 0;         // > 0: instead of ensemble.members
  int jobs = 1;            // members run at once on this process
  bool overwrite = false;  // start afresh instead of resuming an earlier ensemble of the folder
  bool progress = true;    // a progress line on stderr (rank 0)
  bool pictures = true;
  bool share_flow = true;  // one-way and frozen: the flow computed once (shared_flow_reason)
};

struct EnsembleReport {
  std::filesystem::path directory;
  std::string summary;  // rank 0 only
  int ran = 0;          // members run now (this rank)
  int kept = 0;         // members kept from an earlier, interrupted ensemble (this rank)
  int failed = 0;       // in the whole ensemble (rank 0)
  double wall_seconds = 0.0;
  double member_seconds = 0.0;  // [s] sum of the runs' wall times (this rank)
  double step_seconds = 0.0;    // [s] of which in their steps; the rest is set-up and output
  bool flow_shared = false;     // the members replayed a flow computed once (on each rank)
  std::string flow_sharing;     // why the flow is or is not shared (shared_flow_reason)
  double flow_seconds = 0.0;    // [s] computing the shared flow (this rank)
};

/// Whether the members of an ensemble can share one flow, and why: the case's mode is one-way
/// or frozen (the bodies leave the water as it is) and no input the ensemble varies or sweeps
/// changes the flow (discharge_scale does). The text says which, for the log.
struct FlowSharing {
  bool shared = false;
  std::string reason;
};
FlowSharing shared_flow_reason(const Case& base, const EnsembleConfig& config);

EnsembleReport run_ensemble(const EnsembleOptions& options, const RankWorld& world);

}  // namespace flotsam
