#pragma once
// Runs one member of an ensemble as an ordinary run: its case file written beside its folder
// (DIR/member_NNNN.yaml, results in DIR/member_NNNN/), the case read back from that text as
// `flotsam run` reads it, the run stepped to its end with the blocking monitor sampling the jam
// statistics, and member.txt written last. A member without member.txt is run again whole when
// the ensemble resumes: it runs with RunOptions::rerun_whole. A member that fails (its case
// refused, its run stopped) returns a result marked failed with the message; it never throws.
#include <filesystem>
#include <memory>
#include <string>

#include "coupling/jam_statistics.hpp"
#include "coupling/mesh_setup.hpp"
#include "ensemble/ensemble_config.hpp"
#include "ensemble/member_result.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

struct MemberRun {
  MemberInputs inputs;
  std::string case_text;            // its case file (member_case_text)
  std::filesystem::path case_path;  // where it is written: DIR/member_NNNN.yaml
  std::filesystem::path folder;     // its results: DIR/member_NNNN/
};

/// What every member shares: the mesh (generated once) and its set-up, its jam geometry, the
/// criterion, and in one-way and frozen ensembles the flow.
struct MemberSetup {
  const Mesh* mesh = nullptr;
  const JamGeometry* geometry = nullptr;
  BlockingCriterion criterion;
  int threads = 0;  // OpenMP threads of each member's flow; 0: the default
  std::filesystem::path shared_flow =
      {};  // the flow every member replays (coupling/shared_flow.hpp);
           // "": each computes its own
  /// The mesh's set-up, built once for all the members (coupling/mesh_setup.hpp).
  std::shared_ptr<const MeshSetup> mesh_setup = nullptr;
};

MemberResult run_member(const MemberRun& run, const MemberSetup& setup);

}  // namespace flotsam
