// RKF45 (spec 3.5): Fehlberg's table, the orders of its two solutions, the step controller and
// the exact landing on the interval's end.
#include "bodies/rkf45.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace flotsam {
namespace {

using V1 = RkVector<1>;
using V2 = RkVector<2>;

TEST(Rkf45, TableIsConsistent) {
  using F = Fehlberg;
  double sum5 = 0, sum4 = 0;
  for (int i = 0; i < 6; ++i) {
    double row = 0;
    for (int j = 0; j < i; ++j) row += F::a[i][j];
    EXPECT_NEAR(row, F::c[i], 1e-15) << "row " << i;  // c_i = sum_j a_ij
    sum5 += F::b5[i];
    sum4 += F::b4[i];
    EXPECT_NEAR(F::e[i], F::b5[i] - F::b4[i], 1e-16) << "weight " << i;
  }
  EXPECT_NEAR(sum5, 1.0, 1e-15);
  EXPECT_NEAR(sum4, 1.0, 1e-15);
}

/// Local errors of one step of size h on y' = -y, y(0) = 1: of y5 (5th order, O(h^6)), of y4
/// (4th order, O(h^5)); the observed orders from h and h/2.
TEST(Rkf45, LocalErrorOrdersOnDecay) {
  const auto f = [](double, const V1& y) { return V1(-y); };
  const auto local_errors = [&](double h) {
    V1 y0(1.0), y5, err, y4;
    rkf45_step<1>(f, 0.0, y0, h, f(0.0, y0), y5, err, &y4);
    return std::pair{std::abs(y5[0] - std::exp(-h)), std::abs(y4[0] - std::exp(-h))};
  };
  const double h = 0.2;
  const auto [e5_h, e4_h] = local_errors(h);
  const auto [e5_h2, e4_h2] = local_errors(h / 2);
  EXPECT_NEAR(std::log2(e5_h / e5_h2), 6.0, 0.25);  // y5: local error ~ h^6
  EXPECT_NEAR(std::log2(e4_h / e4_h2), 5.0, 0.25);  // y4 and the estimate: ~ h^5
}

TEST(Rkf45, LocalErrorOrdersOnHarmonicOscillator) {
  // x'' = -x as (x, v)' = (v, -x); exact (cos t, -sin t) from (1, 0).
  const auto f = [](double, const V2& y) { return V2(y[1], -y[0]); };
  const auto local_errors = [&](double h) {
    V2 y0(1.0, 0.0), y5, err, y4;
    rkf45_step<2>(f, 0.0, y0, h, f(0.0, y0), y5, err, &y4);
    const V2 exact(std::cos(h), -std::sin(h));
    return std::pair{(y5 - exact).norm(), err.norm()};
  };
  const double h = 0.25;
  const auto [e5_h, est_h] = local_errors(h);
  const auto [e5_h2, est_h2] = local_errors(h / 2);
  EXPECT_NEAR(std::log2(e5_h / e5_h2), 6.0, 0.3);
  EXPECT_NEAR(std::log2(est_h / est_h2), 5.0, 0.3);  // the error estimate y5 - y4
}

/// y' = -lambda (y - cos t) - sin t, exact y = cos t + (y0 - 1) exp(-lambda t): a fast decay onto
/// a slow solution. The controller keeps the global error within a small multiple of the
/// tolerance, and a looser tolerance costs fewer steps.
TEST(Rkf45, ControllerMeetsToleranceOnStiffishDecay) {
  const double lambda = 50.0;  // [1/s]
  const auto f = [&](double t, const V1& y) {
    return V1(-lambda * (y[0] - std::cos(t)) - std::sin(t));
  };
  const auto run = [&](double tol, Rkf45Counters& counters) {
    Rkf45Options<1> options;
    options.abs_tol.setConstant(tol);
    options.rel_tol.setConstant(tol);
    double h = 0.1;
    const V1 y = rkf45_integrate<1>(f, f, 0.0, 2.0, V1(2.0), h, options, counters);
    const double exact = std::cos(2.0) + std::exp(-lambda * 2.0);
    return std::abs(y[0] - exact);
  };
  Rkf45Counters tight, loose;
  EXPECT_LT(run(1e-8, tight), 1e-7);
  EXPECT_LT(run(1e-4, loose), 1e-3);
  EXPECT_LT(loose.accepted, tight.accepted);
  EXPECT_GT(tight.accepted, 0);
}

struct RecordingHooks : NoStepHooks {
  double* last_t;
  double bound;
  double max_step(double, const V1&) const { return bound; }
  void accepted(double t, const V1&) const { *last_t = t; }
};

TEST(Rkf45, LandsExactlyOnTheEndAndHonoursTheStepBound) {
  const auto f = [](double, const V1& y) { return V1(-y); };
  Rkf45Options<1> options;
  double last_t = -1;
  Rkf45Counters counters;
  double h = 0.07;
  const double t1 = 0.3;  // not a multiple of any step the controller takes
  const V1 y = rkf45_integrate<1>(f, f, 0.1, t1, V1(1.0), h, options, counters,
                                  RecordingHooks{{}, &last_t, 0.01});
  EXPECT_EQ(last_t, t1);             // bit for bit
  EXPECT_GE(counters.accepted, 20);  // (0.3 - 0.1) / 0.01
  EXPECT_NEAR(y[0], std::exp(-0.2), 1e-9);
}

TEST(Rkf45, RejectsAndShrinksWhenTheFirstStepIsTooLong) {
  const auto f = [](double, const V1& y) { return V1(-y); };
  Rkf45Options<1> options;
  options.abs_tol.setConstant(1e-10);
  options.rel_tol.setConstant(1e-10);
  Rkf45Counters counters;
  double h = 1.0;
  const V1 y = rkf45_integrate<1>(f, f, 0.0, 1.0, V1(1.0), h, options, counters);
  EXPECT_GT(counters.rejected, 0);
  EXPECT_NEAR(y[0], std::exp(-1.0), 1e-8);
}

TEST(Rkf45, OptimalStepFollowsThePaper) {
  // h_opt = 0.8 h (tol/|err|)^(1/5): |err| = 32 tol gives 0.4 h.
  EXPECT_NEAR(rkf45_optimal_step(1.0, 32.0), 0.4, 1e-15);
}

}  // namespace
}  // namespace flotsam
