// Verifies the order in time of the time schemes (docs/model.md "Time scheme") on a standing
// wave: a closed basin of length L and depth H, no friction, starting from rest with
// eta = H + a cos(pi x / L), whose linear solution is eta = H + a cos(pi x / L) cos(omega t),
// omega = (pi / L) sqrt(g H) (a / H = 1e-3: the nonlinear terms are 1e-3 of the linear ones).
// The state after one period T at steps T/20, T/40 and T/80 on one mesh: the differences
// between successive step sizes cancel the mesh's error, and their ratio gives the observed
// order p = log2(|eta_1 - eta_2| / |eta_2 - eta_3|). BDF2 must show p >= 1.8 (second order);
// the theta-scheme at theta = 0.6 is first order (p < 1.3, asserted so that a test of the
// order can fail at all). And the BDF2 state at T/80 agrees with the linear solution within
// 2 % of the amplitude at T/80 (the mesh's and the step's errors together). Both steps
// (flow.scheme): the segregated step splits nothing in this wave (no viscosity; its elevation
// system is the Schur complement of the lumped coupled system), so it keeps BDF2's order.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support/flow_schemes.hpp"
#include "core/constants.hpp"
#include "flow/fem/shallow_water_solver.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

constexpr double L = 100.0, H = 10.0, a = 0.01, g = 9.81;  // [m], [m], [m], [m s^-2]

std::vector<double> wave_after_one_period(FlowScheme flow, TimeScheme scheme, int steps) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, L, 10.0, 20, 1, true});
  Case c;
  c.flow.initial_eta_start = c.flow.initial_eta_end = H;  // walls all round: a closed basin
  c.time.scheme = scheme;
  c.flow.scheme = flow;
  ShallowWaterSolver solver(mesh, c);
  solver.initialize();
  FlowState s = solver.state();
  for (int j = 0; j < mesh.vertex_count; ++j)
    s.eta[j] = H + a * std::cos(pi * mesh.nodes[j].x() / L);
  solver.set_state(s);
  const double period = 2.0 * L / std::sqrt(g * H);  // [s]
  for (int n = 0; n < steps; ++n) solver.step(period / steps);
  EXPECT_LE(std::abs(solver.water_balance().relative_error()), 1e-9);
  return solver.eta();
}

double max_difference(const std::vector<double>& x, const std::vector<double>& y) {
  double m = 0.0;
  for (size_t i = 0; i < x.size(); ++i) m = std::max(m, std::abs(x[i] - y[i]));
  return m;
}

double observed_order(FlowScheme flow, TimeScheme scheme) {
  const auto e1 = wave_after_one_period(flow, scheme, 20),
             e2 = wave_after_one_period(flow, scheme, 40),
             e3 = wave_after_one_period(flow, scheme, 80);
  return std::log2(max_difference(e1, e2) / max_difference(e2, e3));
}

class StandingWave : public testing::TestWithParam<FlowScheme> {};

TEST_P(StandingWave, Bdf2IsSecondOrderInTime) {
  const double p = observed_order(GetParam(), TimeScheme::bdf2);
  EXPECT_GE(p, 1.8);
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, L, 10.0, 20, 1, true});
  const auto eta = wave_after_one_period(GetParam(), TimeScheme::bdf2, 80);
  double error = 0.0;  // [m] against the linear solution at t = T
  for (int j = 0; j < mesh.vertex_count; ++j)
    error = std::max(error, std::abs(eta[j] - H - a * std::cos(pi * mesh.nodes[j].x() / L)));
  EXPECT_LE(error, 0.02 * a);
  std::printf(
      "standing wave, %s step, BDF2: observed order %.2f, error at T/80 %.2e m (%.2f %% of a)\n",
      test::scheme_name(GetParam()).c_str(), p, error, 100 * error / a);
}

TEST_P(StandingWave, ThetaSchemeIsFirstOrderInTime) {
  const double p = observed_order(GetParam(), TimeScheme::theta);
  EXPECT_LT(p, 1.3);
  EXPECT_GE(p, 0.8);
  std::printf("standing wave, %s step, theta = 0.6: observed order %.2f\n",
              test::scheme_name(GetParam()).c_str(), p);
}

INSTANTIATE_TEST_SUITE_P(FlowSchemes, StandingWave, test::both_flow_schemes,
                         test::flow_scheme_name);

}  // namespace
}  // namespace flotsam
