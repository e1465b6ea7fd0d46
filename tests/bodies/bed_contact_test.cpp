// Bed contact (spec 3.4): effective weight, slope force, Coulomb friction with a static state.
#include "bodies/bed_contact.hpp"

#include <gtest/gtest.h>

#include "bodies/analytic_flow.hpp"
#include "bodies/body_motion.hpp"

namespace flotsam {
namespace {

TEST(BedContact, EffectiveWeightAndSlopeForce) {
  EXPECT_EQ(effective_weight(1000, 400, 10), 6000);
  EXPECT_EQ(effective_weight(400, 1000, 10), 0);  // buoyant: never negative
  const Vec2 F = slope_force(6000, Vec2(0.1, -0.2));
  EXPECT_EQ(F, Vec2(-600, 1200));  // down the slope
}

TEST(BedContact, HeldWhileTheOtherForcesAreBelowTheBound) {
  // mu W' = 0.5 * 1000 = 500 N; 300 N pushing: held exactly, F_bed = -F.
  const BedFriction f = bed_friction(Vec2::Zero(), 0.0, Vec2(300, 0), 100, 0.5, 1000, 8);
  EXPECT_EQ(f.force, Vec2(-300, 0));
  EXPECT_EQ(f.torque, -100);  // below the torque bound mu W' L/4 = 1000 N m
}

TEST(BedContact, StartsToSlideAboveTheBound) {
  const BedFriction f = bed_friction(Vec2::Zero(), 0.0, Vec2(0, 800), 3000, 0.5, 1000, 8);
  EXPECT_EQ(f.force, Vec2(0, -500));
  EXPECT_EQ(f.torque, -1000);
}

TEST(BedContact, KineticFrictionOpposesTheSlidingVelocity) {
  const BedFriction f = bed_friction(Vec2(3, 4), -2.0, Vec2(0, 0), 0, 0.5, 1000, 8);
  EXPECT_NEAR((f.force - Vec2(-300, -400)).norm(), 0.0, 1e-12);
  EXPECT_EQ(f.torque, 1000);
}

/// A grounded log in a current too weak to move it: (M-5) gives exactly zero acceleration.
TEST(BedContact, GroundedLogInAWeakCurrentDoesNotCreep) {
  BodySet bodies;
  bodies.add(BodySpec{});  // draft ~0.59 m
  const AnalyticFlow flow = uniform_flow({0.2, 0.0}, 0.3);
  ForceModel model;
  model.physics.drag_law = DragLaw::constant;
  BodyStateVector y;
  y << 0, 0, 1.0, 0, 0, 0;
  int hint = -1;
  BodyLoads loads;
  const BodyStateVector dy = body_derivative(bodies, 0, 0.0, y, flow, hint, model, &loads);
  EXPECT_TRUE(loads.grounded);
  EXPECT_EQ(dy.tail<3>().norm(), 0.0);  // no acceleration, no spin-up
  EXPECT_GT(loads.drag.x(), 0.0);       // the bed holds it against the drag
  EXPECT_NEAR((loads.bed + loads.drag + loads.fluid).norm(), 0.0, 1e-12 * loads.drag.norm());
}

/// The same on a side slope, drag and slope force at an angle: F + F_bed rounds to ~1e-16 |F|,
/// yet a held body's acceleration must be exactly zero (a residue would set it sliding).
TEST(BedContact, GroundedLogOnASideSlopeInACurrentHasExactlyZeroAcceleration) {
  BodySet bodies;
  bodies.add(BodySpec{});
  AnalyticFlowSpec spec;
  spec.velocity = {0.9, -0.17};
  spec.eta = 0.05;
  spec.bed_gradient = {-0.0023, -0.018};
  const AnalyticFlow flow(spec);
  ForceModel model;
  model.physics.bed_friction = 0.6;
  BodyStateVector y;
  y << 0, 0, 0.3, 0, 0, 0;
  int hint = -1;
  BodyLoads loads;
  const BodyStateVector dy = body_derivative(bodies, 0, 0.0, y, flow, hint, model, &loads);
  ASSERT_TRUE(loads.grounded);
  EXPECT_GT(loads.bed.norm(), 0.0);
  EXPECT_EQ(dy.tail<3>().norm(), 0.0);
}

}  // namespace
}  // namespace flotsam
