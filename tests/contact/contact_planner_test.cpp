// The contact plan of a flow step (src/contact/contact_planner.hpp): which bodies are linked (may
// touch), the groups equal the connected components of the links that need more than one
// interval (checked against a brute-force search on random scenes), and each group's interval
// count K follows the l/4 rule on the closing distance, exactly.
#include "contact/contact_planner.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

namespace flotsam {
namespace {

constexpr double safety = 1.5;  // s of contact_planner.hpp [-]

BoundarySegments bank_at_zero() {
  BoundarySegments walls;
  walls.group_names = {"bank"};
  walls.add_segment({-1000.0, 0.0}, {1000.0, 0.0}, 0);  // y = 0, water above
  walls.build_grid(10.0);
  return walls;
}

TEST(ContactPlanner, BodiesOutOfEachOthersReachAreFree) {
  BodySet bodies;  // logs 20 m x 1 m, 100 m apart, at 2 m/s: each reaches 3 m in 1 s
  bodies.add(BodySpec{.position = {0, 50}, .velocity = {2, 0}});
  bodies.add(BodySpec{.position = {100, 50}, .velocity = {-2, 0}});
  ContactPlanner planner;
  const ContactSchedule s = planner.plan(bodies, bank_at_zero(), 1.0, ContactConfig{});
  EXPECT_TRUE(s.groups.empty());
  EXPECT_EQ(s.free, (std::vector<int>{0, 1}));
}

TEST(ContactPlanner, ALogDriftingTowardsABankGetsTheQuarterWidthIntervals) {
  BodySet bodies;  // 1 m from the bank, closing at 3 m/s: reach 1.5 * 3 m = 4.5 m in 1 s
  bodies.add(BodySpec{.position = {0, 1.5}, .velocity = {0, -3}});
  ContactPlanner planner;
  const ContactSchedule s = planner.plan(bodies, bank_at_zero(), 1.0, ContactConfig{});
  ASSERT_EQ(s.groups.size(), 1u);
  EXPECT_EQ(s.groups[0].bodies, (std::vector<int>{0}));
  EXPECT_EQ(s.groups[0].intervals, static_cast<int>(std::ceil(safety * 3.0 / 0.25)));  // 18
  EXPECT_TRUE(s.free.empty());
  EXPECT_EQ(s.at_end, (std::vector<int>{0}));
}

TEST(ContactPlanner, LogsDriftingTogetherNeedOneIntervalWhateverTheirSpeed) {
  BodySet bodies;  // side by side, touching, both at 4 m/s: they close on each other at 0 m/s
  bodies.add(BodySpec{.position = {0, 50}, .velocity = {4, 0}});
  bodies.add(BodySpec{.position = {0, 51}, .velocity = {4, 0}});
  ContactPlanner planner;
  const ContactSchedule s = planner.plan(bodies, bank_at_zero(), 1.0, ContactConfig{});
  EXPECT_TRUE(s.groups.empty());  // each crosses the step in one go,
  EXPECT_EQ(s.free, (std::vector<int>{0, 1}));
  EXPECT_EQ(s.at_end, (std::vector<int>{0, 1}));  // their contact resolved at its end
}

TEST(ContactPlanner, AnApproachingLogSetsItsGroupsIntervalsByTheThinnerWidth) {
  BodySet bodies;  // a thin log (l = 0.4 m) 2 m behind a resting one, closing at 2 m/s
  bodies.add(BodySpec{.position = {0, 50}});
  bodies.add(BodySpec{.width = 0.4, .position = {-22, 50}, .velocity = {2, 0}});
  bodies.add(BodySpec{.position = {20, 50}});  // resting end to end with the first: one interval
  ContactPlanner planner;
  const ContactSchedule s = planner.plan(bodies, bank_at_zero(), 1.0, ContactConfig{});
  ASSERT_EQ(s.groups.size(), 1u);
  EXPECT_EQ(s.groups[0].bodies, (std::vector<int>{0, 1}));
  EXPECT_EQ(s.groups[0].intervals, static_cast<int>(std::ceil(safety * 2.0 / (0.25 * 0.4))));
  EXPECT_EQ(s.free, (std::vector<int>{2}));
  EXPECT_EQ(s.at_end, (std::vector<int>{0, 1, 2}));
  // Over a step of 0.5 s it closes by at most 1.5 m, less than the 2 m gap: not linked.
  const ContactSchedule short_step = planner.plan(bodies, bank_at_zero(), 0.5, ContactConfig{});
  EXPECT_TRUE(short_step.groups.empty());
  EXPECT_EQ(short_step.at_end, (std::vector<int>{0, 2}));
  EXPECT_EQ(short_step.free, (std::vector<int>{0, 1, 2}));
}

TEST(ContactPlanner, AnAcceleratedBodyGetsIntervalsInWhichItMovesAQuarterWidth) {
  BodySet bodies;  // at rest 2 m from the bank, the drag pulling it there at 4 m/s^2
  bodies.add(BodySpec{.position = {0, 2.5}});
  bodies.drag_force[0] = Vec2(0.0, -4.0 * bodies.mass[0]);
  bodies.reaction_force[0] = bodies.drag_force[0];  // F_x = F_drag: no added-mass term
  ContactPlanner planner;
  // reach = 1.5 * 4 * 1^2 / 2 = 3 m > 2 m: the bank is within reach. From rest, an interval h
  // moves it 1.5 * 4 h^2 / 2 <= 0.25 m: h <= 0.2887 s, K = 4 (not 3 m / 0.25 m = 12).
  const ContactSchedule s = planner.plan(bodies, bank_at_zero(), 1.0, ContactConfig{});
  ASSERT_EQ(s.groups.size(), 1u);
  EXPECT_EQ(s.groups[0].intervals, 4);
  // Moving at 1 m/s as well: 1.5 (h + 2 h^2) <= 0.25 gives h <= 0.1319 s, K = 8.
  bodies.velocity[0] = Vec2(0.0, -1.0);
  EXPECT_EQ(planner.plan(bodies, bank_at_zero(), 1.0, ContactConfig{}).groups[0].intervals, 8);
}

// A log a contact has just stopped 2 m from the bank (its footprint's edge), the water running at
// 1.5 m/s towards the bank: its last sub-step saw it drift at 0.05 m/s relative to the water
// (drag K u_rel, K = 100 kg/s), so its loads are tiny, but within the step the drag can bring
// it back to 1.45 m/s faster than now: reach 1.5 * 1.45 m > 2 m, intervals in which it moves a
// quarter width, ceil(1.5 * 1.45 / 0.25) = 9. Had the contact not stopped it (u_p = u_f - u_rel)
// it would move with the water, and the same loads plan it with its speed as before.
TEST(ContactPlanner, ABodyAContactStoppedIsPlannedWithTheDriftTheWaterGivesItBack) {
  BodySet bodies;
  bodies.add(BodySpec{.position = {0, 2.5}});
  const double K = 100.0;  // [kg/s]
  bodies.drag_rate[0] = K;
  bodies.drag_force[0] = Vec2(0.0, -0.05 * K);
  bodies.reaction_force[0] = bodies.drag_force[0];
  bodies.flow_velocity[0] = Vec2(0.0, -1.5);
  ContactPlanner planner;
  const ContactSchedule stopped = planner.plan(bodies, bank_at_zero(), 1.0, ContactConfig{});
  ASSERT_EQ(stopped.groups.size(), 1u);
  EXPECT_EQ(stopped.groups[0].intervals, 9);
  bodies.velocity[0] = Vec2(0.0, -1.45);  // drifting: 1.5 * 1.45 m again, from its own speed
  const ContactSchedule drifting = planner.plan(bodies, bank_at_zero(), 1.0, ContactConfig{});
  ASSERT_EQ(drifting.groups.size(), 1u);
  EXPECT_EQ(drifting.groups[0].intervals, 9);
  bodies.flow_velocity[0] = Vec2(0.0, -0.05);  // a slow flow: neither drift nor reach
  bodies.velocity[0] = Vec2::Zero();
  EXPECT_TRUE(planner.plan(bodies, bank_at_zero(), 1.0, ContactConfig{}).groups.empty());
}

// Brute force: i and j linked when their footprint boxes are within the closing distance (the
// planner's formula, written out again here); the linked bodies, and the components (by
// depth-first search) of the links that need more than one interval (no accelerations here:
// K = ceil(closing / (l_min / 4))).
struct BruteForcePlan {
  std::vector<int> linked;
  std::vector<std::vector<int>> groups;
};

BruteForcePlan brute_force_plan(const BodySet& b, double dt, double margin_f) {
  const int n = b.size();
  auto box = [&](int i) {
    const Vec2 u = b.axis(i), h = b.half_extents(i);
    const Vec2 e(std::abs(u.x()) * h.x() + std::abs(u.y()) * h.y(),
                 std::abs(u.y()) * h.x() + std::abs(u.x()) * h.y());
    return Aabb{b.position[i] - e, b.position[i] + e};
  };
  std::vector<std::vector<int>> links(static_cast<std::size_t>(n));
  std::vector<char> is_linked(static_cast<std::size_t>(n), 0);
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const Aabb a = box(i), c = box(j);
      const Vec2 d = (a.lower - c.upper).cwiseMax(c.lower - a.upper).cwiseMax(0.0);
      // The closing speed seen from each body (the other's rotation about it taken out).
      auto seen_from = [&](int p, int q) {
        const Vec2 r = b.position[q] - b.position[p];
        const Vec2 rigid(b.velocity[p].x() - b.velocity[q].x() - b.angular_velocity[q] * r.y(),
                         b.velocity[p].y() - b.velocity[q].y() + b.angular_velocity[q] * r.x());
        return rigid.norm() + std::abs(b.angular_velocity[p] - b.angular_velocity[q]) * 0.5 *
                                  std::sqrt(b.length[p] * b.length[p] + b.width[p] * b.width[p]);
      };
      auto fastest = [&](int p) {  // its fastest point's speed
        return b.velocity[p].norm() +
               std::abs(b.angular_velocity[p]) * 0.5 *
                   std::sqrt(b.length[p] * b.length[p] + b.width[p] * b.width[p]);
      };
      const double closing =
          safety * std::min({seen_from(i, j), seen_from(j, i), fastest(i) + fastest(j)}) * dt;
      if (d.norm() > closing + 2.0 * margin_f * (b.width[i] + b.width[j])) continue;
      is_linked[i] = is_linked[j] = 1;
      if (closing > 0.25 * std::min(b.width[i], b.width[j])) {
        links[i].push_back(j), links[j].push_back(i);
      }
    }
  }
  BruteForcePlan plan;
  for (int i = 0; i < n; ++i)
    if (is_linked[i]) plan.linked.push_back(i);
  std::vector<int> seen(static_cast<std::size_t>(n), 0);
  auto& groups = plan.groups;
  for (int i = 0; i < n; ++i) {
    if (seen[i] || links[i].empty()) continue;
    std::vector<int> group, stack{i};
    seen[i] = 1;
    while (!stack.empty()) {
      const int k = stack.back();
      stack.pop_back();
      group.push_back(k);
      for (const int m : links[k])
        if (!seen[m]) seen[m] = 1, stack.push_back(m);
    }
    std::sort(group.begin(), group.end());
    groups.push_back(group);
  }
  return plan;  // groups in the order of their smallest member, as the planner's
}

