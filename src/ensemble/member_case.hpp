#pragma once
// A member of an ensemble: its inputs drawn from the ensemble's seed and its index alone (so
// that member i gets the same inputs whatever the number of jobs or ranks), and its case file:
// the ensemble's case with those inputs written in, an ordinary case that `flotsam run` reruns.
//
// Member m of an ensemble with M members per sweep value has sweep index s = m / M and draw
// j = m % M. The draws depend on (seed, j) and the input only: the members with the same j at
// every sweep value share their random inputs and release seeds (common random numbers, so that
// the trend over the sweep is not buried under the noise of different draws).
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "ensemble/ensemble_config.hpp"

namespace flotsam {

struct MemberInputs {
  int member = 0;                                        // index in the ensemble, from 0
  int sweep_index = 0;                                   // which sweep value (0 without a sweep)
  int draw = 0;                                          // j: the index of the member's draws
  std::vector<std::pair<EnsembleInput, double>> values;  // swept and varied, in enum order
  std::vector<long> release_seeds;                       // one per bodies.release[k]
  /// The value of `input`; NaN when the member does not set it.
  double value(EnsembleInput input) const;
};

/// A stream of 64-bit numbers from a key (splitmix64 on a hash of the key): the same key gives
/// the same numbers on every machine and compiler.
class KeyedStream {
 public:
  explicit KeyedStream(std::initializer_list<std::uint64_t> key);
  std::uint64_t next();
  double uniform();  // in [0, 1), 53 random bits
  double normal();   // standard normal (Box-Muller)

 private:
  std::uint64_t state_;
};

/// One draw from the distribution, from `stream`.
double draw_value(const Distribution& distribution, KeyedStream& stream);

/// The inputs of member `member`; `release_count` is the number of bodies.release entries.
MemberInputs draw_member_inputs(const EnsembleConfig& config, int member, int release_count);

/// "member_0012": the name of member 12's case and folder.
std::string member_name(int member);

/// What a member's case needs besides its inputs.
struct MemberCaseContext {
  std::filesystem::path case_folder;  // the ensemble case's folder: relative file paths in it
                                      // are written absolute
  std::filesystem::path directory;    // the ensemble's folder (absolute): output.directory
  std::string source;                 // the ensemble's case file, for the header
  double gap_width = 0.0;             // [m] for log_length_over_gap (widest gap of bridge_1)
};

/// The member's case file text: `base` (the ensemble's case without its ensemble section) with
/// the member's inputs and release seeds written in, name = member_name, output.directory = the
/// ensemble's folder, and a header saying whose member it is and how to rerun it. An input that
/// cannot be applied (a rate on a release given with a count, no release for a log input) is an
/// InputError naming `source` and ensemble.vary or ensemble.sweep.
std::string member_case_text(const YAML::Node& base, const MemberInputs& inputs,
                             const MemberCaseContext& context);

}  // namespace flotsam
