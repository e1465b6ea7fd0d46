// ctest-label: slow
// Verifies the rain on a tilted plane of fv_rain_on_tilted_plane.cpp (the kinematic wave's
// outflow, Overton & Meadows 1976, ch. 4) on cells four times finer (0.125 m), with the two
// lower ends: `free`, whose outflow on the rising limb stays within 8 % of the kinematic wave's
// q(t) (its growing layer at the end holds back a few per cent, more on finer cells:
// docs/validation.md), and an overfall (an elevation boundary far below the bed: the water
// leaves at critical depth), whose outflow converges to q(t): within 3 % at t_e / 2 and
// 3 t_e / 4 here (+11 %, +5.2 %, +2.4 % at t_e / 2 on 0.5, 0.25, 0.125 m cells: first order),
// and its outflow at 3 t_e is i L B within 0.1 %. Both plateaus: depth i t within 1e-8,
// discharge Manning's within 1 %. About 25 s.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support/fv_cases.hpp"

namespace flotsam {
namespace {

using test::RainPlaneOutlet;

void check(const test::RainPlaneRun& r, const char* outlet, double rising_tolerance,
           double equilibrium_tolerance) {
  std::printf(
      "FV rain on a tilted plane, %s end (%d cells): outflow / kinematic at t_e/2 %.4f, "
      "3t_e/4 %.4f, t_e %.4f; at 3 t_e Q / (i L B) %.5f; plateau h %.1e, q %.1e; balance %.1e; "
      "%.1f s\n",
      outlet, r.cells, r.ratio_half, r.ratio_three_quarters, r.ratio_t_e, r.ratio_equilibrium,
      r.plateau_depth, r.plateau_discharge, r.balance, r.seconds);
  EXPECT_NEAR(r.ratio_equilibrium, 1.0, equilibrium_tolerance) << outlet;
  EXPECT_LE(r.plateau_depth, 1e-8) << outlet;
  EXPECT_LE(r.plateau_discharge, 0.01) << outlet;
  EXPECT_NEAR(r.ratio_half, 1.0, rising_tolerance) << outlet;
  EXPECT_NEAR(r.ratio_three_quarters, 1.0, rising_tolerance) << outlet;
  EXPECT_LE(std::abs(r.balance), 1e-12) << outlet;
}

TEST(FvRainOnTiltedPlaneSlow, FreeEndStaysNearAndOverfallConvergesToTheKinematicWave) {
  check(test::run_rain_plane(800, RainPlaneOutlet::free), "free", 0.08, 0.02);
  check(test::run_rain_plane(800, RainPlaneOutlet::overfall), "overfall", 0.03, 1e-3);
}

}  // namespace
}  // namespace flotsam
