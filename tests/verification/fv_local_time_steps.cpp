// Verifies the finite-volume engine's local time stepping (flow.fv.time_levels; docs/model.md
// "Local time stepping") on a graded mesh: a 100 m x 40 m channel with two piers, 3 m cells
// falling to 1.5 m at the piers, over a bumpy bed with an island.
//   - A lake at rest (eta_0 = 1 m) stays at rest to round-off with four levels: max|Hu|, max|Hv|
//     <= 1e-12 m^2/s, max|eta - eta_0| <= 1e-12 m, the island's dry cells stay dry.
//   - A dam break in the closed channel (eta = 1.5 m upstream of x = 35 m, 1 m below, walls all
//     round, 20 s, wet/dry fronts at the island): the volume is conserved to 1e-12 relative, the
//     result differs from the one-level scheme's by at most 0.5 % of the mean depth in L1 (both
//     are second order; they differ by their truncation errors), the cell updates fall by at least
//     1.3x (the mesh is graded by 2x only), and 1 and 2 threads give the same state bit for bit.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>

#include "../support/fv_cases.hpp"
#include "../support/island_channel.hpp"

namespace flotsam {
namespace {

constexpr double eta0 = 1.0;  // [m]

Case channel_case(int levels, const char* eta) {
  Case c = test::fv_case({"bank_right", "bank_left", "pier_1", "pier_2", "inflow", "outflow"});
  test::set_island_bed(c);
  c.flow.initial_eta = Expression(eta, "initial surface");
  c.flow.fv.time_levels = levels;
  return c;
}

struct LevelsRun {
  ConservedState state;
  double volume_change = 0.0;  // [-] relative
  double updates = 0.0;        // cell updates
  int cells = 0;
};

LevelsRun run(int levels, const char* eta, double end, int threads) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  const Case c = channel_case(levels, eta);
  FvEngine engine(test::island_channel_mesh(), c);
  engine.initialize();
  const FiniteVolumeSolver& solver = engine.solver();
  const double V0 = solver.volume();
  for (int n = 0; n < static_cast<int>(end); ++n) engine.step(1.0);
  omp_set_num_threads(saved);
  return {solver.state(), (solver.volume() - V0) / V0, solver.sub_steps().cell_updates,
          solver.cells().cell_count};
}

TEST(FvLocalTimeSteps, LakeAtRestStaysAtRestWithFourLevels) {
  const test::Stopwatch clock;
  const LevelsRun r = run(4, "1", 100.0, 2);
  const Case c = channel_case(4, "1");
  FvEngine engine(test::island_channel_mesh(), c);
  engine.initialize();
  const std::vector<double> h0 = engine.solver().state().h;
  const std::vector<double>& z = engine.solver().bed();
  double hu_max = 0.0, eta_error = 0.0;
  int wetted = 0;
  for (int i = 0; i < r.cells; ++i) {
    if (h0[i] == 0.0) {
      wetted += r.state.h[i] != 0.0;
      continue;
    }
    hu_max = std::max(hu_max, std::max(std::abs(r.state.hu[i]), std::abs(r.state.hv[i])));
    eta_error = std::max(eta_error, std::abs(r.state.h[i] + z[i] - eta0));
  }
  std::printf(
      "lake at rest, 4 levels, 100 s: max|Hu|, |Hv| %.1e m^2/s, max|eta - eta0| %.1e m, dry "
      "cells wetted %d, volume %.1e, %.4g cell updates, %.2f s\n",
      hu_max, eta_error, wetted, r.volume_change, r.updates, clock.seconds());
  EXPECT_LE(hu_max, 1e-12);
  EXPECT_LE(eta_error, 1e-12);
  EXPECT_EQ(wetted, 0);
  EXPECT_LE(std::abs(r.volume_change), 1e-12);
}

TEST(FvLocalTimeSteps, DamBreakConservesMassAndFollowsTheOneLevelScheme) {
  const test::Stopwatch clock;
  const char* eta = "x < 35 ? 1.5 : 1";
  const LevelsRun one = run(1, eta, 20.0, 2), four = run(4, eta, 20.0, 2),
                  serial = run(4, eta, 20.0, 1);
  double difference = 0.0, depth = 0.0;
  for (int i = 0; i < one.cells; ++i) {
    difference += std::abs(four.state.h[i] - one.state.h[i]);
    depth += one.state.h[i];
  }
  const double l1 = difference / depth;
  bool identical = serial.state.h == four.state.h && serial.state.hu == four.state.hu &&
                   serial.state.hv == four.state.hv;
  std::printf(
      "dam break, 20 s: volume change %.1e (1 level %.1e), L1(h) difference from 1 level %.3f "
      "%%, cell updates %.4g vs %.4g (x%.2f), 1 and 2 threads %s, %.2f s\n",
      four.volume_change, one.volume_change, 100.0 * l1, four.updates, one.updates,
      one.updates / four.updates, identical ? "identical" : "differ", clock.seconds());
  EXPECT_LE(std::abs(four.volume_change), 1e-12);
  EXPECT_LE(l1, 5e-3);
  EXPECT_GE(one.updates / four.updates, 1.3);
  EXPECT_TRUE(identical);
}

}  // namespace
}  // namespace flotsam
