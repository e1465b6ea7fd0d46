// The force laws (spec 3.2, 3.3) against hand computations: S_eff, Ganser C_d, the centre of
// pressure (M-7), drag points in uniform flow, the rotation resistance (M-8), and (M-5) in an
// accelerating flow.
#include "bodies/hydrodynamic_forces.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "bodies/analytic_flow.hpp"
#include "bodies/body_motion.hpp"
#include "core/constants.hpp"

namespace flotsam {
namespace {

constexpr double deg = pi / 180.0;

TEST(EffectiveArea, LogEndOnBroadsideAndAt45Degrees) {
  const double L = 20, l = 1, h_s = 0.6;
  // alpha = 0: the wetted part of the end disc, phi_s pi l^2/4 with phi_s = h_s/l.
  EXPECT_NEAR(effective_area(Shape::log, L, l, h_s, 1.0, 0.0), 0.6 * pi / 4, 1e-14);
  // alpha = 90 deg: the wetted side, h_s L.
  EXPECT_NEAR(effective_area(Shape::log, L, l, h_s, 0.0, 1.0), 12.0, 1e-12);
  // 45 deg: 0.6 (pi/4) sqrt(1/2 + (80/pi)^2/2) = 8.49182... (hand computed)
  const double c = std::cos(45 * deg);
  EXPECT_NEAR(effective_area(Shape::log, L, l, h_s, c, c),
              0.6 * pi / 4 * std::sqrt(0.5 + 0.5 * std::pow(80 / pi, 2)), 1e-12);
  EXPECT_NEAR(effective_area(Shape::log, L, l, h_s, c, c), 8.4918215, 1e-6);
}

TEST(EffectiveArea, Box) {
  // h_s (L |sin| + l |cos|): 0.5 (4 sin 30 + 2 cos 30) = 1 + 0.866...
  EXPECT_NEAR(effective_area(Shape::box, 4, 2, 0.5, std::cos(30 * deg), std::sin(30 * deg)),
              1.0 + 0.5 * std::sqrt(3.0) * 1.0, 1e-14);
}

TEST(Incidence, FoldsIntoTheFirstQuadrant) {
  const Vec2 axis{1, 0};
  const Vec2 a = incidence(Vec2(-1, 1), axis);  // 135 deg from the axis folds to 45
  EXPECT_NEAR(a.x(), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(a.y(), std::sqrt(0.5), 1e-15);
  const Vec2 b = incidence(Vec2(0, -3), axis);  // broadside
  EXPECT_NEAR(b.x(), 0.0, 1e-15);
  EXPECT_NEAR(b.y(), 1.0, 1e-15);
}

TEST(Ganser, ShapeFactorsOfA20By1Log) {
  // Hand computed: V = pi/4 * 20 = 15.708 m^3, d_v = (6V/pi)^(1/3) = 30^(1/3) = 3.10723 m,
  // S = pi 20 + pi/2 = 64.403 m^2, Theta = pi d_v^2 / S = 0.470970, K2 = 10^(1.8148
  // (-log10 Theta)^0.5743) = 9.01731; broadside, fully wet: S_eff = 20 m^2, d_n = 5.04627 m,
  // K1 = (d_n/(3 d_v) + 2/(3 sqrt Theta))^-1 = 0.661036.
  BodySet bodies;
  bodies.add(BodySpec{});
  EXPECT_NEAR(bodies.equal_volume_diameter[0], 3.1072325059538586, 1e-12);
  EXPECT_NEAR(bodies.sphericity[0], 0.4709704315149413, 1e-12);
  EXPECT_NEAR(bodies.ganser_K2[0], 9.017310347936869, 1e-10);
  EXPECT_NEAR(ganser_K1_factor(std::sqrt(80 / pi), 3.1072325059538586, 0.4709704315149413),
              0.6610359353292378, 1e-12);
}

TEST(Ganser, DragCoefficientAtSeveralReynoldsNumbers) {
  // C_d = K2 [24/(R)(1 + 0.1118 R^0.6567) + 0.4305/(1 + 3305/R)], R = Re K1 K2, with the
  // factors above; values computed by hand (Python, double precision).
  const double K1 = 0.6610359353292378, K2 = 9.017310347936869;
  const struct {
    double Re, C_d;
  } cases[] = {{0.1, 391.96526599373885},
               {10, 9.646039699599614},
               {1000, 3.7572906309231358},
               {1e5, 4.112717637098558},
               {1e7, 3.9335571023019997}};
  for (const auto& c : cases)
    EXPECT_NEAR(ganser_drag_coefficient(c.Re, K1, K2), c.C_d, 1e-12 * c.C_d) << "Re " << c.Re;
  // Newton regime limit: C_d -> 0.4305 K2.
  EXPECT_NEAR(ganser_drag_coefficient(1e14, K1, K2), 0.4305 * K2, 1e-3);
}

TEST(CentreOfPressure, OffsetAt0And45And90Degrees) {
  BodySet bodies;
  bodies.add(BodySpec{});  // L = 20, l = 1: reach 0.1 L (1 - exp(-57)) = 2 m
  const double reach = bodies.pressure_reach[0];
  EXPECT_NEAR(reach, 2.0, 1e-14);
  EXPECT_NEAR(pressure_centre_offset(reach, 1.0), 2.0, 1e-14);
  EXPECT_NEAR(pressure_centre_offset(reach, std::cos(45 * deg)), 2.0 * std::pow(0.5, 1.5), 1e-14);
  EXPECT_NEAR(pressure_centre_offset(reach, std::cos(90 * deg)), 0.0, 1e-14);
}

/// A log held at rest at 20 deg in a uniform current: the drag acts upstream of G and turns the
/// log towards broadside, T = |GP| |F| sin(20 deg) > 0; drag_points 5 gives the same force and
/// torque in uniform flow.
TEST(DragOnBody, UpstreamCentreOfPressureTurnsTheLogBroadside) {
  BodySet bodies;
  BodySpec spec;
  spec.angle = 20 * deg;
  bodies.add(spec);
  const AnalyticFlow flow = uniform_flow({0.5, 0.0}, 10.0);
  ForceModel model;
  model.physics.drag_law = DragLaw::constant;
  int hint = -1;
  const FlowSample at_G = flow.sample(Vec2::Zero(), 0.0, hint);
  const BodyPose pose{Vec2::Zero(), bodies.axis(0), Vec2::Zero(), bodies.draft[0], at_G, hint};
  const Drag one = drag_on_body(bodies, 0, pose, 0.0, flow, model);
  const double S_eff =
      effective_area(Shape::log, 20, 1, bodies.draft[0], std::cos(20 * deg), std::sin(20 * deg));
  const double F = 0.5 * 1000 * 1.2 * S_eff * 0.25;  // (M-6) [N]
  EXPECT_NEAR(one.force.x(), F, 1e-9 * F);
  EXPECT_NEAR(one.force.y(), 0.0, 1e-9 * F);
  const double GP = 2.0 * std::pow(std::cos(20 * deg), 3);
  EXPECT_NEAR(one.torque, GP * F * std::sin(20 * deg), 1e-9 * F);
  EXPECT_GT(one.torque, 0.0);

  model.physics.drag_points = 5;
  const Drag five = drag_on_body(bodies, 0, pose, 0.0, flow, model);
  EXPECT_NEAR(five.force.x(), one.force.x(), 1e-12 * F);
  EXPECT_NEAR(five.torque, one.torque, 1e-11 * F);

  model.physics.center_of_pressure = false;
  EXPECT_NEAR(drag_on_body(bodies, 0, pose, 0.0, flow, model).torque, 0.0, 1e-11 * F);
}

TEST(RotationResistance, OpposesSpinRelativeToTheFluid) {
  // (M-8): -rho C_r h_s L^4/64 |w - w_f| (w - w_f) = -1000 * 1 * 0.5 * (160000/64) * 0.2 * 0.2
  EXPECT_NEAR(rotation_torque(1000, 1.0, 0.5, 20, 0.1, -0.1), -50000.0, 1e-9);
  EXPECT_EQ(rotation_torque(1000, 1.0, 0.5, 20, 0.3, 0.3), 0.0);
  Mat2 grad_u;
  grad_u << 0, 2, 0, 0;  // u = (2 y, 0): omega_f = -1
  EXPECT_EQ(fluid_spin(grad_u), -1.0);
}

/// (M-5) with u_p = u_f: no drag, and (m_p + C_a m_f) du_p/dt = (1 + C_a) m_f a with m_f = m_p
/// gives du_p/dt = a for any C_a.
TEST(BodyMotion, FloatingBodyAcceleratesWithTheFluidForAnyAddedMass) {
  BodySet bodies;
  bodies.add(BodySpec{});
  const Vec2 a{0.03, -0.01};
  const AnalyticFlow flow = accelerating_flow({0.5, 0.2}, a, 10.0);
  for (const double C_a : {0.0, 0.5, 1.0, 2.5}) {
    ForceModel model;
    model.physics.added_mass_coefficient = C_a;
    BodyStateVector y;
    y << 3, 4, 0.3, 0.5 + a.x() * 2, 0.2 + a.y() * 2, 0;  // at t = 2, moving with the water
    int hint = -1;
    BodyLoads loads;
    const BodyStateVector dy = body_derivative(bodies, 0, 2.0, y, flow, hint, model, &loads);
    EXPECT_NEAR(dy[3], a.x(), 1e-15) << "C_a " << C_a;
    EXPECT_NEAR(dy[4], a.y(), 1e-15) << "C_a " << C_a;
    EXPECT_FALSE(loads.grounded);
    // Reaction on the fluid: F_drag + C_a m_f (Du_f/Dt - du_p/dt) = 0 here.
    EXPECT_NEAR(loads.reaction.norm(), 0.0, 1e-9);
  }
}

}  // namespace
}  // namespace flotsam
