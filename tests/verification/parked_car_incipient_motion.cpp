// Verifies that a parked car starts to move when and only when the drag exceeds the bed friction
// (spec 3.4, (M-5), (M-6)). The car is a box 4.0 m x 1.7 m x 1.5 m of 1,100 kg resting on a flat
// bed, mu_bed = 0.5. Reference: the analytic balance at the onset,
//
//   1/2 rho C_d S_eff u^2 + (1 + C_a) m_f du_f/dt = mu_bed W',   W' = (m_p - m_f) g,
//   m_f = rho L l H,  S_eff = H l (end-on) or H L (broadside),
//
// solved by bodies/incipient_motion.hpp (unit-tested against its closed form):
//   * a current speeding up, u_f = a t, in 0.1 m of water, Ganser's C_d: the car stays exactly
//     where it was parked until t* = u_c / a, then slides; onset within 2 % of t*;
//   * water rising at r under a steady 1 m/s current, constant C_d: it starts at the depth
//     H* = mu m_p g / (1/2 rho C_d L u^2 + mu rho L l g) (broadside), before it floats;
//   * a steady current 1 % under u_c holds it for ten minutes, 1 % over moves it.
// IncipientMotionTable prints the table of docs/validation.md ("A parked car").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "bodies/analytic_flow.hpp"
#include "bodies/body_integrator.hpp"
#include "bodies/incipient_motion.hpp"
#include "core/constants.hpp"

