// Verifies that a log lying across a simple shear flow u = (G y, 0) turns with the shear, in
// the sense of the fluid's own spin omega_f = -G/2, when drag is sampled at drag_points = 5
// slices along it (spec 3.2): the slice at s_k on the axis sees u_rel = G s_k sin(theta), and
// at theta = 90 deg the torque is T = -(1/N) (rho/2) C_d S_eff G|G| sum_k |s_k| s_k^2 with
// S_eff = d L. A single drag point at G sees no flow at all there and gives no torque.
#include <gtest/gtest.h>

#include <cmath>

#include "bodies/analytic_flow.hpp"
#include "bodies/body_integrator.hpp"
#include "bodies/body_motion.hpp"
#include "core/constants.hpp"

namespace flotsam {
namespace {

constexpr double G = 0.05;  // shear rate [1/s]

ForceModel shear_model(int drag_points, double C_r) {
  ForceModel model;
  model.physics.drag_law = DragLaw::constant;
  model.physics.drag_coefficient = 1.2;
  model.physics.drag_points = drag_points;
  model.physics.rotation_coefficient = C_r;
  return model;
}

TEST(LogTurnsWithShear, InitialTorqueOfFiveDragPointsAndNoneForOne) {
  const AnalyticFlow flow = shear_flow(0.0, G, 10.0);
  BodySet bodies;
  bodies.add(BodySpec{.angle = pi / 2});
  BodyStateVector y;
  y << 0, 0, pi / 2, 0, 0, 0;
  int hint = -1;
  const BodyStateVector one = body_derivative(bodies, 0, 0, y, flow, hint, shear_model(1, 0));
  EXPECT_EQ(one[5], 0.0);
  const BodyStateVector five = body_derivative(bodies, 0, 0, y, flow, hint, shear_model(5, 0));
  double sum = 0;  // sum |s_k| s_k^2 over s_k = -8, -4, 0, 4, 8 m
  for (const double s : {-8.0, -4.0, 0.0, 4.0, 8.0}) sum += std::abs(s) * s * s;
  const double S_eff = bodies.draft[0] * 20.0;
  const double T = -0.2 * 0.5 * 1000 * 1.2 * S_eff * G * G * sum;
  EXPECT_NEAR(five[5], T / bodies.inertia[0], 1e-12 * std::abs(T / bodies.inertia[0]));
  EXPECT_LT(five[5], 0.0);                             // the sense of omega_f = -G/2
  EXPECT_NEAR(five.segment<2>(3).norm(), 0.0, 1e-15);  // slice drags cancel: G stays put
}

TEST(LogTurnsWithShear, KeepsTurningInTheSenseOfTheFluidSpin) {
  const AnalyticFlow flow = shear_flow(0.0, G, 10.0);
  BodySet one_point, five_points;
  one_point.add(BodySpec{.angle = pi / 2});
  five_points.add(BodySpec{.angle = pi / 2});
  BodyIntegrator integrator_1(shear_model(1, 0.0)), integrator_5(shear_model(5, 1.0));
  bool monotonic = true;
  double previous = pi / 2;
  for (int n = 0; n < 600; ++n) {  // 60 s
    integrator_1.advance(one_point, flow, n * 0.1, (n + 1) * 0.1);
    integrator_5.advance(five_points, flow, n * 0.1, (n + 1) * 0.1);
    monotonic = monotonic && five_points.angle[0] < previous;
    previous = five_points.angle[0];
  }
  EXPECT_EQ(one_point.angle[0], pi / 2);  // no torque, no turn
  EXPECT_TRUE(monotonic);                 // clockwise, like omega_f
  EXPECT_LT(five_points.angle[0], pi / 2 - 0.3);
  EXPECT_LT(five_points.angular_velocity[0], 0.0);
  EXPECT_NEAR(five_points.position[0].norm(), 0.0, 1e-9);
  std::printf("angle after 60 s: %.4f rad, omega %.5f rad/s (omega_f = %.3f)\n",
              five_points.angle[0], five_points.angular_velocity[0], -G / 2);
}

}  // namespace
}  // namespace flotsam
