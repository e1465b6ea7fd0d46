// The batch path (body_batch.hpp, batch_integration.hpp) against the scalar one
// (hydrodynamic_forces.hpp, body_motion.hpp, BodyIntegrator with batch = false) over many random
// bodies, states and flows. The two do the same operations in the same order except Ganser's
// R^0.6567, branch_free_pow instead of std::exp(0.6567 std::log(R)), within 1.2e-14 relative
// (tests/core/branch_free_math_test.cpp): C_d and so the drag differ by at most that, and the
// derivative by that times the drag over the mass. Tolerances are 4x those bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "bodies/analytic_flow.hpp"
#include "bodies/batch_integration.hpp"
#include "bodies/body_integrator.hpp"
#include "core/constants.hpp"

namespace flotsam {
namespace {

constexpr double pow_error = 1.2e-14;  // [-] branch_free_pow against exp(p log R)
constexpr double tolerance = 4 * pow_error;

/// A random flow of the analytic family: velocity, gradient, acceleration, depth from 0.2 m to
/// 5 m (logs aground and afloat), a sloping bed; a domain edge at x = 60 m (some bodies outside).
AnalyticFlow random_flow(std::mt19937_64& random) {
  std::uniform_real_distribution<double> u(-2.0, 2.0), g(-0.05, 0.05), eta(0.2, 5.0);
  AnalyticFlowSpec spec;
  spec.velocity = {u(random), u(random)};
  spec.velocity_gradient << g(random), g(random), g(random), g(random);
  spec.acceleration = {0.1 * u(random), 0.1 * u(random)};
  spec.eta = eta(random);
  spec.eta_rate = 0.01 * u(random);
  spec.bed_gradient = {0.01 * g(random), 0.01 * g(random)};
  spec.domain_max = {60.0, 1e9};
  return AnalyticFlow(spec);
}

/// Random logs and boxes, lighter and denser than water (only lighter: `afloat`).
BodySet random_bodies(std::mt19937_64& random, int n, bool afloat = false) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  BodySet bodies;
  for (int i = 0; i < n; ++i) {
    BodySpec s;
    s.shape = unit(random) < 0.7 ? Shape::log : Shape::box;
    s.length = 1.0 + 24.0 * unit(random);
    s.width = 0.2 + 1.3 * unit(random);
    s.height = 0.2 + 1.0 * unit(random);
    s.density = 300.0 + (afloat ? 600.0 : 900.0) * unit(random);
    s.position = {-50.0 + 120.0 * unit(random), -50.0 + 100.0 * unit(random)};
    s.angle = 2 * pi * unit(random);
    s.velocity = {2.0 * unit(random) - 1.0, 2.0 * unit(random) - 1.0};
    s.angular_velocity = 0.2 * unit(random) - 0.1;
    bodies.add(s);
  }
  return bodies;
}

ForceModel random_model(std::mt19937_64& random) {
  std::uniform_int_distribution<int> choice(0, 3), points(1, 5);
  ForceModel model;
  model.physics.drag_law = choice(random) == 0 ? DragLaw::constant : DragLaw::ganser;
  model.physics.center_of_pressure = choice(random) != 0;
  model.physics.drag_points = choice(random) == 0 ? points(random) : 1;
  return model;
}

TEST(BodyBatch, DerivativeAndLoadsAgreeWithTheScalarLawsOverRandomBodiesAndFlows) {
  std::mt19937_64 random(2024);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0, grounded = 0, outside = 0, slices = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const AnalyticFlow flow = random_flow(random);
    const ForceModel model = random_model(random);
    const BodySet bodies = random_bodies(random, batch_width);
    int list[batch_width], hints[batch_width];
    Lanes t;
    BatchVector y{}, dy{};
    BodyLoads loads[batch_width];
    for (int k = 0; k < batch_width; ++k) {
      list[k] = k;
      hints[k] = -1;
      t[k] = 10.0 * unit(random);
      const BodyStateVector y_k = body_state(bodies, k);
      for (int c = 0; c < 6; ++c) y.c[c][k] = y_k[c];
      y.c[2][k] += 0.1 * unit(random) - 0.05;  // off the axis reference, near and far
    }
    const int n = 1 + trial % batch_width;  // partly filled batches too
    batch_derivative(bodies, list, n, flow, model, t, y, hints, dy, loads);
    for (int k = 0; k < n; ++k) {
      BodyStateVector y_k;
      for (int c = 0; c < 6; ++c) y_k[c] = y.c[c][k];
      const AxisReference reference(bodies.angle[k]);
      BodyLoads expected;
      int hint = -1;
      const BodyStateVector dy_k =
          body_derivative(bodies, k, t[k], y_k, flow, hint, model, &expected, &reference);
      const double m = bodies.mass[k], I = bodies.inertia[k], L = bodies.length[k];
      const double force_scale =
          expected.drag.norm() + expected.fluid.norm() + expected.bed.norm() + 1e-300;  // [N]
      EXPECT_EQ(loads[k].outside, expected.outside);
      EXPECT_EQ(loads[k].grounded, expected.grounded);
      EXPECT_LE((loads[k].drag - expected.drag).norm(), tolerance * expected.drag.norm());
      EXPECT_LE((loads[k].reaction - expected.reaction).norm(), tolerance * force_scale);
      EXPECT_LE((loads[k].bed - expected.bed).norm(), tolerance * force_scale);
      EXPECT_LE(std::abs(loads[k].torque - expected.torque), tolerance * force_scale * L);
      for (int c = 0; c < 3; ++c) EXPECT_EQ(dy.c[c][k], dy_k[c]);
      for (int c = 3; c < 5; ++c)
        EXPECT_LE(std::abs(dy.c[c][k] - dy_k[c]), tolerance * force_scale / m) << c;
      EXPECT_LE(std::abs(dy.c[5][k] - dy_k[5]), tolerance * force_scale * L / I);
      ++compared;
      grounded += expected.grounded;
      outside += expected.outside;
      slices += model.physics.drag_points > 1;
    }
  }
  // The draw covered every path: afloat, aground, outside, drag points.
  EXPECT_GT(compared, 1500);
  EXPECT_GT(grounded, 100);
  EXPECT_GT(outside, 100);
  EXPECT_GT(slices, 100);
}

