// Verifies that logs thrown at the banks and at a circular pier at up to 10 m/s never end up
// across a wall when stepped as the simulation steps them (each flow step planned by the contact
// stage: within a contact interval no point closes on a wall by more than l/4): 10,000 random
// throws here, the full 100,000 in no_tunnelling_through_walls_slow.cpp.
// Reference: spec 4.3 and 3.5 (a body's step is short enough that it cannot cross a wall); the
// exact answer is zero crossings. Overlaps stay under l/2 (the log's axis never reaches the
// wall) and the position correction leaves at most 1.5 slop = 0.75% of l at the end.
#include <gtest/gtest.h>

#include "log_throws.hpp"

namespace flotsam {
namespace {

TEST(NoTunnellingThroughWalls, TenThousandThrowsAtBanksAndPier) {
  test::expect_no_crossings(10000, 2026, 0.0075);  // 1.5 slop = 0.75 % of l
}

}  // namespace
}  // namespace flotsam
