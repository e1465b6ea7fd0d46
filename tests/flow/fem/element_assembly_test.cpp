// The element terms (src/flow/element_assembly.hpp) are Newton's linearisation of the element
// residual R(x) = K(x) x - F(x): K at x is dR/dx there. Checked column by column against central
// differences of R with every term on (advection, SUPG, Manning friction, wind, Coriolis,
// viscosity, theta-scheme), where the assembly must be exact to the differencing error; a missing
// derivative (of the SUPG weight, of the friction in the depth) shows as an O(1) column error.
#include <gtest/gtest.h>

#include <cmath>

#include "flow/fem/element_assembly.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

using LocalState = Eigen::Matrix<double, 15, 1>;

ElementState element_state(const LocalState& x, const Mesh& mesh, int e) {
  ElementState s;
  for (int a = 0; a < 6; ++a) {
    const Vec2& p = mesh.nodes[mesh.elements[e][a]];
    s.u_k[a] = x(local_velocity(a, 0));
    s.v_k[a] = x(local_velocity(a, 1));
    s.u_n[a] = s.u_d[a] = 0.8 + 0.01 * p.y();  // [m/s] a sheared flow at t^n
    s.v_n[a] = s.v_d[a] = 0.1 - 0.005 * p.x();
    s.z_b[a] = 0.02 * p.x() - 0.01 * p.y();  // [m]
    s.node_force[a] = Vec2(1e-3, -2e-3);     // [m s^-2]
  }
  for (int j = 0; j < 3; ++j) {
    s.eta_k[j] = x(local_elevation(j));
    s.eta_n[j] = s.eta_d[j] = 2.0 + 0.01 * j;
  }
  s.nu_e = 0.05;  // [m^2/s]
  return s;
}

LocalVector residual(const AssemblyParameters& p, const ElementValues& ev, const Mesh& mesh,
                     const LocalState& x) {
  LocalMatrix K;
  LocalVector F;
  assemble_element(p, ev, element_state(x, mesh, 0), K, F);
  return K * x - F;
}

TEST(ElementAssembly, MatrixIsTheJacobianOfTheResidual) {
  const Mesh mesh = make_rectangle_mesh({.length = 20.0, .width = 10.0, .nx = 2, .ny = 1});
  ElementValues ev;
  compute_element_values(mesh, 0, ev);
  AssemblyParameters p;
  p.theta = 0.6;
  p.inv_dt = 1.0 / 5.0;  // [1/s]
  p.coriolis = 1e-4;     // [1/s]
  p.wind_stress = Vec2(2e-3, -1e-3);
  p.friction = {FrictionLaw::manning, 0.03, 9.81, 1e-3};
  LocalState x;  // a non-uniform state: every term's derivative is exercised
  for (int a = 0; a < 6; ++a) {
    x(local_velocity(a, 0)) = 1.0 + 0.3 * a;
    x(local_velocity(a, 1)) = 0.4 - 0.2 * a;
  }
  for (int j = 0; j < 3; ++j) x(local_elevation(j)) = 2.1 - 0.05 * j;
  for (const bool supg : {false, true}) {
    p.supg = supg;
    LocalMatrix K;
    LocalVector F;
    assemble_element(p, ev, element_state(x, mesh, 0), K, F);
    for (int j = 0; j < 15; ++j) {
      const double h = 1e-6;
      LocalState plus = x, minus = x;
      plus(j) += h;
      minus(j) -= h;
      const LocalVector column =
          (residual(p, ev, mesh, plus) - residual(p, ev, mesh, minus)) / (2 * h);
      // Central differences: error ~ h^2 |R'''| + round-off |R| / h, about 1e-8 of the column.
      EXPECT_LE((column - K.col(j)).norm(), 1e-6 * K.col(j).norm())
          << "supg " << supg << ", column " << j;
    }
  }
}

}  // namespace
}  // namespace flotsam
