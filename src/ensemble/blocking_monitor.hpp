#pragma once
// Blocking (docs/model.md "Blocking"), watched over one member's run. A gap of a bridge line is
// blocked when the jams at that bridge cover at least `fraction` of its width, without a break,
// for at least `duration` seconds; the bridge is blocked when one of its gaps is. Coverage is
// sampled at the jam statistics' times (BlockingCriterion::sample_interval), so a blocking is
// held from the first sample at or above the fraction to a sample at least `duration` later,
// every sample in between at or above it.
//
// The monitor also follows each body from the step it appears (its start for the travel
// distance) to the end, and the largest jam, blockage, closed share of the openings and
// backwater rise at each bridge (and the largest cover and closed share of each gap).
#include <span>
#include <vector>

#include "bodies/body_set.hpp"
#include "coupling/jam_statistics.hpp"
#include "ensemble/ensemble_config.hpp"
#include "ensemble/member_result.hpp"

namespace flotsam {

/// The share of each gap of `bridge` covered by the union of the footprint spans of the bodies
/// in the jams at that bridge [-] (docs/model.md "Jam statistics", footprint span).
std::vector<double> gap_cover(const JamStatistics& statistics, const BodySet& bodies,
                              const JamGeometry& geometry, int bridge);

class BlockingMonitor {
 public:
  BlockingMonitor(const JamGeometry& geometry, const BlockingCriterion& criterion);

  /// Records where bodies that appeared since the last call are (call after every step, and once
  /// after the run is initialised for the bodies present at the start).
  void note_new_bodies(const BodySet& bodies);

  /// One sample at time t [s]: `rise` [m] per bridge, empty without a reference flow.
  void sample(double t, const JamStatistics& statistics, const BodySet& bodies,
              std::span<const double> rise);

  /// The member's outcome at the end: counts and fates from the final `statistics`.
  void finish(const JamStatistics& statistics, const BodySet& bodies, MemberResult& result) const;

 private:
  const JamGeometry* geometry_;
  BlockingCriterion criterion_;
  std::vector<Vec2> start_;  // [m] per body index: G when first seen
  std::vector<BridgeOutcome> bridges_;
  std::vector<std::vector<GapOutcome>> gaps_;
  std::vector<std::vector<double>> streak_start_;  // [s] per gap: start of the covered run, or NaN
};

}  // namespace flotsam
