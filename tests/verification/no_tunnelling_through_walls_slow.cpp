// ctest-label: slow
// Verifies that 100,000 logs thrown at the banks and at a circular pier at up to 10 m/s never end
// up across a wall when stepped as the simulation steps them (each flow step planned by the
// contact stage: within a contact interval no point closes on a wall by more than l/4). About 10 s:
// the default run has the 10,000-throw version (no_tunnelling_through_walls.cpp). Reference:
// spec 4.3 and 3.5; the exact answer is zero crossings.
#include <gtest/gtest.h>

#include "log_throws.hpp"

namespace flotsam {
namespace {

TEST(NoTunnellingThroughWalls, HundredThousandThrowsAtBanksAndPier) {
  const test::ThrowStatistics s = test::throw_logs(100000, 1121);
  EXPECT_EQ(s.throws, 100000);
  EXPECT_EQ(s.crossings, 0);
  EXPECT_GT(s.hits, s.throws / 2);  // most throws reach their wall: the contacts are exercised
  EXPECT_LT(s.deepest, 0.5);        // relative to l
  // 2 slop: over 100,000 throws, on a thin log, the ten correction sweeps of the last interval
  // can end above the 1.5 slop they aim at (largest 0.82 % of l).
  EXPECT_LT(s.deepest_end, 0.01);
  RecordProperty("intervals", static_cast<int>(s.intervals));
  RecordProperty("hits", static_cast<int>(s.hits));
  RecordProperty("deepest_permille", static_cast<int>(1000.0 * s.deepest));
  RecordProperty("deepest_end_per_100000", static_cast<int>(1e5 * s.deepest_end));
}

}  // namespace
}  // namespace flotsam
