// Verifies that the colour maps hit their control points exactly (ends, middle) and interpolate
// linearly between them.
#include "render/colour_map.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace flotsam {
namespace {

TEST(ColourMap, ViridisEndsAndMiddleAreTheTableValues) {
  EXPECT_EQ(colour_at(ColourMapName::viridis, 0.0), (Colour{0x44, 0x01, 0x54}));
  EXPECT_EQ(colour_at(ColourMapName::viridis, 0.5), (Colour{0x21, 0x91, 0x8c}));
  EXPECT_EQ(colour_at(ColourMapName::viridis, 1.0), (Colour{0xfd, 0xe7, 0x25}));
}

TEST(ColourMap, BlueWhiteRedEndsAndMiddleAreTheTableValues) {
  EXPECT_EQ(colour_at(ColourMapName::blue_white_red, 0.0), (Colour{0x21, 0x66, 0xac}));
  EXPECT_EQ(colour_at(ColourMapName::blue_white_red, 0.5), (Colour{0xf7, 0xf7, 0xf7}));
  EXPECT_EQ(colour_at(ColourMapName::blue_white_red, 1.0), (Colour{0xb2, 0x18, 0x2b}));
}

TEST(ColourMap, EveryControlPointIsHitAtItsCoordinate) {
  for (const auto map : {ColourMapName::viridis, ColourMapName::blue_white_red}) {
    const auto points = colour_map_control_points(map);
    ASSERT_EQ(points.size(), 9u);
    for (std::size_t k = 0; k < points.size(); ++k) {
      EXPECT_EQ(colour_at(map, k / 8.0), points[k]) << "control point " << k;
    }
  }
}

TEST(ColourMap, HalfwayBetweenControlPointsIsTheRoundedMean) {
  // t = 1/16 lies halfway between #440154 and #472d7b: (0x44 + 0x47) / 2 = 69.5 -> 70, and so on.
  const Colour c = colour_at(ColourMapName::viridis, 1.0 / 16.0);
  EXPECT_EQ(c, (Colour{70, 23, 104}));  // lround(69.5, 23.0, 103.5)
}

TEST(ColourMap, OutOfRangeIsClampedAndNanIsNoData) {
  EXPECT_EQ(colour_at(ColourMapName::viridis, -3.0), colour_at(ColourMapName::viridis, 0.0));
  EXPECT_EQ(colour_at(ColourMapName::viridis, 7.0), colour_at(ColourMapName::viridis, 1.0));
  EXPECT_EQ(colour_at(ColourMapName::viridis, std::numeric_limits<double>::quiet_NaN()),
            no_data_colour);
}

TEST(ColourMap, CoordinateIsTheFractionOfTheRange) {
  EXPECT_DOUBLE_EQ(colour_coordinate(2.5, 2.0, 4.0), 0.25);
  EXPECT_DOUBLE_EQ(colour_coordinate(-1.0, -1.0, 1.0), 0.0);
}

}  // namespace
}  // namespace flotsam
