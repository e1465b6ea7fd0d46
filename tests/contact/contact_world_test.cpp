// The contact stage's second solve (src/contact/contact_world.cpp, docs/model.md "Second solve with
// grown margins"): a log resting 2 cm above a pier, struck from above by another log, is pushed
// towards the pier by the impulse; the pose update of one long interval would carry it across
// the pier's edge, which detection (margin 2 slop = 5 mm) did not see. The second solve sees the
// pier as a gap and lets the log close it and no more.
#include "contact/contact_world.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <tuple>

#include "../support/thrown_jam.hpp"
#include "contact/jam_scene.hpp"
#include "core/constants.hpp"

namespace flotsam {
namespace {

TEST(ContactWorld, AStruckLogIsNotPushedIntoAPierItsMarginDidNotReach) {
  BoundarySegments walls;
  walls.group_names = {"pier"};
  walls.add_circle_hole({0.0, 0.0}, 1.0, 64, 0);  // radius 1 m; the top face at y = 0.9988 m
  walls.build_grid(0.5);
  BodySet bodies;  // logs 10 m x 0.5 m along x
  bodies.add(BodySpec{.length = 10.0, .width = 0.5, .position = {0.0, 1.27}});  // 2 cm gap
  bodies.add(BodySpec{.length = 10.0,
                      .width = 0.5,
                      .position = {0.0, 1.72},    // 5 cm into the first,
                      .velocity = {0.0, -2.0}});  // coming down at 2 m/s
  ContactConfig config;  // e = 1: the blow gives the first log the striker's 2 m/s
  ContactWorld world(config);
  constexpr double h = 0.5;  // [s] the interval
  world.step(bodies, walls, h);
  EXPECT_EQ(world.profile().second_solves, 1);
  // Without the second solve the pose update moves it h * 2 m/s = 1 m down, its centre to
  // y = 0.27 m, inside the pier. With it, it closes the 2 cm gap at most: the gap between the
  // pier's top vertex (0, 1) and the log's lower side stays within [-2 slop, 2 cm].
  const Vec2 up = perp(bodies.axis(0));  // the log's upward normal
  const double gap = -(Vec2(0.0, 1.0) - bodies.position[0]).dot(up) - 0.25;  // [m]
  EXPECT_GT(gap, -2.0 * config.allowed_overlap * 0.5);
  EXPECT_LT(gap, 0.02 + 1e-12);
  EXPECT_LE(bodies.velocity[0].y(), 0.0);
}

// A log pushed against a wall by a steady force (as a jam's drag pushes it against a deck) is
// held there: each flow step is planned, the body step moves it over the interval with the force
// (x += h u + a h^2 / 2, u += a h), and the contact stage puts it where the interval started
// moved on by its new velocity (docs/model.md "Pose update from the interval's start"). Exact
// answer: once at the wall, it stays in contact every interval, at rest, its pose unchanged to
// round-off (the soft step's once its spring has settled). (Moving it on by h times the change of
// velocity alone backed it off by a h^2 / 2 = 0.5 m per 1 s interval and took it out of contact.)
// Both solvers.
class HeldAgainstAWall : public ::testing::TestWithParam<ContactSolverKind> {};

TEST_P(HeldAgainstAWall, StaysInContactAtRestEveryInterval) {
  BoundarySegments walls;
  walls.group_names = {"deck"};
  walls.add_segment({10.0, -20.0}, {10.0, 20.0}, 0);  // a face across x = 10 m, facing -x
  walls.build_grid(2.0);
  BodySet bodies;  // a log across the flow, 0.5 m thick, its front face 1 cm from the wall
  bodies.add(BodySpec{.length = 10.0, .width = 0.5, .position = {9.74, 0.0}, .angle = pi / 2});
  ContactConfig config;
  config.solver = GetParam();
  config.restitution = 0.0;
  ContactWorld world(config);
  constexpr double dt = 1.0, a = 1.0;  // [s] flow step, [m/s^2] the force's acceleration along x
  // The soft step's spring pushes the slop's overlap out over some steps (5e-5 m, then halving).
  const int settled = config.solver == ContactSolverKind::soft_step ? 25 : 5;
  Vec2 held = Vec2::Zero();
  int touching = 0;
  for (int step = 0; step < 40; ++step) {
    bodies.drag_force[0] = bodies.reaction_force[0] = Vec2(bodies.mass[0] * a, 0.0);  // [N]
    const ContactSchedule plan = world.plan(bodies, walls, dt);
    ASSERT_TRUE(plan.free.empty()) << "step " << step;  // the wall is within its reach
    const int K = plan.groups.empty() ? 1 : plan.groups.front().intervals;
    const double h = dt / K;  // [s] as BodyIntegrator::advance: the group's intervals, then all
    for (int k = 0; k < K; ++k) {
      bodies.position[0] += h * bodies.velocity[0] + Vec2(0.5 * a * h * h, 0.0);
      bodies.velocity[0] += Vec2(a * h, 0.0);
      world.step(bodies, walls, h, k + 1 < K ? &plan.groups.front().bodies : &plan.at_end);
    }
    if (step < 5) continue;  // reaching the wall
    EXPECT_FALSE(world.contacts().empty()) << "step " << step;
    touching += !world.contacts().empty();
    if (step > settled) {
      EXPECT_NEAR(bodies.velocity[0].norm(), 0.0, 1e-9) << "step " << step;
      EXPECT_NEAR((bodies.position[0] - held).norm(), 0.0, 1e-9) << "step " << step;
    }
    held = bodies.position[0];
  }
  EXPECT_EQ(touching, 35);
  // Its face at the wall, within 3 slop (the soft step's spring holds it 2.2 slop in).
  EXPECT_NEAR(held.x(), 9.75, 3.0 * config.allowed_overlap * 0.5);
}

INSTANTIATE_TEST_SUITE_P(Solvers, HeldAgainstAWall,
                         ::testing::Values(ContactSolverKind::sequential_impulses,
                                           ContactSolverKind::soft_step));

// Islands are solved in parallel (contact/islands.hpp); none reads another's bodies and each keeps
// its contacts' order, so the result is the same, bit for bit, on 1 and 2 threads. The scene:
// 600 logs in loose rows before 30 piers, thrown about at up to 1 m/s: many islands at once
// (30 steps: a few seconds under the sanitizers).
BodySet thrown_logs_after(int threads, int steps, int& most_islands) {
  const auto islands = [](const ContactProfile& p) { return p.contacts >= 256 ? p.islands : 0; };
  return test::stepped_on_threads(test::thrown_jam_scene(600, 30, 0.05),  // row gap [m]
                                  jam_contact_config(), threads, steps, islands, most_islands);
}

TEST(ContactWorld, IslandsSolvedInParallelGiveTheSameResultOnOneAndTwoThreads) {
  int islands_1 = 0, islands_2 = 0;
  const BodySet one = thrown_logs_after(1, 30, islands_1);
  const BodySet two = thrown_logs_after(2, 30, islands_2);
  EXPECT_GT(islands_2, 20);  // the parallel path ran, over many islands
  EXPECT_EQ(islands_1, islands_2);
  EXPECT_EQ(test::count_different_states(one, two), 0);  // exact equality, not a tolerance
}

// The narrow phase builds each contact straight into its island's place and warm-starts it from
// its pair's last contact, found through an index of the last contacts by body (contact_world.cpp).
// Detected again from the same poses after 10 steps of a thrown jam: the contacts are the pairs
// and points a fresh world finds, already grouped by island (group() moves none), and every point
// whose feature was a point of its pair's last contact starts from that point's impulses; a pair
// new since the last step starts from none.
using ContactKey = std::tuple<int, int, int>;  // (a, b, segment)
ContactKey key_of(const ContactConstraint& c) {
  return {c.a, c.b, c.segment};
}

TEST(ContactWorld, ContactsDetectedAgainAreTheFreshPairsGroupedAndWarmStartedFromTheirOwn) {
  JamScene scene = test::thrown_jam_scene(600, 30, 0.0);
  ContactConfig config = jam_contact_config();
  config.solver = ContactSolverKind::soft_step;
  ContactWorld world(config);
  for (int step = 0; step < 10; ++step) world.step(scene.bodies, scene.walls, move_jam_logs(scene));
  const std::vector<ContactConstraint> last = world.contacts();
  world.detect(scene.bodies, scene.walls);
  const std::vector<ContactConstraint>& now = world.contacts();
  ContactWorld fresh(config);
  fresh.detect(scene.bodies, scene.walls);
  ASSERT_GT(now.size(), 1000u);
  std::vector<ContactKey> keys, fresh_keys;
  for (const ContactConstraint& c : now) keys.push_back(key_of(c));
  for (const ContactConstraint& c : fresh.contacts()) fresh_keys.push_back(key_of(c));
  std::vector<ContactKey> sorted = keys;
  std::sort(sorted.begin(), sorted.end());
  std::sort(fresh_keys.begin(), fresh_keys.end());
  EXPECT_EQ(sorted, fresh_keys);
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());  // one per pair
  std::vector<ContactConstraint> grouped = now;
  Islands islands;
  islands.group(grouped, scene.bodies.size());
  for (std::size_t m = 0; m < now.size(); ++m) ASSERT_EQ(key_of(grouped[m]), keys[m]);
  std::map<ContactKey, const ContactConstraint*> by_key;
  for (const ContactConstraint& c : last) by_key[key_of(c)] = &c;
  int matched = 0, loaded = 0;
  for (const ContactConstraint& c : now) {
    const auto found = by_key.find(key_of(c));
    for (int k = 0; k < c.point_count; ++k) {
      const ContactPointConstraint& p = c.points[static_cast<std::size_t>(k)];
      const ContactPointConstraint* old = nullptr;
      for (int q = 0; found != by_key.end() && q < found->second->point_count; ++q)
        if (found->second->points[static_cast<std::size_t>(q)].feature == p.feature)
          old = &found->second->points[static_cast<std::size_t>(q)];
      if (found == by_key.end()) {
        EXPECT_EQ(p.normal_impulse, 0.0);
        EXPECT_EQ(p.first_impulse, Vec2::Zero());
        continue;
      }
      if (!old) continue;  // matched by position, or not at all
      ++matched;
      loaded += old->normal_impulse > 0.0;
      EXPECT_EQ(p.normal_impulse, old->normal_impulse);  // exact: copied
      EXPECT_EQ(p.tangent_impulse, old->tangent_impulse);
      EXPECT_EQ(p.first_impulse, old->first_impulse);
      EXPECT_EQ(p.last_impulse, old->last_impulse);
      EXPECT_EQ(p.resting, old->normal_impulse > 0.0);
    }
  }
  EXPECT_GT(matched, 1000);
  EXPECT_GT(loaded, 500);  // the jam is pressed together: many points carry impulses
  EXPECT_GE(world.profile().warm_started_points, matched);
}

}  // namespace
}  // namespace flotsam
