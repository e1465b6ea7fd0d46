// Verifies that a floating body carried by a uniformly accelerating current accelerates with it,
// du_p/dt = du_f/dt, whatever the added-mass coefficient C_a: with m_f = m_p, (M-5) gives
// (m_p + C_a m_p) du_p/dt = (1 + C_a) m_p Du_f/Dt (Maxey & Riley 1983, the Froude-Krylov and
// added-mass terms). Exact solution u_p = u_0 + a t, x = x_0 + u_0 t + a t^2 / 2.
#include <gtest/gtest.h>

#include <cmath>

#include "bodies/analytic_flow.hpp"
#include "bodies/body_integrator.hpp"

namespace flotsam {
namespace {

TEST(BodyFollowsAcceleratingFlow, WhateverTheAddedMassCoefficient) {
  const Vec2 u0{0.3, -0.1}, a{0.02, 0.01};  // [m/s], [m/s^2]
  const AnalyticFlow flow = accelerating_flow(u0, a, 8.0);
  for (const double C_a : {0.0, 0.5, 1.0, 2.0}) {
    ForceModel model;  // Ganser drag, centre of pressure: both vanish at u_rel = 0
    model.physics.added_mass_coefficient = C_a;
    BodySet bodies;
    bodies.add(BodySpec{.position = {5, 5}, .angle = 0.7, .velocity = u0});
    BodyIntegrator integrator(model);
    for (int n = 0; n < 300; ++n) integrator.advance(bodies, flow, n * 0.1, (n + 1) * 0.1);
    const double t = 30.0;
    const Vec2 u_exact = u0 + a * t;
    const Vec2 x_exact = Vec2(5, 5) + u0 * t + 0.5 * a * t * t;
    EXPECT_LT((bodies.velocity[0] - u_exact).norm(), 1e-9 * u_exact.norm()) << "C_a " << C_a;
    EXPECT_LT((bodies.position[0] - x_exact).norm(), 1e-9 * x_exact.norm()) << "C_a " << C_a;
    EXPECT_NEAR(bodies.angle[0], 0.7, 1e-12);
  }
}

}  // namespace
}  // namespace flotsam
