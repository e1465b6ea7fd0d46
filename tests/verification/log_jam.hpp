#pragma once
// A jam of logs pushed downstream by a constant force against a line of piers (the jam scene,
// src/contact/jam_scene.hpp), settled and then held: shared by log_jam_at_piers.cpp (50 logs,
// default run) and log_jam_at_piers_slow.cpp (2,000 logs before 41 piers).
// Reference: static equilibrium of a jam (spec 4.3, "resting contact must be stable"); the force
// stands in for the drag (M-6) of a steady flow.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contact/contact_world.hpp"
#include "contact/jam_scene.hpp"

namespace flotsam::test {

struct JamState {
  double fastest = 0.0;      // [m/s] largest |u| or |omega| L/2
  double deepest = 0.0;      // [m] largest overlap
  double farthest = -1e300;  // [m] largest x of a centre
};

inline JamState measure_jam(const JamScene& scene) {
  JamState s;
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

struct JamOutcome {
  int settled_after = 0;  // steps until `quiet_steps` consecutive steps were all under 1e-4 m/s
  bool settled = false;
  JamState worst;  // over the held steps
};

// The scene's step (move_jam_logs: the body integrator's l/4 limit), then the contact stage over
// the interval just taken. Settling: at most `settle_steps`, until `quiet_steps` consecutive
// steps are all under 1e-4 m/s; then `hold_steps` more, keeping the worst state.
inline JamOutcome settle_and_hold(JamScene& scene, ContactWorld& world, int settle_steps,
                                  int quiet_steps, int hold_steps) {
  auto advance = [&] { world.step(scene.bodies, scene.walls, move_jam_logs(scene)); };
  JamOutcome out;
  int quiet = 0;
  for (; out.settled_after < settle_steps && quiet < quiet_steps; ++out.settled_after) {
    advance();
    quiet = measure_jam(scene).fastest < 1e-4 ? quiet + 1 : 0;
  }
  out.settled = quiet == quiet_steps;
  if (!out.settled) return out;
  for (int k = 0; k < hold_steps; ++k) {
    advance();
    const JamState s = measure_jam(scene);
    out.worst.fastest = std::max(out.worst.fastest, s.fastest);
    out.worst.deepest = std::max(out.worst.deepest, s.deepest);
    out.worst.farthest = std::max(out.worst.farthest, s.farthest);
  }
  return out;
}

// The jam of `scene` settled (at most 6,000 steps, 200 quiet ones) and held for 1,000 steps: every
// speed under 1e-3 m/s, every overlap under 1% of a log's width, no log past the piers. The
// figures are recorded as test properties (`--gtest_output=xml`).
inline void expect_jam_settles_and_holds(JamScene& scene, ContactWorld& world) {
  const double width = scene.bodies.width[0];  // l [m]
  const JamOutcome out = settle_and_hold(scene, world, 6000, 200, 1000);
  SCOPED_TRACE(::testing::Message() << "settled after " << out.settled_after << " steps");
  ASSERT_TRUE(out.settled);
  ::testing::Test::RecordProperty("settled_after_steps", out.settled_after);
  ::testing::Test::RecordProperty("fastest_micrometres_per_s",
                                  static_cast<int>(1e6 * out.worst.fastest));
  ::testing::Test::RecordProperty("deepest_micrometres", static_cast<int>(1e6 * out.worst.deepest));
  EXPECT_LT(out.worst.fastest, 1e-3);
  EXPECT_LT(out.worst.deepest, 0.01 * width);
  EXPECT_LT(out.worst.farthest, scene.pier_x);
}

}  // namespace flotsam::test
