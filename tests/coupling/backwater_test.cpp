// Verifies that the backwater measurement (src/coupling/backwater.cpp, spec 6.3) gives the mean
// water surface along a cross-section by the midpoint rule, and the rise over a reference. A P1
// field that is linear in x and y is represented exactly by the mesh, and the mean of a linear
// function over points placed symmetrically about the segment's midpoint is its value there; so
// every expected value below is exact up to round-off.
#include "coupling/backwater.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>

#include "../mesh/holey_mesh.hpp"
#include "core/error.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

using ::testing::HasSubstr;

constexpr double tolerance = 1e-12;  // [m] round-off on elevations of about 10 m

/// eta = c0 + cx x + cy y at the mesh's vertices [m].
std::vector<double> linear_eta(const Mesh& mesh, double c0, double cx, double cy) {
  std::vector<double> eta(static_cast<std::size_t>(mesh.vertex_count));
  for (int v = 0; v < mesh.vertex_count; ++v)
    eta[v] = c0 + cx * mesh.nodes[v].x() + cy * mesh.nodes[v].y();
  return eta;
}

Mesh channel_mesh() {
  return make_rectangle_mesh({.length = 100.0, .width = 20.0, .nx = 10, .ny = 4});
}

TEST(LineSamplePoints, MidpointsOfEqualPieces) {
  const auto p = line_sample_points(Vec2(0, 0), Vec2(10, 20), 4);
  ASSERT_EQ(p.size(), 4u);
  EXPECT_NEAR(p[0].x(), 1.25, tolerance);
  EXPECT_NEAR(p[0].y(), 2.5, tolerance);
  EXPECT_NEAR(p[3].x(), 8.75, tolerance);
  EXPECT_NEAR(p[3].y(), 17.5, tolerance);
  EXPECT_THROW(line_sample_points(Vec2(0, 0), Vec2(1, 0), 0), std::invalid_argument);
}

TEST(MeanEtaAlong, LinearSurfaceAveragesToItsValueAtTheMidpoint) {
  const Mesh mesh = channel_mesh();
  const PointLocator locator(mesh);
  const auto eta = linear_eta(mesh, 10.0, 0.01, -0.02);
  // Midpoint (49.7, 9.9): 10 + 0.497 - 0.198.
  const double mean = mean_eta_along(mesh, locator, eta, Vec2(12.3, 1.1), Vec2(87.1, 18.7), 37);
  EXPECT_NEAR(mean, 10.299, tolerance);
}

TEST(MeanEtaAlong, PointsInAHoleAreLeftOut) {
  // The holey fixture's hole_1 is the square [2, 4] x [2, 5]. On x = 3 from y = 0 to 8 with 80
  // samples at y = 0.05, 0.15, ..., 7.95, those in (2, 5) are in the hole: 20 points below it
  // (mean y 1.0) and 30 above it (mean y 6.5) remain, so mean(eta = y) = (20 + 195) / 50 = 4.3.
  const Mesh mesh = fixtures::make_holey_mesh(2);
  const PointLocator locator(mesh);
  const auto eta = linear_eta(mesh, 0.0, 0.0, 1.0);
  EXPECT_NEAR(mean_eta_along(mesh, locator, eta, Vec2(3, 0), Vec2(3, 8), 80), 4.3, tolerance);
}

TEST(MeanEtaAlong, ALineOutsideTheDomainIsAnError) {
  const Mesh mesh = channel_mesh();
  const PointLocator locator(mesh);
  const auto eta = linear_eta(mesh, 10.0, 0.0, 0.0);
  EXPECT_THROW(mean_eta_along(mesh, locator, eta, Vec2(-5, 0), Vec2(-5, 20), 10),
               std::invalid_argument);
}

/// eta = 2 + 0.1 x + 0.3 y inside [0, 10] x [0, 10], nothing outside.
class LinearSurface : public FlowField {
 public:
  FlowSample sample(const Vec2& p, double /*t*/, int& /*hint*/) const override {
    FlowSample s;
    s.inside = p.x() >= 0 && p.x() <= 10 && p.y() >= 0 && p.y() <= 10;
    s.eta = 2.0 + 0.1 * p.x() + 0.3 * p.y();
    return s;
  }
  double time_begin() const override { return 0.0; }
  double time_end() const override { return 1.0; }
};

TEST(MeanEtaAlong, ThroughTheFlowFieldInterface) {
  const LinearSurface flow;
  // (1, 2) -> (9, 6), midpoint (5, 4): 2 + 0.5 + 1.2.
  EXPECT_NEAR(mean_eta_along(flow, 0.5, Vec2(1, 2), Vec2(9, 6), 16), 3.7, tolerance);
  // From (0, 5) to (20, 5) with 4 samples: x = 2.5, 7.5 inside, 12.5 and 17.5 outside.
  EXPECT_NEAR(mean_eta_along(flow, 0.5, Vec2(0, 5), Vec2(20, 5), 4), 2.0 + 0.5 + 1.5, tolerance);
}

/// A bridge across the 20 m wide channel at x whose piers reach 5 m, the section two diameters
/// upstream (as channel_bridges makes it).
JamGeometry one_bridge_at(double x) {
  JamGeometry g;
  Bridge bridge;
  bridge.name = "bridge_1";
  bridge.start = Vec2(x, 0.0);
  bridge.end = Vec2(x, 20.0);
  bridge.reach = 5.0;
  bridge.backwater_distance = 20.0;
  g.bridges.push_back(bridge);
  return g;
}

TEST(BackwaterProbe, SectionTwoPierDiametersUpstreamAcrossTheFullWidth) {
  const Mesh mesh = channel_mesh();
  const BackwaterProbe probe(mesh, one_bridge_at(60.0));
  ASSERT_EQ(probe.sections().size(), 1u);
  const auto& section = probe.sections()[0];
  EXPECT_EQ(section.bridge, "bridge_1");
  EXPECT_EQ(section.a, Vec2(40.0, 0.0));  // 60 - 2 * (2 * 5)
  EXPECT_EQ(section.b, Vec2(40.0, 20.0));
  EXPECT_EQ(section.locations.size(), 200u);
}

TEST(BackwaterProbe, RiseIsTheMeanSurfaceAboveTheReferenceWithoutBodies) {
  const Mesh mesh = channel_mesh();
  const BackwaterProbe probe(mesh, one_bridge_at(60.0));
  const auto with_bodies = linear_eta(mesh, 10.0, 0.01, 0.02);  // at x = 40: 10.4 + 0.02 y
  const auto reference = linear_eta(mesh, 10.0, 0.01, 0.0);     // at x = 40: 10.4
  const auto mean = probe.mean_eta(with_bodies);
  ASSERT_EQ(mean.size(), 1u);
  EXPECT_NEAR(mean[0], 10.6, tolerance);  // 10.4 + 0.02 * 10
  const auto rise = probe.rise(with_bodies, reference);
  ASSERT_EQ(rise.size(), 1u);
  EXPECT_NEAR(rise[0], 0.2, tolerance);
}

TEST(BackwaterProbe, ASectionOutsideTheMeshIsAnInputErrorNamingTheBridge) {
  const Mesh mesh = channel_mesh();
  try {
    const BackwaterProbe probe(mesh, one_bridge_at(10.0));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("the backwater section of bridge 'bridge_1', 20 m upstream "
                                    "of its axis, from (-10, 0) to (-10, 20) m, lies outside "
                                    "the mesh"));
  }
}

}  // namespace
}  // namespace flotsam
