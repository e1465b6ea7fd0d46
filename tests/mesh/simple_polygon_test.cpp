// Simple polygons (mesh/simple_polygon.hpp): area, bounding box, point inside, and each defect
// named in words.
#include "mesh/simple_polygon.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace flotsam {
namespace {

// An L of three unit squares, counter-clockwise: area 3.
const std::vector<Vec2> l_shape = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};

TEST(SimplePolygon, AreaAndBoundingBox) {
  EXPECT_EQ(signed_area(l_shape), 3.0);
  const std::vector<Vec2> clockwise(l_shape.rbegin(), l_shape.rend());
  EXPECT_EQ(signed_area(clockwise), -3.0);
  const BoundingBox box = bounding_box(l_shape);
  EXPECT_EQ(box.min, Vec2(0, 0));
  EXPECT_EQ(box.max, Vec2(2, 2));
}

TEST(SimplePolygon, HoldsThePointsOfItsConcaveShapeOnly) {
  EXPECT_TRUE(polygon_contains(l_shape, {0.5, 0.5}));
  EXPECT_TRUE(polygon_contains(l_shape, {1.5, 0.5}));
  EXPECT_TRUE(polygon_contains(l_shape, {0.5, 1.5}));
  EXPECT_FALSE(polygon_contains(l_shape, {1.5, 1.5}));  // the notch
  EXPECT_FALSE(polygon_contains(l_shape, {-0.5, 0.5}));
  EXPECT_FALSE(polygon_contains(l_shape, {0.5, 2.5}));
  EXPECT_TRUE(polygon_contains(l_shape, {0.5, 1.0}));  // level with a corner: counted once
}

TEST(SimplePolygon, DefectsAreNamed) {
  EXPECT_EQ(polygon_defect(l_shape), "");
  EXPECT_EQ(polygon_defect(std::vector<Vec2>{{0, 0}, {1, 0}}),
            "a polygon needs at least 3 points; got 2");
  EXPECT_EQ(polygon_defect(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {1, 0}}),
            "points 2 and 4 coincide at (1, 0) m");
  EXPECT_EQ(polygon_defect(std::vector<Vec2>{{0, 0}, {1, 0.1}, {3, 0.3}}),
            "the polygon has zero area (its points lie on one line)");
  EXPECT_EQ(polygon_defect(std::vector<Vec2>{{0, 0}, {1, 1}, {1, 0}, {0, 1}}),  // a bow tie
            "the polygon intersects itself: side 1 (points 1 to 2) meets side 3 (points 3 to 4)");
  // A side folding back onto its neighbour, and a corner touching a side that is not its own.
  EXPECT_EQ(polygon_defect(std::vector<Vec2>{{0, 0}, {2, 0}, {1, 0}, {1, 1}}),
            "the polygon intersects itself: side 1 (points 1 to 2) meets side 2 (points 2 to 3)");
  EXPECT_EQ(polygon_defect(std::vector<Vec2>{{0, 0}, {2, 0}, {2, 2}, {1, 0}, {0, 2}}),
            "the polygon intersects itself: side 1 (points 1 to 2) meets side 3 (points 3 to 4)");
}

}  // namespace
}  // namespace flotsam
