// Verifies that steady uniform flow down a sloping straight channel with Manning friction has the
// Manning normal depth h_n = (n q / sqrt(S))^(3/5) everywhere, within 0.5% (issue 3 item 5;
// Chow 1959, Open-channel hydraulics, ch. 6): discharge in at the upstream end, the normal depth
// imposed downstream; and that the outflow equals the inflow to 1e-9.
#include <gtest/gtest.h>

#include <cmath>

#include "flow/fem/shallow_water_solver.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

TEST(ManningUniformFlow, DepthIsTheNormalDepthEverywhere) {
  const double L = 1000.0, B = 20.0;  // [m]
  const double S = 1e-3, n = 0.03;    // bed slope [-], Manning [s m^-1/3]
  const double h_n = 1.0;             // [m] normal depth we aim at
  const double q = std::pow(h_n, 5.0 / 3.0) * std::sqrt(S) / n;  // [m^2/s] Manning
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, L, B, 40, 2, true});
  Case c;
  c.bed.kind = BedConfig::Kind::slope;
  c.bed.slope = Vec2(S, 0.0);
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = n;
  c.flow.initial_eta_start = h_n;
  c.flow.initial_eta_end = h_n - S * L;
  c.flow.boundaries = {{BoundaryCondition::Kind::discharge, "left", TimeSeries(q * B), {}},
                       {BoundaryCondition::Kind::elevation, "right", TimeSeries(h_n - S * L), {}}};
  ShallowWaterSolver solver(mesh, c);
  solver.initialize();
  const SteadyReport report = solver.solve_steady();
  ASSERT_TRUE(report.converged) << report.residuals.back();
  const auto H = solver.depth();
  double error = 0.0;
  for (double h : H) error = std::max(error, std::abs(h - h_n) / h_n);
  EXPECT_LE(error, 0.005);
  // Steady state: what leaves through the outlet is what the inlet brings, to 1e-9.
  const auto& rate = solver.water_balance().group_rate;
  EXPECT_LE(std::abs(rate[mesh.find_group("left")] + rate[mesh.find_group("right")]) /
                std::abs(rate[mesh.find_group("left")]),
            1e-9);
  // Discharge through the outflow equals the inflow Q in the steady state: the last pseudo step
  // moved (almost) nothing.
  std::printf("Manning: max relative depth error %.3e after %d iterations\n", error,
              report.iterations);
}

}  // namespace
}  // namespace flotsam
