// Verifies that steady uniform flow along a straight channel on the rotating Earth keeps the
// cross-channel surface slope of geostrophic balance d eta/dy = - f u / g (spec 1.1 Coriolis;
// the y component of (M-1a) with v = 0), within 2% (issue 3 item 5); outflow equals inflow to 1e-9.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/time_schemes.hpp"
#include "core/constants.hpp"
#include "flow/fem/shallow_water_solver.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

// The cross-channel slope at x = L/2 of the solver's state, and the one geostrophic balance gives
// its mean velocity there.
struct Slopes {
  double slope, expected;  // [-]
};

Slopes cross_channel_slope(const Mesh& mesh, const ShallowWaterSolver& solver, double L, double B) {
  double eta_right = 0, eta_left = 0, u_sum = 0;
  int count = 0;
  for (int i = 0; i < mesh.node_count(); ++i) {
    const Vec2& p = mesh.nodes[i];
    if (std::abs(p.x() - L / 2) > 1e-9) continue;
    u_sum += solver.u()[i];
    ++count;
    if (i < mesh.vertex_count && p.y() < 1e-9) eta_right = solver.eta()[i];
    if (i < mesh.vertex_count && p.y() > B - 1e-9) eta_left = solver.eta()[i];
  }
  const double f = 2 * earth_rotation_rate * std::sin(pi / 4);  // [1/s]
  return {(eta_left - eta_right) / B, -f * (u_sum / count) / 9.81};
}

TEST(CoriolisGeostrophicSlope, CrossChannelSlopeIsMinusFUOverG) {
  const double L = 4000.0, B = 400.0, S = 1e-3, n = 0.03, h_n = 2.0;
  const double q = std::pow(h_n, 5.0 / 3.0) * std::sqrt(S) / n;  // [m^2/s]
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, L, B, 40, 8, true});
  Case c;
  c.bed.kind = BedConfig::Kind::slope;
  c.bed.slope = Vec2(S, 0.0);
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = n;
  c.flow.coriolis = true;
  c.flow.latitude_deg = 45.0;
  c.flow.initial_eta_start = h_n;
  c.flow.initial_eta_end = h_n - S * L;
  c.flow.boundaries = {{BoundaryCondition::Kind::discharge, "left", TimeSeries(q * B), {}},
                       {BoundaryCondition::Kind::elevation, "right", TimeSeries(h_n - S * L), {}}};
  ShallowWaterSolver solver(mesh, c);
  solver.initialize();
  const SteadyReport report = solver.solve_steady();
  ASSERT_TRUE(report.converged);
  const auto [slope, expected] = cross_channel_slope(mesh, solver, L, B);
  EXPECT_NEAR(slope / expected, 1.0, 0.02);
  // Steady state: what leaves through the outlet is what the inlet brings, to 1e-9.
  const auto& rate = solver.water_balance().group_rate;
  EXPECT_LE(std::abs(rate[mesh.find_group("left")] + rate[mesh.find_group("right")]) /
                std::abs(rate[mesh.find_group("left")]),
            1e-9);
  std::printf("coriolis: slope %.6e expected %.6e (ratio %.5f)\n", slope, expected,
              slope / expected);
}

// The same balance kept by the segregated step marching from the steady state, with either time
// scheme (its Coriolis is explicit: at the paths' feet with theta, at the node on the velocity
// extrapolated to t^{n+1} with BDF2, whose first step has no earlier state): 20 steps of 20 s,
// the slope still within 2 % of -f u / g.
class CoriolisMarched : public testing::TestWithParam<TimeScheme> {};

TEST_P(CoriolisMarched, SegregatedStepKeepsTheGeostrophicSlope) {
  const double L = 4000.0, B = 400.0, S = 1e-3, n = 0.03, h_n = 2.0;
  const double q = std::pow(h_n, 5.0 / 3.0) * std::sqrt(S) / n;  // [m^2/s]
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, L, B, 40, 8, true});
  Case c;
  c.bed.kind = BedConfig::Kind::slope;
  c.bed.slope = Vec2(S, 0.0);
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = n;
  c.flow.coriolis = true;
  c.flow.latitude_deg = 45.0;
  c.flow.initial_eta_start = h_n;
  c.flow.initial_eta_end = h_n - S * L;
  c.flow.boundaries = {{BoundaryCondition::Kind::discharge, "left", TimeSeries(q * B), {}},
                       {BoundaryCondition::Kind::elevation, "right", TimeSeries(h_n - S * L), {}}};
  c.flow.scheme = FlowScheme::segregated;
  c.time.scheme = GetParam();
  ShallowWaterSolver solver(mesh, c);
  solver.initialize();
  ASSERT_TRUE(solver.solve_steady().converged);
  for (int k = 0; k < 20; ++k) solver.step(20.0);
  const auto [slope, expected] = cross_channel_slope(mesh, solver, L, B);
  EXPECT_NEAR(slope / expected, 1.0, 0.02);
  std::printf("coriolis, segregated, %s: slope %.6e expected %.6e (ratio %.5f)\n",
              test::scheme_name(GetParam()).c_str(), slope, expected, slope / expected);
}

INSTANTIATE_TEST_SUITE_P(TimeSchemes, CoriolisMarched, test::both_time_schemes,
                         test::time_scheme_name);

}  // namespace
}  // namespace flotsam
