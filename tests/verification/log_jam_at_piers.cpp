// Verifies that 50 logs pushed downstream by a constant force against two circular piers come
// to rest and stay at rest: every speed under 1e-3 m/s, every overlap under 1% of a log's width,
// no log past the piers, for 1,000 steps after settling.
// Reference: static equilibrium of a jam (spec 4.3, "resting contact must be stable"); the
// force stands in for the drag (M-6) of a steady flow.
#include <gtest/gtest.h>

#include "log_jam.hpp"

namespace flotsam {
namespace {

TEST(LogJamAtPiers, FiftyLogsComeToRestAgainstTwoPiersAndStay) {
  JamSceneSpec spec;
  JamScene scene = make_jam_scene(spec);
  ASSERT_EQ(scene.bodies.size(), 50);
  ContactWorld world(jam_contact_config());

  test::expect_jam_settles_and_holds(scene, world);
  if (HasFatalFailure()) return;
  // The jam is anchored: every log is connected to a pier or a bank through contacts.
  const ContactReport report = world.report(scene.walls, scene.bodies.size());
  std::vector<char> anchored(50, 0);
  for (int g = 0; g < static_cast<int>(scene.walls.group_names.size()); ++g) {
    for (const int i : report.anchored_cluster(g)) anchored[i] = 1;
  }
  EXPECT_EQ(std::count(anchored.begin(), anchored.end(), 1), 50);
  EXPECT_GE(report.count_touching(2) + report.count_touching(3), 2);
}

}  // namespace
}  // namespace flotsam

namespace flotsam {
namespace {

// The same jam with the soft step (`solver: soft_step`, src/contact/soft_step.hpp).
TEST(LogJamAtPiers, FiftyLogsComeToRestAndStayWithTheSoftStep) {
  JamScene scene = make_jam_scene(JamSceneSpec{});
  ContactConfig config = jam_contact_config();
  config.solver = ContactSolverKind::soft_step;
  ContactWorld world(config);
  test::expect_jam_settles_and_holds(scene, world);
}

}  // namespace
}  // namespace flotsam

namespace flotsam {
namespace {

// The same jam with the soft step and sleeping islands (contact/island_sleep.hpp, as a case
// file's soft step): it holds as well, and ends asleep (not solved).
TEST(LogJamAtPiers, FiftyLogsComeToRestAndStayWithTheSoftStepAsleep) {
  JamScene scene = make_jam_scene(JamSceneSpec{});
  ContactConfig config = jam_contact_config();
  config.solver = ContactSolverKind::soft_step;
  config.sleep_time = soft_step_sleep_time;
  ContactWorld world(config);
  test::expect_jam_settles_and_holds(scene, world);
  for (int i = 0; i < scene.bodies.size(); ++i) EXPECT_TRUE(world.asleep(i)) << i;
}

}  // namespace
}  // namespace flotsam

namespace flotsam {
namespace {

// Sleeping with sequential impulses (`sleep_time` set in a case): the jam holds as well.
TEST(LogJamAtPiers, FiftyLogsComeToRestAndStayWithSequentialImpulsesAsleep) {
  JamScene scene = make_jam_scene(JamSceneSpec{});
  ContactConfig config = jam_contact_config();
  config.sleep_time = soft_step_sleep_time;
  ContactWorld world(config);
  test::expect_jam_settles_and_holds(scene, world);
  for (int i = 0; i < scene.bodies.size(); ++i) EXPECT_TRUE(world.asleep(i)) << i;
}

}  // namespace
}  // namespace flotsam
