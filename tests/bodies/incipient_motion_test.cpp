// The threshold of sliding (spec 3.4, bodies/incipient_motion.hpp) against the closed form of a
// constant drag coefficient, and the balance it strikes with Ganser's.
#include "bodies/incipient_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/constants.hpp"

namespace flotsam {
namespace {

/// A small car as a box: 4.0 m x 1.7 m x 1.5 m, 1,100 kg (draft 1100 / (1000 * 6.8) = 0.162 m).
BodySet car() {
  BodySet bodies;
  bodies.add(BodySpec{.shape = Shape::box,
                      .length = 4.0,
                      .width = 1.7,
                      .height = 1.5,
                      .density = 1100.0 / (4.0 * 1.7 * 1.5)});
  return bodies;
}

ForceModel constant_drag(double C_d, double mu) {
  ForceModel model;
  model.physics.drag_law = DragLaw::constant;
  model.physics.drag_coefficient = C_d;
  model.physics.bed_friction = mu;
  return model;
}

TEST(IncipientMotion, RestingWeightIsTheWeightLessTheDisplacedWater) {
  const BodySet bodies = car();
  const ForceModel model;
  EXPECT_NEAR(resting_weight(bodies, 0, 0.0, model), 1100.0 * 9.81, 1e-9);
  EXPECT_NEAR(resting_weight(bodies, 0, 0.1, model), (1100.0 - 1000.0 * 6.8 * 0.1) * 9.81, 1e-9);
  EXPECT_EQ(resting_weight(bodies, 0, 0.17, model), 0.0);  // above the draft: floats
}

TEST(IncipientMotion, ConstantDragHasTheClosedForm) {
  const BodySet bodies = car();
  const double C_d = 1.2, mu = 0.5;
  const ForceModel model = constant_drag(C_d, mu);
  for (const double H : {0.02, 0.05, 0.1, 0.15, 0.16}) {
    for (const double alpha : {0.0, pi / 6, pi / 2}) {
      const double W = (1100.0 - 1000.0 * 6.8 * H) * 9.81;                   // W' [N]
      const double S = H * (4.0 * std::sin(alpha) + 1.7 * std::cos(alpha));  // (M-6) box
      for (const double F_other : {0.0, 0.1 * mu * W}) {
        const double exact = std::sqrt((mu * W - F_other) / (0.5 * 1000.0 * C_d * S));
        const double u_c = incipient_velocity(bodies, 0, {H, alpha, F_other}, model);
        EXPECT_NEAR(u_c, exact, 1e-12 * exact) << "H = " << H << ", alpha = " << alpha;
      }
    }
  }
}

TEST(IncipientMotion, GanserDragAtTheThresholdEqualsTheFriction) {
  const BodySet bodies = car();
  ForceModel model;  // Ganser
  model.physics.bed_friction = 0.5;
  const double H = 0.1;
  const double u_c = incipient_velocity(bodies, 0, {H, 0.0, 0.0}, model);
  const double S = 1.7 * H;  // end-on [m^2]
  const double drag = 0.5 * 1000.0 * drag_coefficient(bodies, 0, S, u_c, model) * S * u_c * u_c;
  const double friction = 0.5 * resting_weight(bodies, 0, H, model);
  EXPECT_NEAR(drag, friction, 1e-12 * friction);
  EXPECT_GT(u_c, 3.0);  // a car in 10 cm of water needs a fast current
  EXPECT_LT(u_c, 5.0);
}

TEST(IncipientMotion, FloatingDryAndPushedBodies) {
  const BodySet bodies = car();
  const ForceModel model = constant_drag(1.2, 0.5);
  EXPECT_EQ(incipient_velocity(bodies, 0, {0.2, 0.0, 0.0}, model), 0.0);  // floats
  EXPECT_EQ(incipient_velocity(bodies, 0, {0.0, 0.0, 0.0}, model),
            std::numeric_limits<double>::infinity());  // dry: no water to drag it
  const double mu_W = 0.5 * resting_weight(bodies, 0, 0.1, model);
  EXPECT_EQ(incipient_velocity(bodies, 0, {0.1, 0.0, 1.01 * mu_W}, model), 0.0);
}

}  // namespace
}  // namespace flotsam
