// Verifies that a log striking a straight bank at an angle, or a circular bridge pier, leaves
// with the normal velocity reversed and scaled by e and the tangential velocity kept
// (frictionless contact), for e = 0 and e = 1.
// Reference: spec 4.3 (M-9) with a wall of infinite mass (P-24): u' = u - (1 + e)(u . n) n.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/contact_world.hpp"

namespace flotsam {
namespace {

ContactConfig frictionless(double e) {
  ContactConfig config;
  config.restitution = e;
  config.friction = 0.0;
  return config;
}

TEST(LogAgainstWall, ReflectsOffAStraightBankAtAnAngle) {
  const double phi = 0.4;  // [rad] bank direction
  const Vec2 t(std::cos(phi), std::sin(phi)), n = perp(t);
  BoundarySegments walls;
  walls.add_segment(-50.0 * t, 50.0 * t, 0);  // water on the left, normal n
  walls.build_grid();
  for (const double e : {0.0, 1.0}) {
    SCOPED_TRACE(e);
    BodySet bodies;
    BodySpec log;
    log.length = 10.0;
    log.width = 0.5;
    log.angle = phi;                              // flat against the bank
    log.position = (0.25 - 0.001) * n + 3.0 * t;  // 1 mm into it
    const Vec2 u = 1.5 * t - 2.0 * n;             // [m/s] approaching at an angle
    log.velocity = u;
    bodies.add(log);
    ContactWorld world(frictionless(e));
    world.step(bodies, walls, 0.01);
    ASSERT_EQ(world.contacts().size(), 1u);
    EXPECT_EQ(world.contacts()[0].point_count, 2);  // edge on edge
    const Vec2 expected = u - (1 + e) * u.dot(n) * n;
    EXPECT_NEAR((bodies.velocity[0] - expected).norm(), 0.0, 1e-12);
    EXPECT_NEAR(bodies.angular_velocity[0], 0.0, 1e-12);
    EXPECT_GE(bodies.position[0].dot(n), 0.25 - 0.001);  // pushed out, not further in
  }
}

TEST(LogAgainstPier, ReflectsOffACircularPier) {
  // Pier of radius 2 m at the origin as a 64-gon with a vertex at (-2, 0); a log lying across
  // the flow (along y) hits it broadside, its face normal through the pier's centre.
  BoundarySegments walls;
  walls.add_circle_hole({0.0, 0.0}, 2.0, 64, 0);
  walls.build_grid();
  for (const double e : {0.0, 1.0}) {
    SCOPED_TRACE(e);
    BodySet bodies;
    BodySpec log;
    log.length = 10.0;
    log.width = 0.5;
    log.angle = 0.5 * 3.14159265358979323846;
    log.position = {-2.0 - 0.25 + 0.001, 0.0};
    const Vec2 u(1.2, 0.4);  // [m/s] into the pier and along its face
    log.velocity = u;
    bodies.add(log);
    ContactWorld world(frictionless(e));
    world.step(bodies, walls, 0.01);
    ASSERT_FALSE(world.contacts().empty());
    // n = (-1, 0) from the pier to the log: u' = (-e u_x, u_y).
    EXPECT_NEAR(bodies.velocity[0].x(), -e * u.x(), 1e-12);
    EXPECT_NEAR(bodies.velocity[0].y(), u.y(), 1e-12);
    EXPECT_NEAR(bodies.angular_velocity[0], 0.0, 1e-12);
    const ContactReport report = world.report(walls, bodies.size());
    EXPECT_EQ(report.count_touching(0), 1);
  }
}

TEST(LogAgainstPier, EndOnImpactOnTheRoundFaceReflectsAlongTheRadius) {
  // A log along x moving +x strikes the pier end first, at height y = 0: the pier's vertex at
  // (-2, 0) meets the log's end face in its middle, normal (-1, 0) through both centres.
  BoundarySegments walls;
  walls.add_circle_hole({0.0, 0.0}, 2.0, 64, 0);
  walls.build_grid();
  for (const double e : {0.0, 1.0}) {
    SCOPED_TRACE(e);
    BodySet bodies;
    BodySpec log;
    log.length = 10.0;
    log.width = 0.5;
    log.position = {-2.0 - 5.0 + 0.001, 0.0};
    log.velocity = {2.0, 0.0};
    bodies.add(log);
    ContactWorld world(frictionless(e));
    world.step(bodies, walls, 0.01);
    EXPECT_NEAR(bodies.velocity[0].x(), -e * 2.0, 1e-12);
    EXPECT_NEAR(bodies.velocity[0].y(), 0.0, 1e-12);
    EXPECT_NEAR(bodies.angular_velocity[0], 0.0, 1e-12);
  }
}

}  // namespace
}  // namespace flotsam
