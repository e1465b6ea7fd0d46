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

/// A car as a box (4 m x 1.7 m x 1.5 m, 1,100 kg) resting on the bed, flow along it (end-on),
/// C_d = 1.2, mu_bed = 0.6: its draft is m_p / (rho L l) (spec 2); in water shallower than the
/// draft it displaces rho L l H, the drag sees the wetted frontal area H l (M-6), and the bed
/// holds it or lets it slide (spec 3.4); deeper, it floats and the drag sees d l.
struct CarLoads {
  BodyLoads loads;
  Vec2 acceleration;  // [m/s^2]
};

CarLoads car_in(double depth, double speed) {
  BodySet bodies;
  bodies.add(BodySpec{.shape = Shape::box,
                      .length = 4.0,
                      .width = 1.7,
                      .height = 1.5,
                      .density = 1100.0 / (4.0 * 1.7 * 1.5)});
  EXPECT_NEAR(bodies.draft[0], 1100.0 / (1000.0 * 4.0 * 1.7), 1e-15);  // 0.1618 m
  ForceModel model;
  model.physics.drag_law = DragLaw::constant;
  model.physics.drag_coefficient = 1.2;
  const AnalyticFlow flow = uniform_flow({speed, 0.0}, depth);
  BodyStateVector y = BodyStateVector::Zero();
  int hint = -1;
  CarLoads car;
  const BodyStateVector dy = body_derivative(bodies, 0, 0.0, y, flow, hint, model, &car.loads);
  car.acceleration = dy.segment<2>(3);
  return car;
}

TEST(BedContact, ACarInWaterShallowerThanItsDraftIsHeldByTheBed) {
  const CarLoads car = car_in(0.1, 1.0);
  const double drag = 0.5 * 1000.0 * 1.2 * (0.1 * 1.7) * 1.0;  // (M-6): 102 N
  EXPECT_TRUE(car.loads.grounded);
  EXPECT_NEAR(car.loads.drag.x(), drag, 1e-12 * drag);
  EXPECT_EQ(car.loads.drag.y(), 0.0);
  EXPECT_EQ(car.loads.bed, -car.loads.drag);  // held: 102 N < mu W' = 0.6 (1100 - 680) g
  EXPECT_EQ(car.acceleration, Vec2::Zero());
}

TEST(BedContact, ACarSlidesWhenTheDragExceedsTheFriction) {
  const CarLoads car = car_in(0.1, 6.0);
  const double m_f = 1000.0 * 4.0 * 1.7 * 0.1;                  // displaced water [kg]
  const double drag = 0.5 * 1000.0 * 1.2 * (0.1 * 1.7) * 36.0;  // 3672 N
  const double friction = 0.6 * (1100.0 - m_f) * 9.81;          // mu W' = 2472.12 N
  const double a = (drag - friction) / (1100.0 + 0.5 * m_f);    // (M-5)
  EXPECT_TRUE(car.loads.grounded);
  EXPECT_NEAR(car.loads.bed.x(), -friction, 1e-12 * friction);
  EXPECT_NEAR(car.acceleration.x(), a, 1e-12 * a);
  EXPECT_EQ(car.acceleration.y(), 0.0);
}

TEST(BedContact, ACarFloatsInWaterDeeperThanItsDraft) {
  const CarLoads car = car_in(0.2, 1.0);
  const double d = 1100.0 / 6800.0;                    // [m]
  const double drag = 0.5 * 1000.0 * 1.2 * (d * 1.7);  // wetted height d, not H
  EXPECT_FALSE(car.loads.grounded);
  EXPECT_EQ(car.loads.bed, Vec2::Zero());
  EXPECT_NEAR(car.loads.drag.x(), drag, 1e-12 * drag);
  EXPECT_NEAR(car.acceleration.x(), drag / (1.5 * 1100.0), 1e-12);  // m_f = m_p when floating
}

}  // namespace
}  // namespace flotsam