namespace flotsam {
namespace {

constexpr double car_mass = 1100.0;                 // m_p [kg]
constexpr double car_volume = 4.0 * 1.7 * 1.5;      // L l b [m^3]
constexpr double rho = 1000.0, g = 9.81, mu = 0.5;  // [kg m^-3], [m s^-2], [-]
constexpr double flow_step = 0.1;                   // [s]

BodySpec parked_car(double angle, double density = car_mass / car_volume) {
  return BodySpec{.shape = Shape::box,
                  .length = 4.0,
                  .width = 1.7,
                  .height = 1.5,
                  .density = density,
                  .angle = angle};
}

ForceModel model_with(DragLaw law) {
  ForceModel model;
  model.physics.drag_law = law;
  model.physics.drag_coefficient = 1.2;  // used by DragLaw::constant only
  model.physics.bed_friction = mu;
  return model;
}

struct Onset {
  double time = NAN;   // end of the first flow step in which the car moved [s]
  double moved = 0.0;  // x_G 10 s after the onset [m]
  BodyState state = BodyState::grounded;
};

/// Runs the car in `flow` until it has moved and 10 s more, or until t_end.
Onset watch(const AnalyticFlow& flow, const BodySpec& car, const ForceModel& model, double t_end) {
  BodySet bodies;
  bodies.add(car);
  const BodyIntegrator integrator(model);
  Onset onset;
  const int steps = static_cast<int>(std::lround(t_end / flow_step));
  for (int n = 0; n < steps; ++n) {
    const double t1 = (n + 1) * flow_step;
    integrator.advance(bodies, flow, n * flow_step, t1);
    const bool still = bodies.position[0] == car.position && bodies.angle[0] == car.angle &&
                       bodies.velocity[0] == Vec2::Zero();
    if (std::isnan(onset.time)) {
      if (!still) onset.time = t1;
    } else if (t1 >= onset.time + 10.0 - 1e-9) {
      break;
    }
  }
  onset.moved = bodies.position[0].x();
  onset.state = bodies.state[0];
  return onset;
}

TEST(ParkedCarIncipientMotion, StartsWhenASpeedingCurrentsDragExceedsTheFriction) {
  const double H = 0.1, a = 0.02;  // [m], [m/s^2]
  const ForceModel model = model_with(DragLaw::ganser);
  BodySet car;
  car.add(parked_car(0.0));
  const double m_f = rho * car.submerged_volume(0, H);                            // [kg]
  const double F_accel = (1.0 + model.physics.added_mass_coefficient) * m_f * a;  // (M-5) [N]
  const double u_c = incipient_velocity(car, 0, {H, 0.0, F_accel}, model);
  const double t_star = u_c / a;  // [s]
  const AnalyticFlow flow = accelerating_flow(Vec2::Zero(), {a, 0.0}, H);
  const Onset onset = watch(flow, parked_car(0.0), model, 2.0 * t_star);
  ASSERT_FALSE(std::isnan(onset.time)) << "the car never moved";
  EXPECT_GE(onset.time, t_star * (1.0 - 1e-12));  // nothing moved in a step that ended before t*
  EXPECT_NEAR(onset.time, t_star, 0.02 * t_star);
  EXPECT_GT(onset.moved, 0.0);  // and then slides downstream
  EXPECT_EQ(onset.state, BodyState::grounded);
  std::printf(
      "speeding current: u_c = %.4f m/s, t* = %.3f s, moved in the step ending %.3f s "
      "(%+.3f %%), %.3f m 10 s later\n",
      u_c, t_star, onset.time, 100.0 * (onset.time - t_star) / t_star, onset.moved);
}

TEST(ParkedCarIncipientMotion, StartsInRisingWaterAtTheClosedFormDepth) {
  const double H0 = 0.05, r = 1e-3, u = 1.0;  // [m], [m/s], [m/s]
  const ForceModel model = model_with(DragLaw::constant);
  const double C_d = model.physics.drag_coefficient;
  const double H_star =
      mu * car_mass * g / (0.5 * rho * C_d * 4.0 * u * u + mu * rho * 4.0 * 1.7 * g);  // [m]
  const double t_star = (H_star - H0) / r;                                             // [s]
  BodySet car;
  car.add(parked_car(pi / 2));
  ASSERT_LT(H_star, car.draft[0]);  // it slides before it floats
  // The car lies across the current (along y): alpha = pi/2 from its long axis.
  EXPECT_NEAR(incipient_velocity(car, 0, {H_star, pi / 2, 0.0}, model), u, 1e-12);
  const AnalyticFlow flow = rising_water(H0, r, 0.0, {u, 0.0});
  const Onset onset = watch(flow, parked_car(pi / 2), model, 2.0 * t_star);
  ASSERT_FALSE(std::isnan(onset.time)) << "the car never moved";
  EXPECT_GE(onset.time, t_star * (1.0 - 1e-12));
  EXPECT_NEAR(onset.time, t_star, 0.02 * t_star);
  EXPECT_GT(onset.moved, 0.0);
  std::printf(
      "rising water: H* = %.5f m (draft %.5f m), t* = %.3f s, moved in the step ending "
      "%.3f s (%+.3f %%)\n",
      H_star, car.draft[0], t_star, onset.time, 100.0 * (onset.time - t_star) / t_star);
}

TEST(ParkedCarIncipientMotion, HeldOnePercentUnderTheThresholdAndMovedOnePercentOver) {
  const double H = 0.1;  // [m]
  const ForceModel model = model_with(DragLaw::ganser);
  BodySet car;
  car.add(parked_car(0.0));
  const double u_c = incipient_velocity(car, 0, {H, 0.0, 0.0}, model);
  const Onset under = watch(uniform_flow({0.99 * u_c, 0.0}, H), parked_car(0.0), model, 600.0);
  EXPECT_TRUE(std::isnan(under.time)) << "moved at " << under.time << " s";
  EXPECT_EQ(under.moved, 0.0);
  const Onset over = watch(uniform_flow({1.01 * u_c, 0.0}, H), parked_car(0.0), model, 600.0);
  EXPECT_EQ(over.time, flow_step);  // in the first step
  EXPECT_GT(over.moved, 0.1);       // [m] in 10 s
}

// The incipient-motion table of docs/validation.md: u_c(H) of the car in a steady current, with
// its true mass (1,100 kg: draft 0.162 m) and with the effective density 300 kg/m^3 that makes it
// float at 0.45 m, for mu_bed = 0.25, 0.5, 0.75, flow end-on (along the car) and broadside.
TEST(ParkedCarIncipientMotion, IncipientMotionTable) {
  for (const double density : {car_mass / car_volume, 300.0}) {
    BodySet car;
    car.add(parked_car(0.0, density));
    ForceModel model = model_with(DragLaw::ganser);
    std::printf(
        "car %.0f kg (density %.1f kg/m^3, draft %.3f m), Ganser C_d %.3f at 2 m/s "
        "end-on in 0.1 m\n",
        car.mass[0], density, car.draft[0], drag_coefficient(car, 0, 0.17, 2.0, model));
    std::printf(
        "| H [m] | u_c end-on, mu 0.25 | mu 0.5 | mu 0.75 | broadside, mu 0.5 | H u_c "
        "(end-on, 0.5) [m^2/s] |\n");
    double previous = INFINITY;
    const double row = car.draft[0] < 0.2 ? 0.025 : 0.05;  // [m]
    for (int k = 1; row * k < car.draft[0] + row; ++k) {
      const double H = row * k;  // [m]
      double u_c[3];
      for (int j = 0; j < 3; ++j) {
        model.physics.bed_friction = 0.25 * (j + 1);
        u_c[j] = incipient_velocity(car, 0, {H, 0.0, 0.0}, model);
      }
      model.physics.bed_friction = 0.5;
      const double broadside = incipient_velocity(car, 0, {H, pi / 2, 0.0}, model);
      EXPECT_EQ(u_c[1] == 0.0, H > car.draft[0]);  // zero exactly when it floats
      if (H > car.draft[0]) {
        std::printf("| %.3f | floats | floats | floats | floats | 0 |\n", H);
        break;
      }
      std::printf("| %.3f | %.2f | %.2f | %.2f | %.2f | %.2f |\n", H, u_c[0], u_c[1], u_c[2],
                  broadside, H * u_c[1]);
      EXPECT_LT(u_c[0], u_c[1]);  // more friction, faster current needed
      EXPECT_LT(u_c[1], u_c[2]);
      EXPECT_LT(broadside, u_c[1]);  // the long side catches more of the current
      EXPECT_LT(u_c[1], previous);   // deeper water: more drag, less weight on the bed
      previous = u_c[1];
    }
  }
}

}  // namespace
}  // namespace flotsam
