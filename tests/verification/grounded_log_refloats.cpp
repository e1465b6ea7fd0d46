// Verifies that a log stranded in shallow water refloats when the rising water's depth exceeds
// its draft (spec 2, 3.4): with eta = eta_0 + r t over a flat bed, the state turns from grounded
// to floating at t* = (d - H_0) / r, and a log held on the bed by friction against a weak
// current stays exactly in place while stranded and drifts off once afloat.
#include <gtest/gtest.h>

#include <cmath>

#include "bodies/analytic_flow.hpp"
#include "bodies/body_integrator.hpp"

namespace flotsam {
namespace {

TEST(GroundedLogRefloats, WhenTheDepthExceedsTheDraft) {
  const double H0 = 0.3, rate = 0.01;  // [m], [m/s]
  const AnalyticFlow flow = rising_water(H0, rate, 0.0, Vec2::Zero());
  BodySet bodies;
  bodies.add(BodySpec{});  // density 600: draft 0.594 m
  const double t_star = (bodies.draft[0] - H0) / rate;
  BodyIntegrator integrator(ForceModel{});
  for (int n = 0; n < 600; ++n) {
    const double t = (n + 1) * 0.1;
    integrator.advance(bodies, flow, n * 0.1, t);
    // The state is that of the start of the last sub-step: at most one flow step late.
    if (t < t_star) {
      EXPECT_EQ(bodies.state[0], BodyState::grounded) << "t = " << t;
    } else if (t > t_star + 0.1) {
      EXPECT_EQ(bodies.state[0], BodyState::floating) << "t = " << t;
    }
  }
}

TEST(GroundedLogRefloats, HeldByTheBedThenCarriedOff) {
  const AnalyticFlow flow = rising_water(0.3, 0.01, 0.0, Vec2(0.3, 0.0));
  BodySet bodies;
  bodies.add(BodySpec{.angle = 1.2});
  BodyIntegrator integrator(ForceModel{});
  for (int n = 0; n < 100; ++n) integrator.advance(bodies, flow, n * 0.1, (n + 1) * 0.1);
  EXPECT_EQ(bodies.position[0], Vec2::Zero());  // 10 s: stranded, held, not creeping
  EXPECT_EQ(bodies.angle[0], 1.2);
  for (int n = 100; n < 600; ++n) integrator.advance(bodies, flow, n * 0.1, (n + 1) * 0.1);
  EXPECT_EQ(bodies.state[0], BodyState::floating);
  EXPECT_GT(bodies.position[0].x(), 1.0);  // afloat and drifting with the current
  EXPECT_GT(bodies.velocity[0].x(), 0.1);
}

}  // namespace
}  // namespace flotsam
