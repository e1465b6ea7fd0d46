// A seiche in a closed basin (issue 19 item 1), both steps (flow.scheme): a frictionless,
// inviscid basin of length L and depth H starting from rest with eta = H + a cos(pi x / L),
// whose linear solution (a / H = 1e-3) is the first mode, eta = H + a cos(pi x / L) cos(omega t)
// with the period T = 2 L / sqrt(g H). Measured: the period from the zero crossings of
// eta - H at the wall x = 0 over the run (linear interpolation between steps), and the energy
//     E = integral of ( H |u|^2 / 2 + g (eta - H)^2 / 2 ) dA,
// which nothing brings in. Tolerances:
//  * gravity-wave Courant number 1.6 (T/50), 5 periods: the period within 0.5 % of T, and the
//    amplitude left (sqrt of E's ratio) within 1 % of the theta-scheme's own damping of an
//    oscillator over the run's steps (the only damping of this linear, inviscid mode);
//  * Courant 5 and 20, 20 and 5 periods (E falls to 1e-4 of its start; below that round-off
//    takes over): the energy falls at every step (stable: the steps are
//    implicit in the gravity waves), and the period within 1 % of the theta-scheme's own
//    period for an oscillator of frequency omega, T_theta = 2 pi dt / (atan((1 - theta) omega dt)
//    + atan(theta omega dt)) (1.4 % longer than T at Courant 5; only meaningful while a period
//    has several steps, so at Courant 20, four steps a period, only the energy is asserted).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <tuple>
#include <vector>

#include "../support/flow_integral.hpp"
#include "../support/flow_schemes.hpp"
#include "core/constants.hpp"
#include "flow/fem/shallow_water_solver.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

constexpr double L = 100.0, W = 10.0, H = 10.0, a = 0.01;  // [m]
constexpr int cells = 40;                                  // along x: h = 2.5 m

double energy(const ShallowWaterSolver& solver) {  // [m^5 s^-2]
  const double g = solver.flow_case().flow.gravity;
  return test::integrate_flow(solver, [&](const Vec2&, const Vec2& u, double eta, double) {
    return 0.5 * eta * u.squaredNorm() + 0.5 * g * (eta - H) * (eta - H);
  });
}

struct Seiche {
  double period;        // [s] measured
  double largest_rise;  // [-] largest relative change of E over one step
  double energy_ratio;  // [-] E(end) / E(0)
  double balance;       // [-] the water balance's relative error
  double dt;            // [s] the run's step
  int steps;            // the run's steps
  double theta;         // [-] the case's theta-scheme
};

Seiche run_seiche(FlowScheme scheme, double courant, int periods) {
  const Mesh mesh = make_rectangle_mesh({.length = L, .width = W, .nx = cells, .ny = 2});
  Case c;
  c.flow.scheme = scheme;
  c.flow.viscosity = 0.0;
  c.flow.initial_eta_start = c.flow.initial_eta_end = H;  // walls all round
  ShallowWaterSolver solver(mesh, c);
  solver.initialize();
  FlowState s = solver.state();
  int wall = -1;  // a vertex at x = 0
  for (int j = 0; j < mesh.vertex_count; ++j) {
    s.eta[j] = H + a * std::cos(pi * mesh.nodes[j].x() / L);
    if (mesh.nodes[j].x() == 0.0) wall = j;
  }
  solver.set_state(s);
  const double c0 = std::sqrt(c.flow.gravity * H), T = 2.0 * L / c0;  // [m/s], [s]
  const double dt = courant * (L / cells) / c0;                       // [s]
  const int steps = static_cast<int>(std::ceil(periods * T / dt));
  std::vector<double> crossings;  // [s] zero crossings of eta - H at the wall
  double E0 = energy(solver), E = E0, largest_rise = -1.0, before = a, t = 0.0;
  for (int n = 0; n < steps; ++n) {
    solver.step(dt);
    const double now = solver.eta()[wall] - H, E_new = energy(solver);
    if ((before > 0.0) != (now > 0.0)) crossings.push_back(t + dt * before / (before - now));
    largest_rise = std::max(largest_rise, (E_new - E) / E);
    before = now;
    E = E_new;
    t += dt;
  }
  const double period = crossings.size() < 3 ? 0.0
                                             : 2.0 * (crossings.back() - crossings.front()) /
                                                   static_cast<double>(crossings.size() - 1);
  return {period, largest_rise, E / E0,      solver.water_balance().relative_error(),
          dt,     steps,        c.time.theta};
}

