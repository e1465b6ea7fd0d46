// ctest-label: slow
// Verifies that the finite-volume engine converges to Thacker's planar surface in a paraboloid
// (Thacker 1981; SWASHES 4.2.2, Delestre et al. 2013; fv_thacker_paraboloid.cpp has the case and
// its coarse meshes) on finer meshes, after three periods, at its default settings:
//   - the L1 error of H falls at an observed order above 0.5 from 80 x 80 to 160 x 160 to
//     320 x 320 rectangles (measured 0.80 and 0.62: at most first order is expected with a
//     moving shoreline, whose cells are partly wet), and on the finest it is within 2 % of the
//     exact depth's mean (1.74 %);
//   - the volume is conserved to 1e-12 relative and no depth goes negative.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support/fv_cases.hpp"

namespace flotsam {
namespace {

void print(const test::ThackerRun& r) {
  std::printf(
      "Thacker, %d x %d rectangles (cell width %.4f m): L1(H) %.3e m (%.2f %% of the mean "
      "depth), L1(Hu) %.3e m^2/s, volume change %.1e, balance %.1e, %.2f s\n",
      r.n, r.n, r.cell_width, r.error_h, 100.0 * r.relative_h, r.error_hu, r.volume_change,
      r.balance, r.seconds);
  EXPECT_LE(std::abs(r.volume_change), 1e-12) << r.n;
  EXPECT_LE(std::abs(r.balance), 1e-12) << r.n;
}

TEST(FvThackerParaboloidSlow, ConvergesOnFinerMeshesWithDefaultSettings) {
  std::vector<test::ThackerRun> runs;
  for (int n : {80, 160, 320}) {
    runs.push_back(test::run_thacker(n, 3.0));
    print(runs.back());
  }
  for (std::size_t k = 1; k < runs.size(); ++k) {
    const double order = test::observed_order(runs[k - 1].error_h, runs[k].error_h);
    std::printf("Thacker, %d -> %d: observed order %.2f in H\n", runs[k - 1].n, runs[k].n, order);
    EXPECT_GT(order, 0.5);
  }
  EXPECT_LE(runs.back().relative_h, 0.02);
}

}  // namespace
}  // namespace flotsam
