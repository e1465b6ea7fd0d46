// Verifies that the orientation predicate CCW (P-5.4) and the tests built on it give the exact
// answer, checked against exact integer arithmetic, for nearly collinear points where plain
// floating point gets the sign wrong.
#include "contact/orientation.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>

namespace flotsam {
namespace {

__extension__ using Int128 = __int128;

constexpr double ulp_half = 0x1p-53;  // [-] spacing of doubles in [0.5, 1)

// A coordinate that is a multiple of 2^-53 below 2^5, as an exact integer count of 2^-53.
Int128 as_integer(double x) {
  return static_cast<Int128>(std::ldexp(x, 53));
}

int exact_orientation(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Int128 det =
      (as_integer(b.x()) - as_integer(a.x())) * (as_integer(c.y()) - as_integer(a.y())) -
      (as_integer(b.y()) - as_integer(a.y())) * (as_integer(c.x()) - as_integer(a.x()));
  return (det > 0) - (det < 0);
}

int naive_orientation(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double det = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
  return (det > 0.0) - (det < 0.0);
}

// Shewchuk's test: A on a 256 x 256 grid of ulps around (0.5, 0.5), the line through (12, 12)
// and (24, 24). Every answer equals the exact integer one; plain evaluation errs on many.
TEST(Orientation, MatchesExactIntegerArithmeticForNearlyCollinearPoints) {
  const Vec2 b(12.0, 12.0), c(24.0, 24.0);
  int naive_wrong = 0, checked = 0;
  for (int i = 0; i < 256; ++i) {
    for (int j = 0; j < 256; ++j) {
      const Vec2 a(0.5 + i * ulp_half, 0.5 + j * ulp_half);
      const int exact = exact_orientation(a, b, c);
      ASSERT_EQ(orient2d(a, b, c), exact) << i << " " << j;
      ASSERT_EQ(orient2d(b, c, a), exact);  // cyclic permutations agree
      ASSERT_EQ(orient2d(b, a, c), -exact);
      naive_wrong += naive_orientation(a, b, c) != exact;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 65536);
  EXPECT_GT(naive_wrong, 1000);  // the case is hard: plain floating point fails on it
}

TEST(Orientation, NearlyParallelEdgesOfTwoLogs) {
  // Log edges 20 m long, the second tilted by one ulp of its end's y: they cross or not as the
  // exact arithmetic says.
  const Vec2 a(0.5, 0.5), b(20.5, 0.5);
  for (int k = -3; k <= 3; ++k) {
    const Vec2 c(0.25, 0.5 + k * ulp_half), d(20.75, 0.5 - k * ulp_half);
    const bool exact_cross = exact_orientation(c, d, a) * exact_orientation(c, d, b) <= 0 &&
                             exact_orientation(a, b, c) * exact_orientation(a, b, d) <= 0;
    EXPECT_EQ(segments_cross(a, b, c, d), exact_cross) << k;
  }
  // Collinear and overlapping, collinear and apart.
  EXPECT_TRUE(segments_cross({0.0, 0.0}, {2.0, 0.0}, {1.0, 0.0}, {3.0, 0.0}));
  EXPECT_FALSE(segments_cross({0.0, 0.0}, {1.0, 0.0}, {1.5, 0.0}, {3.0, 0.0}));
  EXPECT_TRUE(segments_cross({0.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}, {3.0, 5.0}));  // end touches
}

TEST(Orientation, PointInConvexPolygonCountsTheBoundary) {
  const std::array<Vec2, 4> square{Vec2(0.0, 0.0), Vec2(1.0, 0.0), Vec2(1.0, 1.0), Vec2(0.0, 1.0)};
  EXPECT_TRUE(point_in_convex_polygon({0.5, 0.5}, square));
  EXPECT_TRUE(point_in_convex_polygon({1.0, 0.3}, square));  // on an edge
  EXPECT_TRUE(point_in_convex_polygon({1.0, 1.0}, square));  // a vertex
  EXPECT_FALSE(point_in_convex_polygon({1.0 + 0x1p-52, 0.3}, square));
  const std::array<Vec2, 4> touching{Vec2(1.0, 0.5), Vec2(2.0, 0.5), Vec2(2.0, 1.5),
                                     Vec2(1.0, 1.5)};
  EXPECT_TRUE(convex_polygons_touch(square, touching));
  const std::array<Vec2, 4> apart{Vec2(1.0 + 0x1p-52, 0.5), Vec2(2.0, 0.5), Vec2(2.0, 1.5),
                                  Vec2(1.0 + 0x1p-52, 1.5)};
  EXPECT_FALSE(convex_polygons_touch(square, apart));
}

}  // namespace
}  // namespace flotsam
