// The P2 mass matrix (src/flow/mass_matrix.hpp): the L2 projection of a field that is already
// quadratic returns its nodal values. The load F_i = (N_i, f) is integrated with the same 7-point
// rule, exact for the degree-4 integrand on straight elements, so the nodal values come back to
// round-off: tolerance 1e-11 of the field's range.
#include <gtest/gtest.h>

#include <cmath>

#include "flow/fem/element_values.hpp"
#include "flow/fem/mass_matrix.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

double quadratic(const Vec2& p) {
  const double x = p.x(), y = p.y();
  return 1.0 + 2.0 * x - y + 0.5 * x * x + x * y - 0.25 * y * y;
}

TEST(P2MassMatrix, ProjectionOfAQuadraticFieldReturnsItsNodalValues) {
  const Mesh mesh = make_rectangle_mesh({.length = 3.0, .width = 2.0, .nx = 6, .ny = 5});
  std::vector<double> F(mesh.node_count(), 0.0);
  ElementValues ev;
  for (int e = 0; e < mesh.element_count(); ++e) {
    compute_element_values(mesh, e, ev);
    for (int q = 0; q < triangle_point_count; ++q)
      for (int a = 0; a < 6; ++a)
        F[mesh.elements[e][a]] += ev.N2[q][a] * quadratic(ev.x[q]) * ev.JxW[q];
  }
  P2MassMatrix(mesh).project(F);
  double error = 0.0;
  for (int i = 0; i < mesh.node_count(); ++i)
    error = std::max(error, std::abs(F[i] - quadratic(mesh.nodes[i])));
  EXPECT_LE(error, 1e-11 * 10.0);  // the field spans about 10 over the rectangle
}

}  // namespace
}  // namespace flotsam
