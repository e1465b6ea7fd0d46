// The branch-free ln, exp and x^p (core/branch_free_math.hpp) against the C library over their
// whole domains of use, to the errors the header states.
#include "core/branch_free_math.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace flotsam {
namespace {

constexpr double eps = 1.1102230246251565e-16;  // 2^-53, half an ulp of 1

TEST(BranchFreeMath, LogToTwoUlpsOverTwentySixDecades) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> exponent(-14.0, 12.0), near_one(0.5, 2.0);
  double worst = 0.0;  // [ulps of max(1, |ln x|)]
  for (int k = 0; k < 200000; ++k) {
    for (const double x : {std::pow(10.0, exponent(random)), near_one(random)}) {
      const double exact = std::log(x);
      worst = std::max(
          worst, std::abs(branch_free_log(x) - exact) / (2 * eps * std::max(1.0, std::abs(exact))));
    }
  }
  EXPECT_LE(worst, 2.0);  // 2e-16 absolute near 1, 4.4e-16 relative elsewhere
  EXPECT_EQ(branch_free_log(1.0), 0.0);
  EXPECT_NEAR(branch_free_log(2.0), std::log(2.0), 2 * eps);
}

TEST(BranchFreeMath, ExpToFourTenthsOfAnUlpTimesTwoRelative) {
  std::mt19937_64 random(12);
  std::uniform_real_distribution<double> y(-700.0, 700.0);
  double worst = 0.0;
  for (int k = 0; k < 200000; ++k) {
    const double v = y(random);
    worst = std::max(worst, std::abs(branch_free_exp(v) / std::exp(v) - 1.0));
  }
  EXPECT_LE(worst, 4.0 * eps);
  EXPECT_EQ(branch_free_exp(0.0), 1.0);
}

TEST(BranchFreeMath, GanserPowerAgreesWithExpOfLogAndPow) {
  // R^0.6567 of Ganser's law (P-18) at R from the Stokes floor (1e-12 K1 K2) to 1e12: within
  // (4 + |p ln R|) 4 eps of std::pow and of std::exp(p std::log(R)) (the scalar law), that is
  // 1.2e-14 at most (each rounds ln R to its own ulp, which p ln R carries into the power).
  std::mt19937_64 random(13);
  std::uniform_real_distribution<double> exponent(-14.0, 12.0);
  const double p = 0.6567;
  for (int k = 0; k < 200000; ++k) {
    const double R = std::pow(10.0, exponent(random));
    const double fast = branch_free_pow(R, p);
    const double bound = (4.0 + std::abs(p * std::log(R))) * 4 * eps;
    ASSERT_LE(bound, 1.2e-14);
    ASSERT_LE(std::abs(fast / std::pow(R, p) - 1.0), bound) << R;
    ASSERT_LE(std::abs(fast / std::exp(p * std::log(R)) - 1.0), bound) << R;
  }
}

}  // namespace
}  // namespace flotsam
