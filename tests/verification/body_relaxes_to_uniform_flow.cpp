// Verifies that a log released at rest broadside in a uniform current with a constant drag
// coefficient approaches the current's velocity as the closed-form solution of
// du/dt = k (U - u)^2, k = rho C_d S_eff / (2 (m_p + C_a m_f)) (M-5, M-6):
//   u(t) = k U^2 t / (1 + k U t),   x(t) = U t - ln(1 + k U t) / k.
#include <gtest/gtest.h>

#include <cmath>

#include "bodies/analytic_flow.hpp"
#include "bodies/body_integrator.hpp"
#include "core/constants.hpp"

namespace flotsam {
namespace {

TEST(BodyRelaxesToUniformFlow, FollowsTheClosedFormWithinHalfAPercent) {
  const double U = 0.5;  // [m/s]
  const AnalyticFlow flow = uniform_flow({U, 0.0}, 10.0);
  BodySet bodies;
  bodies.add(BodySpec{.angle = pi / 2});  // 20 m x 1 m log, broadside: alpha = 90 deg throughout
  ForceModel model;
  model.physics.drag_law = DragLaw::constant;
  model.physics.drag_coefficient = 1.2;
  const double m_p = bodies.mass[0];
  const double S_eff = bodies.draft[0] * bodies.length[0];  // (M-6) at alpha = 90 deg, h_s = d
  const double k = 0.5 * model.rho * 1.2 * S_eff / ((1.0 + 0.5) * m_p);  // [1/m]
  BodyIntegrator integrator(model);
  double worst_u = 0.0, worst_x = 0.0;  // relative errors
  for (int n = 0; n < 1200; ++n) {      // 120 s of 0.1 s flow steps
    const double t = (n + 1) * 0.1;
    integrator.advance(bodies, flow, n * 0.1, t);
    const double u = k * U * U * t / (1.0 + k * U * t);
    const double x = U * t - std::log(1.0 + k * U * t) / k;
    worst_u = std::max(worst_u, std::abs(bodies.velocity[0].x() - u) / u);
    worst_x = std::max(worst_x, std::abs(bodies.position[0].x() - x) / x);
  }
  EXPECT_LT(worst_u, 0.005);
  EXPECT_LT(worst_x, 0.005);
  EXPECT_EQ(bodies.velocity[0].y(), 0.0);
  EXPECT_EQ(bodies.angle[0], pi / 2);  // no torque broadside
  RecordProperty("max_relative_error_u", std::to_string(worst_u));
  std::printf("max relative error: u %.3e, x %.3e\n", worst_u, worst_x);
}

}  // namespace
}  // namespace flotsam
