#pragma once
// The integral over the mesh of a quantity of the FEM engine's state, f(x, u, eta, z_b), by the
// elements' quadrature with the P2 velocity and bed and the P1 elevation at each point (M-3):
// energy and angular momentum of the closed-basin verification cases.
#include "flow/fem/element_values.hpp"
#include "flow/fem/shallow_water_solver.hpp"

namespace flotsam::test {

/// f(const Vec2& x [m], const Vec2& u [m/s], double eta [m], double z_b [m]) -> the integrand.
template <class Integrand>
double integrate_flow(const ShallowWaterSolver& solver, Integrand f) {
  const Mesh& mesh = solver.mesh();
  double total = 0.0;
  ElementValues ev;
  for (int e = 0; e < mesh.element_count(); ++e) {
    compute_element_values(mesh, e, ev, false);
    const auto& el = mesh.elements[e];
    for (int q = 0; q < triangle_point_count; ++q) {
      Vec2 u = Vec2::Zero();
      double eta = 0.0, z_b = 0.0;
      for (int b = 0; b < 6; ++b) {
        u += ev.N2[q][b] * Vec2(solver.u()[el[b]], solver.v()[el[b]]);
        z_b += ev.N2[q][b] * solver.bed()[el[b]];
      }
      for (int j = 0; j < 3; ++j) eta += ev.N1[q][j] * solver.eta()[el[j]];
      total += f(ev.x[q], u, eta, z_b) * ev.JxW[q];
    }
  }
  return total;
}

}  // namespace flotsam::test
