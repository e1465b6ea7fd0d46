// Verifies that steady uniform flow down a sloping straight channel with Manning friction has the
// Manning normal depth h_n = (n q / sqrt(S))^(3/5) everywhere, within 0.5% (issue 3 item 5;
// Chow 1959, Open-channel hydraulics, ch. 6): discharge in at the upstream end, the normal depth
// imposed downstream; and that the outflow equals the inflow to 1e-9. The same with the channel's
// n given by a roughness zone covering it over another default (flow.friction.zones, each
// element's n at its centroid: docs/model.md "Friction over the domain").
#include <gtest/gtest.h>

#include <cmath>

#include "flow/fem/shallow_water_solver.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

// The largest relative depth error of the steady flow of q [m^2/s] in a channel whose n is
// given by `zones` over the default `n_default` (none: n_default everywhere).
double steady_depth_error(double n_default, const std::vector<FrictionZone>& zones) {
  const double L = 1000.0, B = 20.0;  // [m]
  const double S = 1e-3, n = 0.03;    // bed slope [-], Manning [s m^-1/3] of the channel
  const double h_n = 1.0;             // [m] normal depth we aim at
  const double q = std::pow(h_n, 5.0 / 3.0) * std::sqrt(S) / n;  // [m^2/s] Manning
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, L, B, 40, 2, true});
  Case c;
  c.bed.kind = BedConfig::Kind::slope;
  c.bed.slope = Vec2(S, 0.0);
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = n_default;
  c.flow.friction_map.zones = zones;
  c.flow.initial_eta_start = h_n;
  c.flow.initial_eta_end = h_n - S * L;
  c.flow.boundaries = {{BoundaryCondition::Kind::discharge, "left", TimeSeries(q * B), {}},
                       {BoundaryCondition::Kind::elevation, "right", TimeSeries(h_n - S * L), {}}};
  ShallowWaterSolver solver(mesh, c);
  for (double k : solver.friction_coefficients()) EXPECT_EQ(k, n);
  solver.initialize();
  const SteadyReport report = solver.solve_steady();
  EXPECT_TRUE(report.converged) << report.residuals.back();
  const auto H = solver.depth();
  double error = 0.0;
  for (double h : H) error = std::max(error, std::abs(h - h_n) / h_n);
  // Steady state: what leaves through the outlet is what the inlet brings, to 1e-9.
  const auto& rate = solver.water_balance().group_rate;
  EXPECT_LE(std::abs(rate[mesh.find_group("left")] + rate[mesh.find_group("right")]) /
                std::abs(rate[mesh.find_group("left")]),
            1e-9);
  std::printf("Manning: max relative depth error %.3e after %d iterations%s\n", error,
              report.iterations, zones.empty() ? "" : " (n from a zone)");
  return error;
}

TEST(ManningUniformFlow, DepthIsTheNormalDepthEverywhere) {
  EXPECT_LE(steady_depth_error(0.03, {}), 0.005);
}

TEST(ManningUniformFlow, AZoneOverTheWholeChannelSetsItsN) {
  const std::vector<Vec2> all = {{-1.0, -1.0}, {1001.0, -1.0}, {1001.0, 21.0}, {-1.0, 21.0}};
  EXPECT_LE(steady_depth_error(0.06, {{all, {}, 0.03, "all"}}), 0.005);
}

}  // namespace
}  // namespace flotsam
