// Verifies that a grounded log on a sloping bed stays put while mu_bed W' exceeds the downslope
// force W' |grad z_b| and slides when it does not, with the constant acceleration of Coulomb
// friction (spec 3.4, (M-5)):  a = W' (s - mu_bed) / (m_p + C_a m_f),  x(t) = a t^2 / 2.
// A log sliding on a flat bed stops after v_0^2 / (2 a), a = mu_bed W' / (m_p + C_a m_f), and
// then stays (friction stops a body, never reverses it).
// A sunken log (denser than water, fully under water) keeps W' = (m_p - m_f) g constant as it
// slides; the drag coefficient is set to zero so that friction and slope are all there is.
#include <gtest/gtest.h>

#include <cmath>

#include "bodies/analytic_flow.hpp"
#include "bodies/body_integrator.hpp"
#include "core/constants.hpp"

namespace flotsam {
namespace {

struct Slide {
  Vec2 position;
  BodyState state;
};

Slide slide_for(double slope, double seconds, double density, double depth) {
  // Bed z_b = -depth - slope x: falling towards +x, water surface at 0, depth `depth` at x = 0.
  const AnalyticFlow flow = still_water_on_slope(0.0, -depth, {-slope, 0.0});
  BodySet bodies;
  bodies.add(BodySpec{.density = density, .angle = pi / 2});
  ForceModel model;
  model.physics.drag_law = DragLaw::constant;
  model.physics.drag_coefficient = 0.0;
  model.physics.bed_friction = 0.6;
  BodyIntegrator integrator(model);
  const int steps = static_cast<int>(std::lround(seconds / 0.1));
  for (int n = 0; n < steps; ++n) integrator.advance(bodies, flow, n * 0.1, (n + 1) * 0.1);
  return {bodies.position[0], bodies.state[0]};
}

TEST(GroundedLogOnSlope, StaysPutWhileFrictionHoldsIt) {
  // Sunken log, s = 0.55 < mu = 0.6: not a micrometre of creep, bit for bit.
  const Slide sunk = slide_for(0.55, 20.0, 1200.0, 2.0);
  EXPECT_EQ(sunk.position, Vec2::Zero());
  EXPECT_EQ(sunk.state, BodyState::grounded);
  // Floating-density log stranded in 0.3 m of water (draft 0.59 m): the same criterion.
  const Slide stranded = slide_for(0.55, 20.0, 600.0, 0.3);
  EXPECT_EQ(stranded.position, Vec2::Zero());
  EXPECT_EQ(stranded.state, BodyState::grounded);
}

TEST(GroundedLogOnSlope, SlidesWithCoulombAccelerationWhenTheSlopeIsSteeper) {
  const double s = 0.65, mu = 0.6, t = 10.0;
  const double V = pi / 4 * 20;                       // [m^3]
  const double m_p = 1200 * V, m_f = 1000 * V;        // fully submerged
  const double W = (m_p - m_f) * 9.81;                // W' [N]
  const double a = W * (s - mu) / (m_p + 0.5 * m_f);  // [m/s^2]
  const Slide sunk = slide_for(s, t, 1200.0, 2.0);
  EXPECT_NEAR(sunk.position.x(), 0.5 * a * t * t, 1e-6 * 0.5 * a * t * t);
  EXPECT_EQ(sunk.position.y(), 0.0);
  std::printf("slid %.9f m, closed form %.9f m\n", sunk.position.x(), 0.5 * a * t * t);
}

TEST(GroundedLogOnSlope, ASlidingLogStopsAndStays) {
  const AnalyticFlow flow = still_water_on_slope(0.0, -2.0, Vec2::Zero());
  BodySet bodies;
  bodies.add(BodySpec{.density = 1200.0, .angle = pi / 2, .velocity = {1.0, 0.0}});
  ForceModel model;
  model.physics.drag_law = DragLaw::constant;
  model.physics.drag_coefficient = 0.0;
  const double V = pi / 4 * 20;
  const double a = 0.6 * 200 * V * 9.81 / (1200 * V + 0.5 * 1000 * V);  // [m/s^2]
  BodyIntegrator integrator(model);
  for (int n = 0; n < 30; ++n) integrator.advance(bodies, flow, n * 0.1, (n + 1) * 0.1);
  const double stop = 1.0 / (2 * a);  // v_0^2 / (2 a) [m]
  EXPECT_NEAR(bodies.position[0].x(), stop, 2e-3 * stop);
  EXPECT_EQ(bodies.velocity[0], Vec2::Zero());
  const Vec2 rest = bodies.position[0];
  for (int n = 30; n < 100; ++n) integrator.advance(bodies, flow, n * 0.1, (n + 1) * 0.1);
  EXPECT_EQ(bodies.position[0], rest);
  std::printf("stopped after %.6f m, closed form %.6f m\n", rest.x(), stop);
}

}  // namespace
}  // namespace flotsam
