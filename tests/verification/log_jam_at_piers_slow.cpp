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
  test::expect_jam_settles_and_holds(scene, world);
}

}  // namespace
}  // namespace flotsam
