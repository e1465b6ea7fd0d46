// Verifies that the finite-volume engine keeps a lake at rest at rest to round-off over a bumpy
// bed with an emerged island and two bridge piers (spec 1.3, well balanced; the hydrostatic
// reconstruction of Audusse et al. 2004 preserves it exactly, dry cells included): the exact
// solution is eta = eta_0 = 1 m and u = 0 where the bed is below eta_0, dry above. After 1,000
// sub-steps at the engine's Courant number, on the wet cells max|Hu|, max|Hv| <= 1e-12 m^2/s
// and max|eta - eta_0| <= 1e-12 m; the dry cells (the island's top) stay exactly dry; the water
// balance closes to 1e-12 relative. The inflow and outflow hold eta_0, banks and piers are walls.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support/fv_cases.hpp"
#include "../support/island_channel.hpp"

namespace flotsam {
namespace {

constexpr double eta0 = 1.0;  // [m]

TEST(FvLakeAtRestWithIsland, StaysAtRestFor1000SubSteps) {
  const test::Stopwatch clock;
  const Mesh& mesh = test::island_channel_mesh();
  Case c = test::fv_case({"bank_right", "bank_left", "pier_1", "pier_2"});
  for (const char* group : {"inflow", "outflow"})
    c.flow.boundaries.push_back(
        {BoundaryCondition::Kind::elevation, group, TimeSeries(eta0), TimeSeries(0.0)});
  test::set_island_bed(c);  // bumps up to 0.7 m under water, an island 1.6 m above
  c.flow.initial_eta_start = c.flow.initial_eta_end = eta0;
  FvEngine engine(mesh, c);
  engine.initialize();
  const FiniteVolumeSolver& solver = engine.solver();
  const std::vector<double> h_initial = solver.state().h;
  const double dt = solver.courant_step();  // [s] one sub-step per coupling step
  for (int n = 0; n < 1000; ++n) engine.step(dt);
  EXPECT_EQ(solver.sub_steps().count, 1000);

  const ConservedState& U = solver.state();
  double hu_max = 0.0, hv_max = 0.0, eta_error = 0.0;
  int dry = 0, wetted = 0;
  for (int i = 0; i < solver.cells().cell_count; ++i) {
    if (h_initial[i] == 0.0) {
      ++dry;
      if (U.h[i] != 0.0) ++wetted;
      continue;
    }
    hu_max = std::max(hu_max, std::abs(U.hu[i]));
    hv_max = std::max(hv_max, std::abs(U.hv[i]));
    eta_error = std::max(eta_error, std::abs(U.h[i] + solver.bed()[i] - eta0));
  }
  const double balance = engine.water_balance().relative_error();
  std::printf(
      "lake at rest with island: %d cells (%d dry), max|Hu| %.1e, max|Hv| %.1e m^2/s, "
      "max|eta - eta0| %.1e m, dry cells wetted %d, balance %.1e, dt %.4f s, %.2f s\n",
      solver.cells().cell_count, dry, hu_max, hv_max, eta_error, wetted, balance, dt,
      clock.seconds());
  EXPECT_GT(dry, 0);  // the island is there
  EXPECT_EQ(wetted, 0);
  EXPECT_LE(hu_max, 1e-12);
  EXPECT_LE(hv_max, 1e-12);
  EXPECT_LE(eta_error, 1e-12);
  EXPECT_LE(std::abs(balance), 1e-12);
}

}  // namespace
}  // namespace flotsam
