// Verifies that steady subcritical flow over a bump follows Bernoulli's equation
// q^2 / (2 g h^2) + h + z_b = const with constant unit discharge q, within 1% in depth (issue 3
// item 5; the classic test of Goutal & Maurel 1997, 25 m channel, z_b = 0.2 - 0.05 (x - 10)^2 on
// 8 < x < 12, q = 4.42 m^2/s, downstream depth 2 m); the outflow equals the inflow to 1e-9.
// Marched from rest on a Gmsh channel, it settles on the steady state (issue 42).
#include "subcritical_bump.hpp"

#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

using test::bernoulli_error;
using test::bump_case;
using test::bump_options;

TEST(SubcriticalBump, DepthFollowsBernoulli) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 25.0, 1.0, 100, 2, true});
  const Case c = bump_case({});
  ShallowWaterSolver solver(mesh, c, bump_options(Advection::supg));
  solver.initialize();
  const SteadyReport report = solver.solve_steady();
  ASSERT_TRUE(report.converged);
  const double error = bernoulli_error(solver);
  EXPECT_LE(error, 0.01);
  // Steady state: what leaves through the outlet is what the inlet brings, to 1e-9.
  const auto& rate = solver.water_balance().group_rate;
  EXPECT_LE(std::abs(rate[mesh.find_group("left")] + rate[mesh.find_group("right")]) /
                std::abs(rate[mesh.find_group("left")]),
            1e-9);
  std::printf("bump: max relative depth error %.3e, %d iterations\n", error, report.iterations);
}

// The default time scheme (characteristics) marched to its steady state at a gravity-wave
// Courant number sqrt(g h) dt / dx = 4.4 (dt = 0.25 s, cells of 0.25 m): its steady state
// differs from the Eulerian one by O(dt), so this checks that the explicit terms taken at the
// departure point keep it within the same 1% of Bernoulli (with them at the arrival point, as
// before 2026-11-21, the error was 1.7%; now 0.8%). Both steps (flow.scheme).
class SubcriticalBumpMarched : public testing::TestWithParam<FlowScheme> {};

TEST_P(SubcriticalBumpMarched, CharacteristicsMarchedToSteadyFollowBernoulli) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 25.0, 1.0, 100, 2, true});
  Case c = bump_case({});
  c.flow.scheme = GetParam();
  ShallowWaterSolver solver(mesh, c, bump_options(Advection::characteristics));
  solver.initialize();
  const double change = solver.march_to_steady(0.25, 1e-8, 400.0);
  ASSERT_LE(change, 1e-8);
  const double error = bernoulli_error(solver);
  EXPECT_LE(error, 0.01);
  std::printf(
      "bump, %s, characteristics at dt = 0.25 s: max relative depth error %.3e at t = %g s\n",
      test::scheme_name(GetParam()).c_str(), error, solver.time());
}

// The report of issue 42 (subcritical_bump.hpp): the segregated step here, the coupled one in
// subcritical_bump_slow.cpp (2.5 min).
TEST(SubcriticalBumpMarched, GmshChannelSettlesAfterBackflowAtTheOutlet) {
  test::march_bump_on_gmsh_channel(FlowScheme::segregated);
}

INSTANTIATE_TEST_SUITE_P(FlowSchemes, SubcriticalBumpMarched, test::both_flow_schemes,
                         test::flow_scheme_name);

}  // namespace
}  // namespace flotsam