TEST(BodyBatch, ABodysResultDoesNotDependOnItsBatchMates) {
  std::mt19937_64 random(7);
  const AnalyticFlow flow = random_flow(random);
  ForceModel model;
  const BodySet bodies = random_bodies(random, batch_width);
  int list[batch_width], hints[batch_width];
  Lanes t;
  BatchVector y{}, dy{}, dy_alone{};
  for (int k = 0; k < batch_width; ++k) {
    list[k] = k;
    hints[k] = -1;
    t[k] = 1.0;
    const BodyStateVector y_k = body_state(bodies, k);
    for (int c = 0; c < 6; ++c) y.c[c][k] = y_k[c];
  }
  batch_derivative(bodies, list, batch_width, flow, model, t, y, hints, dy);
  for (int k = 0; k < batch_width; ++k) {
    int one[batch_width] = {k}, hint[batch_width] = {-1};
    BatchVector y_one{};
    for (int c = 0; c < 6; ++c) y_one.c[c][0] = y.c[c][k];
    batch_derivative(bodies, one, 1, flow, model, t, y_one, hint, dy_alone);
    for (int c = 0; c < 6; ++c) EXPECT_EQ(dy_alone.c[c][0], dy.c[c][k]) << k << " " << c;
  }
}

TEST(BodyBatch, IntegratedFloatingBodiesFollowTheScalarPathOverTwentySteps) {
  // 500 floating bodies, 20 flow steps of 0.5 s from random states in random flows: the same
  // sub-steps, and states within the drag's round-off carried through RKF45 (1e-9 m, rad, m/s).
  // Afloat only: a grounded body's stick and slip (spec 3.4) switch on a threshold, where a
  // difference of round-off may take the other branch.
  std::mt19937_64 random(99);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 3; ++trial) {
    AnalyticFlowSpec spec = random_flow(random).spec();
    spec.eta = 3.0 + 2.0 * unit(random);  // deeper than any draft
    spec.eta_rate = 0.0;
    const AnalyticFlow flow(spec);
    const ForceModel model = random_model(random);
    BodySet batched = random_bodies(random, 500, true);
    for (int i = 0; i < batched.size(); ++i) ASSERT_LT(batched.draft[i], 3.0);
    BodySet scalar = batched;
    const BodyIntegrator fast(model), reference(model, {.batch = false});
    long fast_steps = 0, reference_steps = 0;
    for (int step = 0; step < 20; ++step) {
      fast_steps += fast.advance(batched, flow, 0.5 * step, 0.5 * (step + 1)).accepted;
      reference_steps += reference.advance(scalar, flow, 0.5 * step, 0.5 * (step + 1)).accepted;
    }
    EXPECT_EQ(fast_steps, reference_steps);
    for (int i = 0; i < batched.size(); ++i) {
      ASSERT_NE(scalar.state[i], BodyState::grounded);
      EXPECT_LE((batched.position[i] - scalar.position[i]).norm(), 1e-9) << i;
      EXPECT_LE(std::abs(batched.angle[i] - scalar.angle[i]), 1e-9) << i;
      EXPECT_LE((batched.velocity[i] - scalar.velocity[i]).norm(), 1e-9) << i;
      EXPECT_EQ(batched.state[i], scalar.state[i]) << i;
    }
  }
}

}  // namespace
}  // namespace flotsam