class SeichePeriod : public testing::TestWithParam<FlowScheme> {};

TEST_P(SeichePeriod, IsTheAnalyticPeriodAndDampsAsTheThetaSchemeDoes) {
  const Seiche s = run_seiche(GetParam(), 1.6, 5);
  const double T = 2.0 * L / std::sqrt(9.81 * H);  // [s]
  // The theta-scheme's amplification of an oscillator over one step, |G|^2 =
  // (1 + (1 - theta)^2 (omega dt)^2) / (1 + theta^2 (omega dt)^2), over the run's steps: the
  // amplitude left after 5 periods (issue 42 asks 95 % at the default theta = 0.6; the scheme
  // itself keeps 67.5 % at 50 steps a period and would need theta <= 0.513 for 95 %).
  const double theta = s.theta, x = 2.0 * pi / T * s.dt;  // [-], omega dt [-]
  const double G2 = (1.0 + (1.0 - theta) * (1.0 - theta) * x * x) / (1.0 + theta * theta * x * x);
  const double kept = std::pow(G2, 0.5 * s.steps);  // [-]
  std::printf(
      "seiche, %s, Courant 1.6: period %.4f s, analytic %.4f s (%+.3f %%), amplitude kept %.4f, "
      "theta-scheme's %.4f\n",
      test::scheme_name(GetParam()).c_str(), s.period, T, 100 * (s.period / T - 1),
      std::sqrt(s.energy_ratio), kept);
  EXPECT_NEAR(s.period / T, 1.0, 5e-3);
  EXPECT_NEAR(std::sqrt(s.energy_ratio) / kept, 1.0, 1e-2);
  EXPECT_LT(s.largest_rise, 0.0);
  EXPECT_LE(std::abs(s.balance), 1e-9);
}

class SeicheAtLargeCourant : public testing::TestWithParam<std::tuple<FlowScheme, double>> {};

TEST_P(SeicheAtLargeCourant, IsStable) {
  const auto [scheme, courant] = GetParam();
  const Seiche s = run_seiche(scheme, courant, courant <= 5.0 ? 20 : 5);
  const double omega = pi / L * std::sqrt(9.81 * H), x = omega * s.dt;  // [1/s], [-]
  const double T_theta =
      2.0 * pi * s.dt / (std::atan((1.0 - s.theta) * x) + std::atan(s.theta * x));
  std::printf(
      "seiche, %s, Courant %g: period %.4f s, theta-scheme's %.4f s (%+.3f %%), E ratio %.3e, "
      "largest rise %.2e\n",
      test::scheme_name(scheme).c_str(), courant, s.period, T_theta, 100 * (s.period / T_theta - 1),
      s.energy_ratio, s.largest_rise);
  EXPECT_LT(s.largest_rise, 0.0);
  EXPECT_LT(s.energy_ratio, 1.0);
  EXPECT_LE(std::abs(s.balance), 1e-9);
  if (courant <= 5.0) {
    EXPECT_NEAR(s.period / T_theta, 1.0, 1e-2);
  }
}

INSTANTIATE_TEST_SUITE_P(FlowSchemes, SeichePeriod, test::both_flow_schemes,
                         test::flow_scheme_name);

INSTANTIATE_TEST_SUITE_P(FlowSchemes, SeicheAtLargeCourant,
                         testing::Combine(test::both_flow_schemes, testing::Values(5.0, 20.0)),
                         [](const testing::TestParamInfo<std::tuple<FlowScheme, double>>& p) {
                           return test::scheme_name(std::get<0>(p.param)) + "_Courant" +
                                  std::to_string(static_cast<int>(std::get<1>(p.param)));
                         });

}  // namespace
}  // namespace flotsam
