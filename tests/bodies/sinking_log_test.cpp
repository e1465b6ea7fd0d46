// Logs denser than water aground in shallow water. A long trial step across the instant friction
// stops a log once carried a wildly wrong velocity into the state (the step was accepted whatever
// its error because it ended in the stop), and the drag then blew it up to NaN
// (rkf45_event_error_norm).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "bodies/analytic_flow.hpp"
#include "bodies/body_integrator.hpp"
#include "core/constants.hpp"

namespace flotsam {
namespace {

TEST(SinkingLog, ComesToRestOnAFlatBedWithinTheFrictionStoppingDistance) {
  // Still water 0.3 m deep on a flat bed, a log 3 m x 0.35 m of 1100 kg/m^3 launched at 1 m/s
  // spinning at 0.5 rad/s. Friction alone decelerates it at a = mu W' / (m_p + C_a m_f), the drag
  // of the still water only adds to that: it stops within v0^2 / (2 a) and v0 / a, then stays at
  // rest exactly (spec 3.4).
  const AnalyticFlow flow = still_water_on_slope(0.3, 0.0, {0.0, 0.0});
  for (const bool batch : {false, true}) {
    BodySet bodies;
    BodySpec s;
    s.shape = Shape::log;
    s.length = 3.0;
    s.width = 0.35;
    s.density = 1100.0;
    s.velocity = {1.0, 0.0};  // v0 [m/s]
    s.angular_velocity = 0.5;
    bodies.add(s);
    ForceModel model;
    const double m_f = model.rho * bodies.submerged_volume(0, 0.3);  // [kg]
    const double a = model.physics.bed_friction * (bodies.mass[0] - m_f) * model.g /
                     (bodies.mass[0] + model.physics.added_mass_coefficient * m_f);  // [m/s^2]
    const BodyIntegrator integrator(model, {.batch = batch});
    long steps = 0;
    for (int step = 0; step < 2 * std::ceil(1.0 / a) + 2; ++step)
      steps += integrator.advance(bodies, flow, 0.5 * step, 0.5 * (step + 1)).accepted;
    EXPECT_EQ(bodies.velocity[0], Vec2(0.0, 0.0)) << batch;
    EXPECT_EQ(bodies.angular_velocity[0], 0.0) << batch;
    EXPECT_EQ(bodies.state[0], BodyState::grounded);
    EXPECT_GT(bodies.position[0].x(), 0.0);
    EXPECT_LE(bodies.position[0].x(), 1.0 / (2 * a));
    EXPECT_NEAR(bodies.position[0].y(), 0.0, 1e-12);
    EXPECT_LE(steps, 1000);
  }
}

TEST(SinkingLog, RandomLogsAgroundInShallowSlopedFlowsStayFiniteAndBounded) {
  // 3 random shallow flows (0.1-0.5 m deep, bed slopes to 5 %), 8 logs each 0.2-0.5 m wide of
  // 1050-1200 kg/m^3, 3 s, both paths. The case seen blow up to 3000 m/s and then NaN within the
  // first 0.5 s step (flow 0, log 1). No log can outrun the water by much: the flow is below
  // 4 m/s here, the logs start below 1.5 m/s, so every speed stays below 10 m/s.
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0), u(-2.0, 2.0), g(-0.05, 0.05);
  for (int trial = 0; trial < 3; ++trial) {
    AnalyticFlowSpec spec;
    spec.velocity = {u(random), u(random)};
    spec.velocity_gradient << g(random), g(random), g(random), g(random);
    spec.acceleration = {0.1 * u(random), 0.1 * u(random)};
    spec.eta = 0.1 + 0.4 * unit(random);
    spec.eta_rate = 0.01 * u(random);
    spec.bed_gradient = {g(random), g(random)};
    const AnalyticFlow flow(spec);
    ForceModel model;
    model.physics.drag_law = unit(random) < 0.25 ? DragLaw::constant : DragLaw::ganser;
    BodySet bodies;
    for (int i = 0; i < 8; ++i) {
      BodySpec s;
      s.shape = Shape::log;
      s.length = 1.0 + 24.0 * unit(random);
      s.width = 0.2 + 0.3 * unit(random);
      s.density = 1050.0 + 150.0 * unit(random);
      s.position = {-5.0 + 10.0 * unit(random), -5.0 + 10.0 * unit(random)};
      s.angle = 2 * pi * unit(random);
      s.velocity = {2.0 * unit(random) - 1.0, 2.0 * unit(random) - 1.0};
      s.angular_velocity = 0.2 * unit(random) - 0.1;
      bodies.add(s);
    }
    for (const bool batch : {false, true}) {
      BodySet b = bodies;
      const BodyIntegrator integrator(model, {.batch = batch});
      for (int step = 0; step < 6; ++step) {
        integrator.advance(b, flow, 0.5 * step, 0.5 * (step + 1));
        for (int i = 0; i < b.size(); ++i) {
          ASSERT_TRUE(b.position[i].allFinite()) << trial << " " << batch << " " << i;
          ASSERT_TRUE(std::isfinite(b.angle[i])) << trial << " " << batch << " " << i;
          ASSERT_LT(b.velocity[i].norm(), 10.0) << trial << " " << batch << " " << i;
          ASSERT_LT(std::abs(b.angular_velocity[i]), 10.0) << trial << " " << batch << " " << i;
        }
      }
    }
  }
}

}  // namespace
}  // namespace flotsam
