// Verifies that sampling at a located point reproduces exactly the fields the elements can
// represent, with their gradients: linear fields with P1 and quadratic fields with P2 on straight
// elements; on curved (isoparametric) P2 elements, linear physical fields and every quadratic of
// the reference coordinates. (A quadratic of x, y is not in the isoparametric P2 space of a curved
// element: x(r, s) is quadratic, so x^2 is quartic in (r, s); its error there is O(h^3).)
#include "mesh/interpolation.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "holey_mesh.hpp"
#include "mesh/shape_functions.hpp"

namespace flotsam {
namespace {

using fixtures::make_curved_square_mesh;
using fixtures::make_holey_mesh;
using fixtures::map_to_element;

// f(x, y) = a + b x + c y + d x^2 + e x y + f y^2 and its gradient.
struct Quadratic {
  double a, b, c, d, e, f;
  double operator()(const Vec2& x) const {
    return a + b * x.x() + c * x.y() + d * x.x() * x.x() + e * x.x() * x.y() + f * x.y() * x.y();
  }
  Vec2 gradient(const Vec2& x) const {
    return {b + 2 * d * x.x() + e * x.y(), c + e * x.x() + 2 * f * x.y()};
  }
};

std::vector<double> nodal_values(const Mesh& mesh, const Quadratic& q, int count) {
  std::vector<double> values(count);
  for (int i = 0; i < count; ++i) values[i] = q(mesh.nodes[i]);
  return values;
}

// Random points inside the holey mesh, located from cold.
std::vector<Location> random_locations(const PointLocator& locator, std::vector<Vec2>& points) {
  std::mt19937 random(2024);
  std::uniform_real_distribution<double> x(0.0, 12.0), y(0.0, 8.0);
  std::vector<Location> locations;
  while (locations.size() < 2000) {
    const Vec2 p(x(random), y(random));
    const Location location = locator.locate(p);
    if (!location.inside) continue;
    points.push_back(p);
    locations.push_back(location);
  }
  return locations;
}

TEST(Interpolation, P1ReproducesLinearFieldsAndTheirGradients) {
  const Mesh mesh = make_holey_mesh(2);
  const PointLocator locator(mesh);
  const Quadratic f{1.5, 2.0, -3.0, 0, 0, 0}, g{-0.4, 0.25, 1.1, 0, 0, 0};
  const auto fx = nodal_values(mesh, f, mesh.vertex_count);
  const auto gx = nodal_values(mesh, g, mesh.vertex_count);
  std::vector<Vec2> points;
  const auto locations = random_locations(locator, points);
  const double tolerance = 1e-12 * 40;  // relative to |f| <= 40 over the domain
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec2& p = points[i];
    EXPECT_NEAR(interpolate_p1(mesh, locations[i], fx), f(p), tolerance);
    EXPECT_NEAR((gradient_p1(mesh, locations[i], fx) - f.gradient(p)).norm(), 0.0, tolerance);
    EXPECT_NEAR((interpolate_p1(mesh, locations[i], fx, gx) - Vec2(f(p), g(p))).norm(), 0.0,
                tolerance);
    Mat2 exact;
    exact.row(0) = f.gradient(p).transpose();
    exact.row(1) = g.gradient(p).transpose();
    EXPECT_NEAR((gradient_p1(mesh, locations[i], fx, gx) - exact).norm(), 0.0, tolerance);
  }
}

TEST(Interpolation, P2ReproducesQuadraticFieldsAndTheirGradientsOnStraightElements) {
  const Mesh mesh = make_holey_mesh(2);
  const PointLocator locator(mesh);
  const Quadratic f{1.0, 2.0, -3.0, 0.5, -1.2, 0.7}, g{-2.0, 0.3, 0.8, -0.25, 0.9, 0.15};
  const auto fx = nodal_values(mesh, f, mesh.node_count());
  const auto gx = nodal_values(mesh, g, mesh.node_count());
  std::vector<Vec2> points;
  const auto locations = random_locations(locator, points);
  const double tolerance = 1e-12 * 300;  // relative to |f| <= 300 over the domain
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec2& p = points[i];
    EXPECT_NEAR(interpolate_p2(mesh, locations[i], fx), f(p), tolerance);
    EXPECT_NEAR((gradient_p2(mesh, locations[i], fx) - f.gradient(p)).norm(), 0.0, tolerance);
    EXPECT_NEAR((interpolate_p2(mesh, locations[i], fx, gx) - Vec2(f(p), g(p))).norm(), 0.0,
                tolerance);
    Mat2 exact;  // grad(i, j) = d u_i / d x_j
    exact.row(0) = f.gradient(p).transpose();
    exact.row(1) = g.gradient(p).transpose();
    EXPECT_NEAR((gradient_p2(mesh, locations[i], fx, gx) - exact).norm(), 0.0, tolerance);
  }
}

TEST(Interpolation, P2IsExactOnCurvedElements) {
  const Mesh mesh = make_curved_square_mesh();
  const PointLocator locator(mesh);
  const Quadratic linear{0.3, 1.7, -0.9, 0, 0, 0};
  const auto lx = nodal_values(mesh, linear, mesh.node_count());
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0), value(-1.0, 1.0);
  std::vector<double> arbitrary(mesh.node_count());
  for (double& v : arbitrary) v = value(random);

  int tested = 0;
  for (int e = 0; e < mesh.element_count(); ++e) {
    if (!mesh.is_curved(e)) continue;
    for (int i = 0; i < 50; ++i, ++tested) {
      const double r = 0.1 + 0.7 * unit(random), s = 0.1 + (0.8 - r) * unit(random);
      const Vec2 p = map_to_element(mesh, e, r, s);
      const Location location = locator.locate(p);
      ASSERT_TRUE(location.inside && location.curved);
      ASSERT_EQ(location.element, e);

      // A linear physical field: the isoparametric element reproduces it, gradient included.
      EXPECT_NEAR(interpolate_p2(mesh, location, lx), linear(p), 1e-12);
      EXPECT_NEAR((gradient_p2(mesh, location, lx) - linear.gradient(p)).norm(), 0.0, 1e-12);

      // Any P2 field: its value is sum_k f_k N_k(r, s) at the (r, s) that maps to p ...
      const P2Values N = p2_values(r, s);
      double exact = 0;
      for (int k = 0; k < 6; ++k) exact += N[k] * arbitrary[mesh.elements[e][k]];
      EXPECT_NEAR(interpolate_p2(mesh, location, arbitrary), exact, 1e-12);

      // ... and its physical gradient that of the interpolated field (central differences,
      // truncation error ~ 1e-12 for a 1e-6 m step).
      const double h = 1e-6;  // [m]
      Vec2 differences;
      for (int j = 0; j < 2; ++j) {
        const Vec2 step = h * Vec2::Unit(j);
        const Location plus = locator.locate(p + step, e), minus = locator.locate(p - step, e);
        differences[j] =
            (interpolate_p2(mesh, plus, arbitrary) - interpolate_p2(mesh, minus, arbitrary)) /
            (2 * h);
      }
      EXPECT_NEAR((gradient_p2(mesh, location, arbitrary) - differences).norm(), 0.0, 1e-7);
    }
  }
  EXPECT_EQ(tested, 200);
}

}  // namespace
}  // namespace flotsam
