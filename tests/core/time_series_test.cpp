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

}  // namespace flotsam
