// ctest-label: slow
// Verifies that the finite-volume engine converges to Thacker's planar surface in a paraboloid
// (Thacker 1981; SWASHES 4.2.2, Delestre et al. 2013; fv_thacker_paraboloid.cpp has the case and
// its coarse meshes) on finer meshes, after three periods, with the dry depth and the velocity
// depth H_eps at 1e-5 m instead of their default 1e-3 m (1% of h0 here), which sets a
// mesh-independent error at the shoreline: with the defaults the L1 error of H stalls at
// 8.8e-4 m on both 80 x 80 and 160 x 160 rectangles. With 1e-5 m:
//   - the L1 error of H falls at an observed order above 0.7 from 40 x 40 to 80 x 80 to
//     160 x 160 rectangles (measured 1.1 and 0.8; about first order is expected with a moving
//     shoreline);
//   - the volume is conserved to 1e-12 relative and no depth goes negative.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support/fv_cases.hpp"

namespace flotsam {
namespace {

void print(const test::ThackerRun& r, const char* settings) {
  std::printf(
      "Thacker (%s), %d x %d rectangles (cell width %.4f m): L1(H) %.3e m, L1(Hu) %.3e m^2/s, "
      "volume change %.1e, balance %.1e, %.2f s\n",
      settings, r.n, r.n, r.cell_width, r.error_h, r.error_hu, r.volume_change, r.balance,
      r.seconds);
  EXPECT_LE(std::abs(r.volume_change), 1e-12) << r.n;
  EXPECT_LE(std::abs(r.balance), 1e-12) << r.n;
}

TEST(FvThackerParaboloidSlow, ConvergesWithThinDryAndVelocityDepths) {
  constexpr double thin = 1e-5;  // [m] dry depth and H_eps
  std::vector<test::ThackerRun> runs;
  for (int n : {40, 80, 160}) {
    runs.push_back(test::run_thacker(n, 3.0, thin));
    print(runs.back(), "depths 1e-5 m");
  }
  for (std::size_t k = 1; k < runs.size(); ++k) {
    const double order = test::observed_order(runs[k - 1].error_h, runs[k].error_h);
    std::printf("Thacker (depths 1e-5 m), %d -> %d: observed order %.2f in H\n", runs[k - 1].n,
                runs[k].n, order);
    EXPECT_GT(order, 0.7);
  }
}

}  // namespace
}  // namespace flotsam
