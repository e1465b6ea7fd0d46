// ctest-label: slow
// The jam of log_jam_at_piers.cpp scaled to 2,000 logs before 41 piers (about 50 logs per gap, the
// rows alternating between odd and even gaps so that they interlock into one jam across the
// channel): every speed under 1e-3 m/s, every overlap under 1% of a log's width and no log past
// the piers for 1,000 steps after settling (issue 18).
#include <gtest/gtest.h>

#include "log_jam.hpp"

namespace flotsam {
namespace {

TEST(LogJamAtPiers, TwoThousandLogsComeToRestAgainstFortyOnePiersAndStay) {
  JamSceneSpec spec;
  spec.log_count = 2000;
  spec.pier_count = 41;
  JamScene scene = make_jam_scene(spec);
  ContactWorld world(jam_contact_config());
  const double width = scene.bodies.width[0];  // l [m]
  const test::JamOutcome out = test::settle_and_hold(scene, world, 6000, 200, 1000);
  SCOPED_TRACE(::testing::Message() << "settled after " << out.settled_after << " steps");
  ASSERT_TRUE(out.settled);
  RecordProperty("settled_after_steps", out.settled_after);
  RecordProperty("fastest_micrometres_per_s", static_cast<int>(1e6 * out.worst.fastest));
  RecordProperty("deepest_micrometres", static_cast<int>(1e6 * out.worst.deepest));
  EXPECT_LT(out.worst.fastest, 1e-3);
  EXPECT_LT(out.worst.deepest, 0.01 * width);
  EXPECT_LT(out.worst.farthest, scene.pier_x);
}

}  // namespace
}  // namespace flotsam
