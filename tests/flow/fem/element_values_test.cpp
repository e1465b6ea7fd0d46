// The shape functions of one straight element (src/flow/element_values.hpp): the P2 Hessians
// reproduce the second derivatives of a quadratic exactly, the weights sum to the area, and
// leaving the Hessians out (the characteristics scheme, which has no SUPG) zeroes them and
// changes nothing else.
#include <gtest/gtest.h>

#include "flow/fem/element_values.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

TEST(ElementValues, HessiansOfAQuadraticAreExactAndCanBeLeftOut) {
  const Mesh mesh = make_rectangle_mesh({.length = 20.0, .width = 10.0, .nx = 2, .ny = 1});
  const int e = 1;
  ElementValues with, without;
  compute_element_values(mesh, e, with);
  compute_element_values(mesh, e, without, false);

  // f = a x^2 + b x y + c y^2 at the six nodes: its Hessian is [[2a, b], [b, 2c]] everywhere.
  const double a = 0.3, b = -1.1, c = 0.7;  // [1/m^2 of f]
  Mat2 hessian = Mat2::Zero();
  for (int k = 0; k < 6; ++k) {
    const Vec2& p = mesh.nodes[mesh.elements[e][k]];
    hessian += (a * p.x() * p.x() + b * p.x() * p.y() + c * p.y() * p.y()) * with.hessian2[k];
  }
  EXPECT_NEAR(hessian(0, 0), 2 * a, 1e-12);
  EXPECT_NEAR(hessian(0, 1), b, 1e-12);
  EXPECT_NEAR(hessian(1, 0), b, 1e-12);
  EXPECT_NEAR(hessian(1, 1), 2 * c, 1e-12);

  double area = 0.0;
  for (int q = 0; q < triangle_point_count; ++q) area += with.JxW[q];
  EXPECT_NEAR(area, mesh.area[e], 1e-12 * mesh.area[e]);

  for (int k = 0; k < 6; ++k) EXPECT_EQ(without.hessian2[k], Mat2::Zero());
  for (int q = 0; q < triangle_point_count; ++q) {
    EXPECT_EQ(without.JxW[q], with.JxW[q]);
    EXPECT_EQ(without.x[q], with.x[q]);
    for (int k = 0; k < 6; ++k) EXPECT_EQ(without.dN2[q][k], with.dN2[q][k]);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(without.dN1[q][k], with.dN1[q][k]);
  }
}

}  // namespace
}  // namespace flotsam
