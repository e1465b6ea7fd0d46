// Friction over the domain (flow/friction_map.hpp): each point takes the default coefficient,
// replaced by the raster's nearest pixel where it has a value, replaced by each zone holding it in
// the order listed (the last wins; a zone's holes are not in it); a zone finds every point it
// holds however the points are binned; a pixel whose coefficient is not > 0 and a raster under
// none of the points are errors naming the key, the point and the pixel. Coefficients are
// compared exactly: each is one of the values given, copied.
#include "flow/friction_map.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>

#include "core/error.hpp"
#include "mesh/simple_polygon.hpp"

namespace flotsam {
namespace {

using ::testing::HasSubstr;

constexpr double n_default = 0.03;  // [s m^-1/3]

FlowConfig manning(double n = n_default) {
  FlowConfig flow;
  flow.friction = FrictionLaw::manning;
  flow.friction_coefficient = n;
  return flow;
}

std::vector<Vec2> rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// The points (i + 0.25, j + 0.5) [m], i in [0, 20), j in [0, 10): never on a zone's side below.
std::vector<Vec2> grid_points() {
  std::vector<Vec2> points;
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 20; ++i) points.emplace_back(i + 0.25, j + 0.5);
  return points;
}

std::string point_name(int k) {
  return fmt::format("point {}", k);
}

// A raster of 4 m pixels over x in [0, 12], y in [0, 8] (3 x 2 pixels, row 0 at the top),
// holding 0.01 (c + 1) + 0.001 r, and nodata at (column 1, row 0).
std::shared_ptr<const Raster> roughness_raster() {
  RasterGrid g;
  g.columns = 3;
  g.rows = 2;
  g.transform = {0.0, 4.0, 0.0, 8.0, 0.0, -4.0};
  std::vector<double> v(6);
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 3; ++c) v[r * 3 + c] = 0.01 * (c + 1) + 0.001 * r;
  v[1] = -9999.0;
  return std::make_shared<const Raster>(g, v, -9999.0);
}

TEST(FrictionMap, WithoutRasterOrZonesEveryPointTakesTheDefault) {
  const std::vector<Vec2> points = grid_points();
  const FrictionCoefficients k = friction_coefficients(manning(), points, point_name);
  ASSERT_EQ(k.coefficient.size(), points.size());
  for (double n : k.coefficient) EXPECT_EQ(n, n_default);
  EXPECT_EQ(k.from_raster, 0);
  EXPECT_TRUE(k.in_zone.empty());
}

TEST(FrictionMap, RasterThenZonesInOrderTheLastOneWins) {
  FlowConfig flow = manning();
  flow.friction_map.raster = roughness_raster();
  flow.friction_map.raster_origin = "case.yaml:8: flow.friction.raster";
  flow.friction_map.zones = {{rectangle(2, 2, 10, 6), {}, 0.08, "zone A"},
                             {rectangle(8, 4, 16, 9), {rectangle(13, 6, 15, 8)}, 0.05, "zone B"}};
  const std::vector<Vec2> points = grid_points();
  const FrictionCoefficients k = friction_coefficients(flow, points, point_name);
  int from_raster = 0, in_a = 0, in_b = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double x = points[i].x(), y = points[i].y();
    double expected = n_default;
    const int c = static_cast<int>(x / 4.0), r = static_cast<int>((8.0 - y) / 4.0);
    if (x < 12.0 && y < 8.0 && !(c == 1 && r == 0)) {
      expected = 0.01 * (c + 1) + 0.001 * r;
      ++from_raster;
    }
    if (x > 2 && x < 10 && y > 2 && y < 6) expected = 0.08, ++in_a;
    const bool in_hole = x > 13 && x < 15 && y > 6 && y < 8;
    if (x > 8 && x < 16 && y > 4 && y < 9 && !in_hole) expected = 0.05, ++in_b;
    EXPECT_EQ(k.coefficient[i], expected) << "at (" << x << ", " << y << ")";
  }
  EXPECT_EQ(k.from_raster, from_raster);
  EXPECT_EQ(k.in_zone, (std::vector<int>{in_a, in_b}));
  EXPECT_EQ(in_a, 32);  // x in {2.25 .. 9.25}, y in {2.5 .. 5.5}
}

TEST(FrictionMap, ZonesFindTheSamePointsAsTestingEveryPoint) {
  // Points scattered over a long thin strip, zones of random triangles: the bins of the
  // points change nothing.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> along(0.0, 1000.0), across(0.0, 30.0);
  std::vector<Vec2> points(5000);
  for (Vec2& p : points) p = {along(random), across(random)};
  FlowConfig flow = manning();
  for (int z = 0; z < 40; ++z) {
    const Vec2 a(along(random), across(random));
    std::vector<Vec2> ring = {a, a + Vec2(30.0 * (z % 3 + 1), 2.0), a + Vec2(5.0, 25.0)};
    flow.friction_map.zones.push_back({ring, {}, 0.04 + 0.001 * z, fmt::format("zone {}", z)});
  }
  const FrictionCoefficients k = friction_coefficients(flow, points, point_name);
  for (std::size_t i = 0; i < points.size(); ++i) {
    double expected = n_default;
    for (const FrictionZone& zone : flow.friction_map.zones)
      if (polygon_contains(zone.ring, points[i])) expected = zone.coefficient;
    EXPECT_EQ(k.coefficient[i], expected) << "point " << i;
  }
}

TEST(FrictionMap, RasterValuesMustBePositiveAndUnderSomePoint) {
  FlowConfig flow = manning();
  flow.friction_map.raster_origin = "case.yaml:8: flow.friction.raster";
  RasterGrid g;
  g.columns = 2;
  g.rows = 1;
  g.transform = {0.0, 10.0, 0.0, 10.0, 0.0, -10.0};
  flow.friction_map.raster = std::make_shared<const Raster>(g, std::vector{0.05, -0.02}, -9999.0);
  const std::vector<Vec2> points = {{5.0, 5.0}, {12.5, 7.5}};
  try {
    friction_coefficients(flow, points, point_name);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "case.yaml:8: flow.friction.raster: the raster '' holds -0.02 under point 1 at "
              "(12.500, 7.500) m (column 1, row 0); a friction coefficient must be > 0 (nodata, "
              "for the default, is allowed)");
  }
  const std::vector<Vec2> elsewhere = {{105.0, 5.0}, {112.5, 7.5}};
  try {
    friction_coefficients(flow, elsewhere, point_name);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "case.yaml:8: flow.friction.raster: the raster '' has a value under none of the 2 "
              "points where friction is taken (pixel centres from (5.000, 5.000) to (15.000, "
              "5.000) m; the points from (105.000, 5.000) to (112.500, 7.500) m): is it in the "
              "case's coordinate system?");
  }
}

TEST(FrictionMap, ZoneHoldsWhatIsInItsRingAndNotInItsHoles) {
  const FrictionZone zone{rectangle(0, 0, 10, 10), {rectangle(2, 2, 4, 4)}, 0.1, "zone"};
  EXPECT_TRUE(zone_contains(zone, {1.0, 1.0}));
  EXPECT_FALSE(zone_contains(zone, {3.0, 3.0}));
  EXPECT_FALSE(zone_contains(zone, {11.0, 3.0}));
}

}  // namespace
}  // namespace flotsam
