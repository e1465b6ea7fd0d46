// The element averages behind the eddy viscosity (src/flow/fem/turbulence.hpp): a linear
// velocity, bed and elevation are averaged exactly (their value at the centroid, their constant
// gradient), and the Smagorinsky viscosity of a pure shear is (C_s Delta)^2 |du/dy| (M-3).
#include <gtest/gtest.h>

#include <cmath>

#include "flow/fem/turbulence.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

TEST(ElementFlowAverage, OfLinearFieldsIsTheirCentroidValueAndGradient) {
  const Mesh mesh = make_rectangle_mesh({.length = 20.0, .width = 10.0, .nx = 2, .ny = 1});
  const int e = 1;
  ElementValues ev;
  compute_element_values(mesh, e, ev, false);
  // u = 0.2 + 0.03 x - 0.05 y, v = -0.1 + 0.02 x + 0.04 y [m/s]; z_b = 1 - 0.01 x,
  // eta = 3 + 0.002 y [m].
  auto u_at = [](const Vec2& p) { return 0.2 + 0.03 * p.x() - 0.05 * p.y(); };
  auto v_at = [](const Vec2& p) { return -0.1 + 0.02 * p.x() + 0.04 * p.y(); };
  auto z_at = [](const Vec2& p) { return 1.0 - 0.01 * p.x(); };
  auto eta_at = [](const Vec2& p) { return 3.0 + 0.002 * p.y(); };
  std::array<double, 6> u, v, z_b;
  std::array<double, 3> eta;
  Vec2 centroid = Vec2::Zero();
  for (int a = 0; a < 6; ++a) {
    const Vec2& p = mesh.nodes[mesh.elements[e][a]];
    u[a] = u_at(p);
    v[a] = v_at(p);
    z_b[a] = z_at(p);
    if (a < 3) {
      eta[a] = eta_at(p);
      centroid += p / 3.0;
    }
  }
  const ElementFlowAverage avg = element_flow_average(ev, u, v, z_b, eta);
  EXPECT_NEAR(avg.area, mesh.area[e], 1e-12 * mesh.area[e]);
  EXPECT_NEAR(avg.u.x(), u_at(centroid), 1e-13);
  EXPECT_NEAR(avg.u.y(), v_at(centroid), 1e-13);
  EXPECT_NEAR(avg.H, eta_at(centroid) - z_at(centroid), 1e-13);
  EXPECT_NEAR(avg.grad_u(0, 0), 0.03, 1e-13);   // du/dx [1/s]
  EXPECT_NEAR(avg.grad_u(0, 1), -0.05, 1e-13);  // du/dy
  EXPECT_NEAR(avg.grad_u(1, 0), 0.02, 1e-13);   // dv/dx
  EXPECT_NEAR(avg.grad_u(1, 1), 0.04, 1e-13);   // dv/dy
}

TEST(EddyViscosity, SmagorinskyOfAPureShear) {
  ElementFlowAverage shear;
  shear.area = 12.5;                                 // [m^2]
  shear.grad_u(0, 1) = 0.08;                         // du/dy [1/s]: 2 D:D = (du/dy)^2
  shear.H = 2.0;                                     // [m]
  const double C_s = 0.17;                           // [-]
  const double Delta = std::sqrt(2.0 * shear.area);  // [m]
  const FrictionModel friction{};
  EXPECT_NEAR(eddy_viscosity(TurbulenceModel::smagorinsky, C_s, friction, shear),
              C_s * Delta * C_s * Delta * 0.08, 1e-15);
  EXPECT_EQ(eddy_viscosity(TurbulenceModel::none, C_s, friction, shear), 0.0);
}

}  // namespace
}  // namespace flotsam
