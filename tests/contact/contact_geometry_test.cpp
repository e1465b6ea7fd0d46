// Verifies that the contact manifolds (spec 4.1) have the right number of points, normal,
// depths and points for the cases worked out by hand: a corner pushed into a face (one point),
// two faces flat on each other (two points), a log against a one-sided wall.
#include "contact/contact_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"

namespace flotsam {
namespace {

constexpr double tol = 1e-12;                    // [m]
constexpr double margin = 0.005, flip = 0.0005;  // [m]

Rectangle rectangle(Vec2 centre, double angle, double length, double width) {
  return {{centre, {std::cos(angle), std::sin(angle)}}, {0.5 * length, 0.5 * width}};
}

TEST(ContactGeometry, CornerIntoFaceGivesOnePoint) {
  // B: 4 m x 1 m along x, top face y = 0.5. A: a 2 m x 2 m square turned 45 degrees, its lowest
  // corner at (0.3, 0.5 - d).
  const double d = 0.01;  // [m] depth
  const Rectangle b = rectangle({0.0, 0.0}, 0.0, 4.0, 1.0);
  const Rectangle a = rectangle({0.3, 0.5 - d + std::sqrt(2.0)}, 0.25 * pi, 2.0, 2.0);
  const Manifold m = collide_rectangles(a, b, margin, flip);
  ASSERT_EQ(m.point_count, 1);
  EXPECT_NEAR((m.normal - Vec2(0.0, 1.0)).norm(), 0.0, tol);  // from B towards A
  EXPECT_NEAR(m.points[0].separation, -d, tol);
  EXPECT_NEAR(m.depth(), d, tol);
  // M midway between the corner (0.3, 0.5 - d) and B's face.
  EXPECT_NEAR((m.points[0].point - Vec2(0.3, 0.5 - 0.5 * d)).norm(), 0.0, tol);
  // Swapping A and B flips the normal, keeps the depth.
  const Manifold swapped = collide_rectangles(b, a, margin, flip);
  ASSERT_EQ(swapped.point_count, 1);
  EXPECT_NEAR((swapped.normal - Vec2(0.0, -1.0)).norm(), 0.0, tol);
  EXPECT_NEAR(swapped.points[0].separation, -d, tol);
}

TEST(ContactGeometry, FaceOnFaceGivesTwoPointsAtTheOverlapEnds) {
  // Two logs 10 m x 0.5 m along x, A above B, shifted 3 m along x, overlapping by d.
  const double d = 0.002;  // [m]
  const Rectangle b = rectangle({0.0, 0.0}, 0.0, 10.0, 0.5);
  const Rectangle a = rectangle({3.0, 0.5 - d}, 0.0, 10.0, 0.5);
  const Manifold m = collide_rectangles(a, b, margin, flip);
  ASSERT_EQ(m.point_count, 2);
  EXPECT_NEAR((m.normal - Vec2(0.0, 1.0)).norm(), 0.0, tol);
  double xs[2];
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(m.points[k].separation, -d, tol);
    EXPECT_NEAR(m.points[k].point.y(), 0.25 - 0.5 * d, tol);  // midway between the faces
    xs[k] = m.points[k].point.x();
  }
  // The common part of the faces is x in [-2, 5]: its ends are the points.
  EXPECT_NEAR(std::min(xs[0], xs[1]), -2.0, tol);
  EXPECT_NEAR(std::max(xs[0], xs[1]), 5.0, tol);
  EXPECT_NE(m.points[0].feature, m.points[1].feature);
}

TEST(ContactGeometry, GapsBeyondTheMarginGiveNoContact) {
  const Rectangle b = rectangle({0.0, 0.0}, 0.0, 10.0, 0.5);
  const Manifold near =
      collide_rectangles(rectangle({0.0, 0.5 + 0.004}, 0.0, 10.0, 0.5), b, margin, flip);
  ASSERT_EQ(near.point_count, 2);
  EXPECT_NEAR(near.points[0].separation, 0.004, tol);  // a gap within the margin: s > 0
  EXPECT_EQ(collide_rectangles(rectangle({0.0, 0.5 + 0.006}, 0.0, 10.0, 0.5), b, margin, flip)
                .point_count,
            0);
}

TEST(ContactGeometry, LogAgainstAOneSidedWall) {
  // Wall along the x axis, water above (normal (0, 1)); a log tilted by 0.1 rad, lowest corner
  // d below the wall line.
  const double d = 0.003, theta = 0.1;  // [m], [rad]
  const Vec2 start(-20.0, 0.0), end(20.0, 0.0), normal(0.0, 1.0);
  const Vec2 u(std::cos(theta), std::sin(theta));
  const Vec2 lowest_from_centre = -5.0 * u - 0.25 * perp(u);
  const Rectangle log = rectangle(Vec2(1.0, -d) - lowest_from_centre, theta, 10.0, 0.5);
  const Manifold m = collide_rectangle_segment(log, start, end, normal, margin, flip);
  ASSERT_EQ(m.point_count, 1);
  EXPECT_NEAR((m.normal - normal).norm(), 0.0, tol);  // from the wall (B) towards the log (A)
  EXPECT_NEAR(m.points[0].separation, -d, tol);
  EXPECT_NEAR((m.points[0].point - Vec2(1.0, -0.5 * d)).norm(), 0.0, tol);
  // Flat on the wall: two points at the log's ends.
  const Rectangle flat = rectangle({2.0, 0.25 - d}, 0.0, 10.0, 0.5);
  const Manifold two = collide_rectangle_segment(flat, start, end, normal, margin, flip);
  ASSERT_EQ(two.point_count, 2);
  EXPECT_NEAR(std::abs(two.points[0].point.x() - two.points[1].point.x()), 10.0, tol);
  EXPECT_NEAR(two.points[0].separation, -d, tol);
  // The same log behind the wall (centre below its line) gets no contact: walls are one-sided.
  const Rectangle behind = rectangle({2.0, -0.25 + d}, 0.0, 10.0, 0.5);
  EXPECT_EQ(collide_rectangle_segment(behind, start, end, normal, margin, flip).point_count, 0);
}

}  // namespace
}  // namespace flotsam
