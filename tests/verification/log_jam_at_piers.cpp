// Verifies that 50 logs pushed downstream by a constant force against two circular piers come
// to rest and stay at rest: every speed under 1e-3 m/s, every overlap under 1% of a log's width,
// no log past the piers, for 1,000 steps after settling.
// Reference: static equilibrium of a jam (spec 4.3, "resting contact must be stable"); the
// force stands in for the drag (M-6) of a steady flow.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contact/contact_world.hpp"
#include "contact/jam_scene.hpp"

namespace flotsam {
namespace {

// The scene's step (move_jam_logs: the body integrator's l/4 limit), then the contact stage
// over the interval just taken.
void advance(JamScene& scene, ContactWorld& world) {
  const double dt = move_jam_logs(scene);
  world.step(scene.bodies, scene.walls, dt);
}

struct State {
  double fastest = 0.0;      // [m/s] largest |u| or |omega| L/2
  double deepest = 0.0;      // [m] largest overlap
  double farthest = -1e300;  // [m] largest x of a centre
};

State measure(const JamScene& scene) {
  State s;
  const BodySet& b = scene.bodies;
  for (int i = 0; i < b.size(); ++i) {
    s.fastest = std::max(
        {s.fastest, b.velocity[i].norm(), std::abs(b.angular_velocity[i]) * 0.5 * b.length[i]});
    s.farthest = std::max(s.farthest, b.position[i].x());
  }
  ContactWorld probe{ContactConfig{}};
  probe.detect(b, scene.walls);
  for (const ContactConstraint& c : probe.contacts()) {
    for (int k = 0; k < c.point_count; ++k) {
      s.deepest = std::max(s.deepest, -c.points[static_cast<std::size_t>(k)].separation);
    }
  }
  return s;
}

TEST(LogJamAtPiers, FiftyLogsComeToRestAgainstTwoPiersAndStay) {
  JamSceneSpec spec;
  JamScene scene = make_jam_scene(spec);
  ASSERT_EQ(scene.bodies.size(), 50);
  ContactWorld world(jam_contact_config());

  const double width = scene.bodies.width[0];  // l [m]
  // Settling: at most 6,000 steps (120 s), until 200 consecutive steps are all under 1e-4 m/s.
  int step = 0, quiet = 0;
  for (; step < 6000 && quiet < 200; ++step) {
    advance(scene, world);
    quiet = measure(scene).fastest < 1e-4 ? quiet + 1 : 0;
  }
  SCOPED_TRACE(::testing::Message() << "settled after " << step << " steps");
  ASSERT_EQ(quiet, 200);
  State worst;
  for (int k = 0; k < 1000; ++k) {
    advance(scene, world);
    const State s = measure(scene);
    worst.fastest = std::max(worst.fastest, s.fastest);
    worst.deepest = std::max(worst.deepest, s.deepest);
    worst.farthest = std::max(worst.farthest, s.farthest);
  }
  RecordProperty("settled_after_steps", step);
  RecordProperty("fastest_micrometres_per_s", static_cast<int>(1e6 * worst.fastest));
  RecordProperty("deepest_micrometres", static_cast<int>(1e6 * worst.deepest));
  EXPECT_LT(worst.fastest, 1e-3);
  EXPECT_LT(worst.deepest, 0.01 * width);
  EXPECT_LT(worst.farthest, scene.pier_x);
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
