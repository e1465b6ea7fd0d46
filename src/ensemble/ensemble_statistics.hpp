#pragma once
// Statistics across the members of an ensemble (docs/model.md "Blocking"): the probability that
// each bridge and each gap blocks, with its 95% Wilson score interval, per sweep value; the
// distributions of jam size, backwater rise and travel distance; the fates of the bodies. Every
// sum runs over the members in their order, so the result does not depend on which job or rank
// ran which member.
#include <string>
#include <vector>

#include "coupling/jam_statistics.hpp"
#include "ensemble/ensemble_config.hpp"
#include "ensemble/member_result.hpp"

namespace flotsam {

/// z of the two-sided 95% normal interval: Phi^-1(0.975) [-].
inline constexpr double z_95 = 1.959963984540054;

/// A proportion k/n and its Wilson score interval (Wilson 1927; Brown, Cai & DasGupta 2001):
///   centre = (p + z^2/(2n)) / (1 + z^2/n),
///   half   = z / (1 + z^2/n) sqrt(p (1 - p)/n + z^2/(4 n^2)),   p = k/n.
/// n = 0 gives p = NaN and the interval [0, 1].
struct Proportion {
  int successes = 0;
  int trials = 0;
  double p = 0.0;      // [-] k/n
  double lower = 0.0;  // [-]
  double upper = 1.0;  // [-]
};
Proportion wilson_interval(int successes, int trials, double z = z_95);

/// Order statistics of a sample: mean, min, median, 90th percentile, max (the percentiles by
/// linear interpolation between order statistics, R's type 7). NaN values are left out;
/// `count` is what remains (0: every field NaN).
struct SampleSummary {
  int count = 0;
  double mean = 0.0, min = 0.0, median = 0.0, p90 = 0.0, max = 0.0;
};
SampleSummary summarize(std::vector<double> values);

/// Counts of `values` in `bins` equal bins over [lower, upper] (the last bin closed).
std::vector<int> histogram(const std::vector<double>& values, double lower, double upper, int bins);

/// The blocking estimate of one bridge or gap at one sweep value.
struct BlockingEstimate {
  std::string target;  // "bridge_1", "bridge_1 gap 2"
  int bridge = 0;
  int gap = -1;  // -1: the bridge as a whole
  Proportion blocked;
};

/// Everything at one sweep value (the whole ensemble without a sweep).
struct SweepStatistics {
  double value = 0.0;  // the swept input's value (0 without a sweep)
  int members = 0, failed = 0;
  std::vector<BlockingEstimate> blocking;  // per bridge, then its gaps
  SampleSummary jam_size;                  // largest jam at any bridge, per member [bodies]
  SampleSummary backwater_rise;            // largest rise at any bridge, per member [m]
  SampleSummary travel;                    // per body [m]
  double released = 0, passed = 0, left = 0, trapped = 0, stranded = 0, floating = 0;  // means
  Proportion trapped_any;      // members with at least one body trapped in a jam at the end
  Proportion trapped_several;  // ... with at least `several_trapped` bodies
};

/// "Several" bodies trapped at the end of a member (the paper's Fig. 17 question: do logs stay
/// at the piers?) [bodies].
inline constexpr int several_trapped = 3;

struct EnsembleStatistics {
  std::vector<SweepStatistics> sweep;  // per sweep value, in the order given
  std::vector<const MemberResult*> failures;
};

/// `results` in member order, complete (one per member).
EnsembleStatistics compute_ensemble_statistics(const std::vector<MemberResult>& results,
                                               const EnsembleConfig& config,
                                               const JamGeometry& geometry);

/// The end-of-ensemble summary (deterministic: no timings, no paths).
std::string format_ensemble_summary(const EnsembleStatistics& statistics,
                                    const EnsembleConfig& config, const std::string& case_name);

/// ensemble_members.csv, ensemble_blocking.csv and ensemble_bodies.csv in `directory`
/// (docs/output-format.md, "Ensembles").
void write_ensemble_tables(const std::string& directory, const std::vector<MemberResult>& results,
                           const EnsembleStatistics& statistics, const EnsembleConfig& config,
                           const JamGeometry& geometry);

}  // namespace flotsam
