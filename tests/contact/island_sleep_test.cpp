// Sleeping islands (src/contact/island_sleep.hpp, `bodies.contact.sleep_time`): a still column of
// logs against a wall falls asleep and then keeps its poses bit for bit with zero velocities; it
// stays asleep when its forces change by less than (Z-2) allows and wakes when they change by
// more, or when a log strikes it; and with sleeping the result is the same on one and two
// threads.
#include "contact/island_sleep.hpp"

#include <gtest/gtest.h>

#include "../support/thrown_jam.hpp"
#include "contact/contact_world.hpp"
#include "contact/jam_scene.hpp"
#include "core/constants.hpp"

namespace flotsam {
namespace {

constexpr int column = 5;  // logs

ContactConfig sleeping_config() {
  ContactConfig config = jam_contact_config();
  config.solver = ContactSolverKind::soft_step;
  config.sleep_time = soft_step_sleep_time;
  return config;
}

// `column` logs 10 m x 0.5 m across a channel, touching each other and a wall at x = 0.
JamScene column_scene() {
  JamScene scene;
  scene.walls.group_names = {"wall"};
  scene.walls.add_segment({0.0, -20.0}, {0.0, 20.0}, 0);  // water on the left: x < 0
  scene.walls.build_grid(2.0);
  for (int k = 0; k < column; ++k)
    scene.bodies.add(BodySpec{
        .length = 10.0, .width = 0.5, .position = {-0.25 - 0.5 * k, 0.0}, .angle = 0.5 * pi});
  return scene;
}

// One step of h = jam_max_step under a push `push` [m/s^2] along +x (semi-implicit Euler, as
// move_jam_logs), then the contact stage.
void push_step(JamScene& scene, ContactWorld& world, double push) {
  const double h = jam_max_step;  // [s]
  BodySet& b = scene.bodies;
  for (int i = 0; i < b.size(); ++i) {
    b.velocity[i].x() += push * h;
    b.position[i] += h * b.velocity[i];
    b.angle[i] += h * b.angular_velocity[i];
  }
  world.step(b, scene.walls, h);
}

bool column_asleep(const ContactWorld& world) {
  for (int i = 0; i < column; ++i)
    if (!world.asleep(i)) return false;
  return true;
}

// The column pushed until it falls asleep (at most 3,000 steps).
void settle(JamScene& scene, ContactWorld& world) {
  for (int step = 0; step < 3000 && !column_asleep(world); ++step)
    push_step(scene, world, jam_push);
  ASSERT_TRUE(column_asleep(world));
}

int changed_poses(const BodySet& now, const BodySet& then, int count) {
  int changed = 0;
  for (int i = 0; i < count; ++i)
    changed += now.position[i] != then.position[i] || now.angle[i] != then.angle[i];
  return changed;
}

TEST(IslandSleep, AStillColumnFallsAsleepAndKeepsItsPosesExactly) {
  JamScene scene = column_scene();
  ContactWorld world(sleeping_config());
  settle(scene, world);
  if (HasFatalFailure()) return;
  const BodySet asleep = scene.bodies;
  for (int step = 0; step < 200; ++step) {
    push_step(scene, world, jam_push);
    ASSERT_TRUE(column_asleep(world)) << step;
    EXPECT_EQ(world.profile().sleeping_islands, 1);
    EXPECT_EQ(world.profile().contacts - world.profile().sleeping_contacts, 0);  // none solved
  }
  EXPECT_EQ(changed_poses(scene.bodies, asleep, column), 0);  // exact, not a tolerance
  for (int i = 0; i < column; ++i) {
    EXPECT_EQ(scene.bodies.velocity[i], Vec2::Zero());
    EXPECT_EQ(scene.bodies.angular_velocity[i], 0.0);
  }
  // The wall still carries the column's push, as in the last step solved (the warm start kept
  // for when it wakes), within 1 %: still to v_s = 1e-3 m/s is not yet the exact equilibrium.
  double wall = 0.0;  // [N s]
  for (const ContactConstraint& c : world.contacts())
    if (c.b < 0)
      for (int p = 0; p < c.point_count; ++p)
        wall += c.points[static_cast<std::size_t>(p)].normal_impulse;
  const double load = column * scene.bodies.mass[0] * jam_push * jam_max_step;  // [N s]
  EXPECT_NEAR(wall, load, 1e-2 * load);
}

// (Z-2): with T_s = 0.5 s and v_s = 1e-3 m/s, a change of the push by 1e-3 m/s^2 would give
// 5e-4 m/s over T_s: the column sleeps on; by 4e-3 m/s^2 (2e-3 m/s): it wakes.
TEST(IslandSleep, ASleepingColumnWakesWhenItsForcesChangeByMoreThanTheSleepSpeedAllows) {
  JamScene scene = column_scene();
  ContactWorld world(sleeping_config());
  settle(scene, world);
  if (HasFatalFailure()) return;
  const BodySet asleep = scene.bodies;
  for (int step = 0; step < 20; ++step) push_step(scene, world, jam_push + 1e-3);
  EXPECT_TRUE(column_asleep(world));
  EXPECT_EQ(changed_poses(scene.bodies, asleep, column), 0);
  push_step(scene, world, jam_push + 4e-3);
  for (int i = 0; i < column; ++i) EXPECT_FALSE(world.asleep(i)) << i;
  // Pulled away from the wall instead: the whole column wakes and leaves.
  JamScene pulled = column_scene();
  ContactWorld pulled_world(sleeping_config());
  settle(pulled, pulled_world);
  if (HasFatalFailure()) return;
  push_step(pulled, pulled_world, -jam_push);
  for (int i = 0; i < column; ++i) {
    EXPECT_FALSE(pulled_world.asleep(i)) << i;
    EXPECT_LT(pulled.bodies.velocity[i].x(), 0.0) << i;
  }
}

TEST(IslandSleep, ASleepingColumnWakesWhenALogStrikesIt) {
  JamScene scene = column_scene();
  ContactWorld world(sleeping_config());
  settle(scene, world);
  if (HasFatalFailure()) return;
  const BodySet asleep = scene.bodies;
  // A log 1 m upstream of the column's last, thrown at it at 1 m/s.
  scene.bodies.add(BodySpec{.length = 10.0,
                            .width = 0.5,
                            .position = {-0.25 - 0.5 * column - 1.0, 0.0},
                            .angle = 0.5 * pi});
  scene.bodies.velocity[column] = {1.0, 0.0};
  bool struck = false;
  for (int step = 0; step < 100 && !struck; ++step) {
    push_step(scene, world, jam_push);
    for (const ContactConstraint& c : world.contacts())
      struck = struck || c.a == column || c.b == column;
  }
  ASSERT_TRUE(struck);
  for (int i = 0; i < column; ++i) EXPECT_FALSE(world.asleep(i)) << i;
  push_step(scene, world, jam_push);
  EXPECT_GT(changed_poses(scene.bodies, asleep, column), 0);  // the blow reached the column
  EXPECT_GT(scene.bodies.velocity[column - 1].x(), 0.0);      // the struck log moves on
}

// The jam of 50 logs before two piers (jam_scene.hpp), thrown about, with sleeping: 1 and 2
// threads end in the same states, bit for bit, with islands asleep.
BodySet thrown_logs_after(int threads, int& sleeping) {
  const auto asleep = [](const ContactProfile& p) { return p.sleeping_islands; };
  return test::stepped_on_threads(test::thrown_jam_scene(50, 2, 0.3), sleeping_config(), threads,
                                  2000, asleep, sleeping);
}

TEST(IslandSleep, SleepingGivesTheSameResultOnOneAndTwoThreads) {
  int sleeping_1 = 0, sleeping_2 = 0;
  const BodySet one = thrown_logs_after(1, sleeping_1);
  const BodySet two = thrown_logs_after(2, sleeping_2);
  EXPECT_GT(sleeping_1, 0);
  EXPECT_EQ(sleeping_1, sleeping_2);
  EXPECT_EQ(test::count_different_states(one, two), 0);  // exact equality, not a tolerance
}

}  // namespace
}  // namespace flotsam
