// The body integrator (spec 3.5, 5): free bodies and contact groups with their intervals and the
// hook, counters, and determinism: the same seed gives the same run, bit for bit, with 1 and 2
// threads.
#include "bodies/body_integrator.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>
#include <vector>

#include "bodies/analytic_flow.hpp"
#include "bodies/release.hpp"

namespace flotsam {
namespace {

TEST(BodyIntegrator, AGroupIsSteppedInItsIntervalsWithTheHookAtCommonTimes) {
  BodySet bodies;
  bodies.add(BodySpec{.position = {0, 0}, .velocity = {10.0, 0.0}});  // l = 1: 1 m per 0.1 s
  bodies.add(BodySpec{.position = {0, 50}, .velocity = {10.0, 0.0}});
  bodies.add(BodySpec{.position = {0, 100}, .velocity = {10.0, 0.0}});
  const AnalyticFlow flow = uniform_flow({10.0, 0.0}, 5.0);
  BodyIntegrator integrator(ForceModel{});
  ContactSchedule schedule;
  schedule.groups.push_back({{0, 2}, 4});
  schedule.free = {1};
  schedule.at_end = {0, 1, 2};
  std::vector<double> times, lengths;
  std::vector<double> at_end;   // the lengths per body at the step's end
  std::vector<Vec2> free_body;  // body 1 when the hook is called: already at the step's end
  const IntegrationStats stats =
      integrator.advance(bodies, flow, 0.2, 0.3, schedule, [&](const auto& interval, auto& b) {
        times.push_back(interval.end);
        lengths.push_back(interval.length);
        free_body.push_back(b.position[1]);
        if (interval.lengths) {
          EXPECT_EQ(*interval.bodies, schedule.at_end);
          at_end = *interval.lengths;
        } else {
          EXPECT_EQ(*interval.bodies, schedule.groups[0].bodies);
        }
        EXPECT_EQ(b.position[0].x(), b.position[2].x());  // the group's bodies at a common time
      });
  EXPECT_EQ(stats.contact_intervals, 4);
  EXPECT_EQ(stats.grouped, 2);
  ASSERT_EQ(times.size(), 4u);
  EXPECT_NEAR(times[0], 0.225, 1e-15);
  EXPECT_NEAR(times[1], 0.25, 1e-15);
  EXPECT_NEAR(times[2], 0.275, 1e-15);
  EXPECT_EQ(times[3], 0.3);  // the flow step's end, exactly
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(lengths[k], 0.025, 1e-15);
  EXPECT_NEAR(lengths[3], 0.1, 1e-15);  // the step's end: the free body came the whole step,
  ASSERT_EQ(at_end.size(), 3u);         // the group's bodies its last interval
  EXPECT_NEAR(at_end[0], 0.025, 1e-15);
  EXPECT_NEAR(at_end[1], 0.1, 1e-15);
  EXPECT_NEAR(at_end[2], 0.025, 1e-15);
  for (const Vec2& x : free_body) EXPECT_NEAR(x.x(), 1.0, 1e-12);
  // Every body is carried at the flow speed: exactly 1 m further.
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(bodies.position[i].x(), 1.0, 1e-12);
  // The free body crosses the step in one sub-step (its forces are zero); the group's bodies
  // take one per interval.
  EXPECT_EQ(stats.accepted, 1 + 2 * 4);
}

TEST(BodyIntegrator, WithoutAHookOneIntervalAndGoneBodiesStay) {
  BodySet bodies;
  bodies.add(BodySpec{.velocity = {1.0, 0.0}});
  bodies.add(BodySpec{.position = {0, 10}, .velocity = {1.0, 0.0}});
  bodies.state[1] = BodyState::gone;
  const AnalyticFlow flow = uniform_flow({1.0, 0.0}, 5.0);
  const IntegrationStats stats = BodyIntegrator(ForceModel{}).advance(bodies, flow, 0.0, 0.1);
  EXPECT_EQ(stats.contact_intervals, 1);
  EXPECT_EQ(bodies.position[1], Vec2(0, 10));
  EXPECT_NEAR(bodies.position[0].x(), 0.1, 1e-14);
}

/// A state hash: the bytes of every state array.
std::vector<unsigned char> snapshot(const BodySet& b) {
  std::vector<unsigned char> bytes;
  const auto append = [&](const auto& v) {
    const auto* p = reinterpret_cast<const unsigned char*>(v.data());
    bytes.insert(bytes.end(), p, p + v.size() * sizeof(v[0]));
  };
  append(b.position);
  append(b.angle);
  append(b.velocity);
  append(b.angular_velocity);
  append(b.state);
  append(b.step_size);
  append(b.drag_force);
  append(b.torque);
  return bytes;
}

std::vector<unsigned char> seeded_run(int threads) {
  omp_set_num_threads(threads);
  AnalyticFlowSpec spec;  // a rotating, straining, accelerating current over a slope
  spec.velocity = {0.6, 0.1};
  spec.velocity_gradient << 0.002, 0.004, -0.001, -0.002;
  spec.acceleration = {0.001, 0.0};
  spec.eta = 3.0;
  spec.bed_gradient = {0.004, 0.0};  // shallower downstream: some logs ground
  const AnalyticFlow flow(spec);
  Release r;
  r.line_start = {0, 0};
  r.line_end = {0, 6000};  // long enough for 600 logs of up to 20 m clear of one another
  r.end_time = 100;
  r.rate = 9000;  // 150 per second: 600 bodies, enough for the parallel loop
  r.length_min = 4, r.length_max = 20;
  r.width_min = 0.3, r.width_max = 1.2;
  r.density_min = 400, r.density_max = 900;
  r.seed = 2024;
  Releaser releaser({r}, PlacementCheck{});
  ForceModel model;
  model.physics.drag_points = 3;
  BodyIntegrator integrator(model);
  BodySet bodies;
  for (int n = 0; n < 40; ++n) {
    releaser.release(bodies, flow, n * 0.1, (n + 1) * 0.1);
    integrator.advance(bodies, flow, n * 0.1, (n + 1) * 0.1);
  }
  EXPECT_EQ(bodies.size(), 600);
  return snapshot(bodies);
}

/// A log grounded in a thin film on a side slope, held by the bed against drag and slope: it
/// stays exactly where it is, and the integrator crosses each flow step in a few sub-steps
/// (a stick-slip chatter at round-off speeds took ~10^4 sub-steps per second).
TEST(BodyIntegrator, HeldGroundedLogStaysExactlyAtRestInFewSubSteps) {
  AnalyticFlowSpec spec;
  spec.velocity = {0.9, -0.17};
  spec.eta = 0.05;  // [m] a film far below the log's draft
  spec.bed_gradient = {-0.0023, -0.018};
  const AnalyticFlow flow(spec);
  ForceModel model;
  model.physics.bed_friction = 0.6;
  BodySet bodies;
  BodySpec log;
  log.position = {0.0, 0.0};
  log.angle = 0.3;
  bodies.add(log);
  const BodyIntegrator integrator(model);
  IntegrationStats stats;
  for (int n = 0; n < 10; ++n) {
    const IntegrationStats s = integrator.advance(bodies, flow, n, n + 1.0);
    stats.accepted += s.accepted;
    stats.rejected += s.rejected;
  }
  EXPECT_EQ(bodies.state[0], BodyState::grounded);
  EXPECT_EQ(bodies.position[0], Vec2(0.0, 0.0));
  EXPECT_EQ(bodies.angle[0], 0.3);
  EXPECT_EQ(bodies.velocity[0], Vec2::Zero());
  EXPECT_LE(stats.accepted, 10);  // one sub-step per flow step
  EXPECT_EQ(stats.rejected, 0);
}

TEST(BodyIntegrator, SameSeedSameRunBitForBitWithOneAndTwoThreads) {
  const int before = omp_get_max_threads();
  const std::vector<unsigned char> one = seeded_run(1);
  const std::vector<unsigned char> two = seeded_run(2);
  omp_set_num_threads(before);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size()), 0);
}

}  // namespace
}  // namespace flotsam
