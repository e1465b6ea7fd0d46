// Verifies that a log whose corner strikes another log away from its centre sets both spinning
// as the impulse (M-9) says, and that linear and angular momentum about a fixed point are
// conserved by the impact.
// Reference: spec 4.3 (M-9), (P-22) to (P-25); rigid-body impulse, e.g. Baraff (1997) notes.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/contact_world.hpp"

namespace flotsam {
namespace {

TEST(OffCentreImpact, SpinMatchesImpulseAndAngularMomentumIsConserved) {
  for (const double e : {0.0, 0.5, 1.0}) {
    SCOPED_TRACE(e);
    BodySet bodies;
    BodySpec log;
    log.length = 20.0;
    log.width = 1.0;
    log.position = {0.0, 0.0};  // B: at rest along x, top face y = 0.5
    bodies.add(log);
    // A: tilted nearly upright, its lowest corner 1 mm into B's top face at x ~ 5, falling.
    const double theta = 0.5 * 3.14159265358979 + 0.3;
    const Vec2 axis(std::cos(theta), std::sin(theta)), side = perp(axis);
    const Vec2 corner_offset = -10.0 * axis + 0.5 * side;  // lowest corner, from G_A
    const Vec2 corner(5.0, 0.5 - 0.001);
    log.position = corner - corner_offset;
    log.angle = theta;
    log.velocity = {0.0, -2.0};
    bodies.add(log);
    ASSERT_GT((bodies.position[1] - 10.0 * axis - 0.5 * side).y(), 0.6);  // other corner clear

    const double m = bodies.mass[0], I = bodies.inertia[0];
    const Vec2 G_a = bodies.position[1], G_b = bodies.position[0];
    ContactConfig config;
    config.restitution = e;
    config.friction = 0.0;
    ContactWorld world(config);
    world.step(bodies, BoundarySegments{}, 0.01);
    ASSERT_EQ(world.contacts().size(), 1u);
    ASSERT_EQ(world.contacts()[0].point_count, 1);  // vertex on edge

    // By hand, with A the falling log (body 1) and B the log at rest (body 0): n = (0, 1) from
    // B to A; M is the corner moved half the depth along n, so r x n = r.x; v_n = -2 m/s;
    // j = -(1 + e) v_n / (2/m + rA.x^2/I + rB.x^2/I).
    const double rA = corner.x() - G_a.x(), rB = corner.x() - G_b.x();
    const double j = (1 + e) * 2.0 / (2 / m + rA * rA / I + rB * rB / I);
    EXPECT_NEAR(bodies.velocity[1].y(), -2.0 + j / m, 1e-12);
    EXPECT_NEAR(bodies.velocity[0].y(), -j / m, 1e-12);
    EXPECT_NEAR(bodies.angular_velocity[1], rA * j / I, 1e-12);
    EXPECT_NEAR(bodies.angular_velocity[0], -rB * j / I, 1e-12);
    EXPECT_NEAR(bodies.velocity[1].x() + bodies.velocity[0].x(), 0.0, 1e-12);

    // Angular momentum about a fixed point O, with the positions at the impact.
    const Vec2 O(3.0, -7.0);
    const double L_before = m * cross(G_a - O, Vec2(0.0, -2.0));
    const double L_after = m * cross(G_a - O, bodies.velocity[1]) + I * bodies.angular_velocity[1] +
                           m * cross(G_b - O, bodies.velocity[0]) + I * bodies.angular_velocity[0];
    EXPECT_NEAR(L_after, L_before, 1e-12 * std::abs(L_before));
  }
}

}  // namespace
}  // namespace flotsam
