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
  // 2 slop: over 100,000 throws, on a thin log, the ten correction sweeps of the last interval
  // can end above the 1.5 slop they aim at (largest 0.82 % of l).
  test::expect_no_crossings(100000, 1121, 0.01);
}

}  // namespace
}  // namespace flotsam
