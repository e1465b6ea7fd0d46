#include "core/time_series.hpp"

#include <gtest/gtest.h>

namespace flotsam {

TEST(TimeSeries, ConstantIsConstant) {
  TimeSeries s(2.5);
  EXPECT_EQ(s(-10.0), 2.5);
  EXPECT_EQ(s(1e6), 2.5);
  EXPECT_TRUE(s.is_constant());
}

TEST(TimeSeries, LinearBetweenPointsAndHeldOutside) {
  TimeSeries s({{0.0, 1.0}, {10.0, 3.0}, {20.0, -1.0}});
  EXPECT_DOUBLE_EQ(s(5.0), 2.0);
  EXPECT_DOUBLE_EQ(s(15.0), 1.0);
  EXPECT_DOUBLE_EQ(s(10.0), 3.0);
  EXPECT_EQ(s(-1.0), 1.0);
  EXPECT_EQ(s(99.0), -1.0);
}

// The integral of a piecewise-linear series is the sum of its trapezoids, exactly: here areas of
// whole triangles and rectangles, so the comparisons hold to round-off (1e-14 relative).
TEST(TimeSeries, IntegralIsExactAcrossRowsAndBeyondTheEnds) {
  const TimeSeries s({{0.0, 0.0}, {10.0, 6.0}, {20.0, 2.0}});
  EXPECT_NEAR(s.integral(0.0, 10.0), 30.0, 1e-14 * 30.0);
  EXPECT_NEAR(s.integral(0.0, 20.0), 30.0 + 40.0, 1e-14 * 70.0);
  EXPECT_NEAR(s.integral(5.0, 15.0), 0.5 * 5.0 * (3.0 + 6.0) + 0.5 * 5.0 * (6.0 + 4.0),
              1e-14 * 50.0);
  EXPECT_NEAR(s.integral(-4.0, 0.0), 0.0, 1e-14);           // the first value held
  EXPECT_NEAR(s.integral(20.0, 30.0), 20.0, 1e-14 * 20.0);  // the last value held
  EXPECT_NEAR(s.integral(-4.0, 30.0), 30.0 + 40.0 + 20.0, 1e-14 * 90.0);
  EXPECT_NEAR(s.integral(2.0, 3.0), 0.5 * (1.2 + 1.8), 1e-14);  // inside one row
  EXPECT_EQ(s.integral(7.0, 7.0), 0.0);
  // Pieces add up: the integral over [0, 20] split at any point is the whole.
  for (double t : {0.5, 9.99, 10.0, 13.7})
    EXPECT_NEAR(s.integral(0.0, t) + s.integral(t, 20.0), 70.0, 1e-13) << t;
  EXPECT_EQ(TimeSeries(2.5).integral(-1.0, 3.0), 10.0);
}

}  // namespace flotsam