TEST(ContactPlanner, GroupsAreTheComponentsOfTheLinksNeedingIntervalsOnRandomScenes) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  ContactPlanner planner;
  const BoundarySegments no_walls;
  int grouped_in_all = 0, linked_in_all = 0;
  for (int scene = 0; scene < 20; ++scene) {
    const double speed = scene % 2 ? 3.0 : 0.1, spin = scene % 2 ? 0.2 : 0.01;  // [m/s], [rad/s]
    BodySet bodies;
    for (int k = 0; k < 400; ++k) {
      bodies.add(BodySpec{.length = 2.0 + 10.0 * unit(rng),
                          .width = 0.2 + 0.6 * unit(rng),
                          .position = {300.0 * unit(rng), 300.0 * unit(rng)},
                          .angle = 6.283185307179586 * unit(rng),
                          .velocity = {speed * (unit(rng) - 0.5), speed * (unit(rng) - 0.5)},
                          .angular_velocity = spin * (unit(rng) - 0.5)});
    }
    const ContactConfig config;
    const ContactSchedule s = planner.plan(bodies, no_walls, 1.0, config);
    const BruteForcePlan expected = brute_force_plan(bodies, 1.0, config.allowed_overlap);
    EXPECT_EQ(s.at_end, expected.linked) << "scene " << scene;
    ASSERT_EQ(s.groups.size(), expected.groups.size()) << "scene " << scene;
    int grouped = 0;
    for (std::size_t g = 0; g < expected.groups.size(); ++g) {
      EXPECT_EQ(s.groups[g].bodies, expected.groups[g]) << "scene " << scene << ", group " << g;
      grouped += static_cast<int>(expected.groups[g].size());
    }
    EXPECT_EQ(static_cast<int>(s.free.size()) + grouped, bodies.size());
    grouped_in_all += grouped;
    linked_in_all += static_cast<int>(s.at_end.size());
  }
  EXPECT_GT(grouped_in_all, 0);              // the scenes do have groups
  EXPECT_GT(linked_in_all, grouped_in_all);  // and links of one interval
}

}  // namespace
}  // namespace flotsam
