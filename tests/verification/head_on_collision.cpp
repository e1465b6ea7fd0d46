// Verifies that two equal logs meeting end to end leave with the velocities of a 1D collision
// with restitution e: exchange for e = 1, a common velocity for e = 0, separation speed e times
// the approach speed, momentum conserved and kinetic energy never increased.
// Reference: Newton's law of restitution, (P-21) with the corrected impulse (M-9) of spec 4.3;
// for equal masses u_A' = (u_A + u_B)/2 - e (u_A - u_B)/2, u_B' = (u_A + u_B)/2 + e (u_A - u_B)/2.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/contact_world.hpp"

namespace flotsam {
namespace {

struct Outcome {
  Vec2 u_a, u_b;            // [m/s]
  double omega_a, omega_b;  // [rad/s]
  double mass;              // [kg]
  int points;               // contact points found
};

// Log A (left) at speed u_a and log B (right) at u_b along x, ends overlapping by 1 mm.
Outcome collide_end_to_end(double e, double u_a, double u_b) {
  BodySet bodies;
  BodySpec log;
  log.length = 20.0;
  log.width = 1.0;
  log.position = {-10.0 + 0.0005, 0.0};
  log.velocity = {u_a, 0.0};
  bodies.add(log);
  log.position = {10.0 - 0.0005, 0.0};
  log.velocity = {u_b, 0.0};
  bodies.add(log);
  ContactConfig config;
  config.restitution = e;
  ContactWorld world(config);
  world.step(bodies, BoundarySegments{}, 0.01);
  const int points = world.contacts().empty() ? 0 : world.contacts()[0].point_count;
  return {bodies.velocity[0],         bodies.velocity[1], bodies.angular_velocity[0],
          bodies.angular_velocity[1], bodies.mass[0],     points};
}

TEST(HeadOnCollision, ElasticLogsExchangeVelocities) {
  const Outcome o = collide_end_to_end(1.0, 2.0, -1.0);
  EXPECT_EQ(o.points, 2);  // edge on edge
  EXPECT_NEAR(o.u_a.x(), -1.0, 1e-12);
  EXPECT_NEAR(o.u_b.x(), 2.0, 1e-12);
  EXPECT_NEAR(o.u_a.y(), 0.0, 1e-12);
  EXPECT_NEAR(o.omega_a, 0.0, 1e-12);
  EXPECT_NEAR(o.omega_b, 0.0, 1e-12);
}

TEST(HeadOnCollision, PerfectlyInelasticLogsMoveTogether) {
  const Outcome o = collide_end_to_end(0.0, 2.0, -1.0);
  EXPECT_NEAR(o.u_a.x(), 0.5, 1e-12);
  EXPECT_NEAR(o.u_b.x(), 0.5, 1e-12);
}

TEST(HeadOnCollision, SeparationIsRestitutionTimesApproachAndMomentumAndEnergyHold) {
  const double u_a = 1.5, u_b = -0.75;  // [m/s]; approach speed 2.25
  for (const double e : {0.0, 0.3, 0.7, 1.0}) {
    SCOPED_TRACE(e);
    const Outcome o = collide_end_to_end(e, u_a, u_b);
    EXPECT_NEAR(o.u_b.x() - o.u_a.x(), e * (u_a - u_b), 1e-12);
    const double p_before = o.mass * (u_a + u_b), p_after = o.mass * (o.u_a.x() + o.u_b.x());
    EXPECT_LE(std::abs(p_after - p_before), 1e-12 * o.mass * (std::abs(u_a) + std::abs(u_b)));
    const double ke_before = 0.5 * o.mass * (u_a * u_a + u_b * u_b);
    const double ke_after = 0.5 * o.mass * (o.u_a.squaredNorm() + o.u_b.squaredNorm());
    // Lost energy for equal masses: (1 - e^2) m (u_a - u_b)^2 / 4.
    EXPECT_NEAR(ke_before - ke_after, (1 - e * e) * o.mass * std::pow(u_a - u_b, 2) / 4,
                1e-12 * ke_before);
    EXPECT_LE(ke_after, ke_before * (1 + 1e-14));
  }
}

TEST(HeadOnCollision, SeparatingLogsGetNoImpulse) {
  const Outcome o = collide_end_to_end(1.0, -1.0, 1.0);  // overlapping but moving apart
  EXPECT_EQ(o.u_a.x(), -1.0);
  EXPECT_EQ(o.u_b.x(), 1.0);
}

}  // namespace
}  // namespace flotsam
