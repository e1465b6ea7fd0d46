// Verifies that the engine converges to a manufactured steady solution with advection, gravity,
// viscosity, Manning friction, Coriolis and wind all switched on (Roache 2002, method of
// manufactured solutions): on three nested meshes the observed L2 orders are at least 2.7 for
// the P2 velocity and 1.8 for the P1 elevation (issue 3 item 5). Exact solution on [0,1]^2:
//   u = 0.5 + 0.3 sin(pi x) sin(pi y),  v = 0.2 + 0.2 sin(pi x) sin(2 pi y),
//   eta = 1 + 0.05 sin(pi x / 2) cos(pi y),  z_b = 0.1 x y,
// velocity (0.5, 0.2) on the whole boundary and eta = 1 on the inflow side x = 0. (Eddy viscosity
// stays off: a per-element nu_t is itself an O(h^2) model error.)
#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "flow/fem/element_values.hpp"
#include "flow/fem/shallow_water_solver.hpp"
#include "flow/friction.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

constexpr double A = 0.3, B = 0.2, C = 0.05, nu = 0.01, g = 9.81, n_manning = 0.03;
const Vec2 wind(8.0, -4.0);  // [m/s]
const double f_coriolis = 2 * earth_rotation_rate * std::sin(pi / 4);

struct Exact {
  Vec2 u;
  Mat2 G;        // G(i, j) = d u_i / d x_j
  Vec2 viscous;  // Laplace u + grad div u
  double eta, H;
  Vec2 grad_eta, grad_H;
};

Exact exact(const Vec2& p) {
  const double x = p.x(), y = p.y();
  const double s1 = std::sin(pi * x), c1 = std::cos(pi * x), sy = std::sin(pi * y),
               cy = std::cos(pi * y), s2y = std::sin(2 * pi * y), c2y = std::cos(2 * pi * y);
  Exact e;
  e.u = Vec2(0.5 + A * s1 * sy, 0.2 + B * s1 * s2y);
  e.G << A * pi * c1 * sy, A * pi * s1 * cy, B * pi * c1 * s2y, 2 * B * pi * s1 * c2y;
  const double pp = pi * pi;
  const double u_xx = -A * pp * s1 * sy, u_yy = u_xx, u_xy = A * pp * c1 * cy;
  const double v_xx = -B * pp * s1 * s2y, v_yy = -4 * B * pp * s1 * s2y,
               v_xy = 2 * B * pp * c1 * c2y;
  e.viscous = Vec2(2 * u_xx + u_yy + v_xy, v_xx + 2 * v_yy + u_xy);
  e.eta = 1 + C * std::sin(pi * x / 2) * cy;
  e.grad_eta = Vec2(C * pi / 2 * std::cos(pi * x / 2) * cy, -C * pi * std::sin(pi * x / 2) * sy);
  e.H = e.eta - 0.1 * x * y;
  e.grad_H = e.grad_eta - Vec2(0.1 * y, 0.1 * x);
  return e;
}

// F_source = (u.grad)u + g grad eta - nu (Laplace u + grad div u) + gamma u - f (v, -u) - F_wind,
// S_source = div(H u): (M-1) with every term, solved for the source.
SourceTerms manufactured_source(const Vec2& p, double) {
  const Exact e = exact(p);
  FrictionModel friction{FrictionLaw::manning, n_manning, g, 1e-3};
  const double gamma = friction.rate(e.u.norm(), e.H);
  const Vec2 tau = air_density / 1000.0 * wind_drag_coefficient * wind.norm() * wind;
  SourceTerms s;
  s.momentum = e.G * e.u + g * e.grad_eta - nu * e.viscous + gamma * e.u -
               f_coriolis * Vec2(e.u.y(), -e.u.x()) - tau / e.H;
  s.continuity = e.grad_H.dot(e.u) + e.H * e.G.trace();
  return s;
}

struct Errors {
  double u, eta;  // L2 norms [m^2 s^-1], [m^2]
};

Errors solve_on(int cells) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 1.0, 1.0, cells, cells, true});
  Case c;
  c.flow.viscosity = nu;
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = n_manning;
  c.flow.coriolis = true;
  c.flow.latitude_deg = 45.0;
  c.flow.wind = wind;
  c.flow.initial_eta_start = c.flow.initial_eta_end = 1.0;
  for (const char* side : {"left", "right", "top", "bottom"})
    c.flow.boundaries.push_back(
        {BoundaryCondition::Kind::velocity, side, TimeSeries(0.5), TimeSeries(0.2)});
  c.flow.boundaries.push_back({BoundaryCondition::Kind::elevation, "left", TimeSeries(1.0), {}});
  FlowSolverOptions options;
  options.bed = [](const Vec2& p) { return 0.1 * p.x() * p.y(); };
  options.source = manufactured_source;
  ShallowWaterSolver solver(mesh, c, options);
  solver.initialize();
  // Start from the interpolated exact solution (the steady solve's Newton iterations then stay
  // in its basin of attraction).
  FlowState start;
  start.eta.resize(mesh.vertex_count);
  for (int j = 0; j < mesh.vertex_count; ++j) start.eta[j] = exact(mesh.nodes[j]).eta;
  for (const Vec2& p : mesh.nodes) {
    start.u.push_back(exact(p).u.x());
    start.v.push_back(exact(p).u.y());
  }
  solver.set_state(start);
  const SteadyReport report = solver.solve_steady();
  EXPECT_TRUE(report.converged);
  Errors err{0.0, 0.0};
  ElementValues ev;
  for (int e = 0; e < mesh.element_count(); ++e) {
    compute_element_values(mesh, e, ev);
    const auto& el = mesh.elements[e];
    for (int q = 0; q < triangle_point_count; ++q) {
      Vec2 u = Vec2::Zero();
      double eta = 0.0;
      for (int k = 0; k < 6; ++k) u += ev.N2[q][k] * Vec2(solver.u()[el[k]], solver.v()[el[k]]);
      for (int k = 0; k < 3; ++k) eta += ev.N1[q][k] * solver.eta()[el[k]];
      const Exact x = exact(ev.x[q]);
      err.u += (u - x.u).squaredNorm() * ev.JxW[q];
      err.eta += (eta - x.eta) * (eta - x.eta) * ev.JxW[q];
    }
  }
  return {std::sqrt(err.u), std::sqrt(err.eta)};
}

TEST(ManufacturedSolution, ConvergesAtTaylorHoodOrders) {
  const Errors e4 = solve_on(4), e8 = solve_on(8), e16 = solve_on(16);
  const double order_u_1 = std::log2(e4.u / e8.u), order_u_2 = std::log2(e8.u / e16.u);
  const double order_eta_1 = std::log2(e4.eta / e8.eta), order_eta_2 = std::log2(e8.eta / e16.eta);
  std::printf("MMS L2 u: %.3e %.3e %.3e orders %.2f %.2f\n", e4.u, e8.u, e16.u, order_u_1,
              order_u_2);
  std::printf("MMS L2 eta: %.3e %.3e %.3e orders %.2f %.2f\n", e4.eta, e8.eta, e16.eta, order_eta_1,
              order_eta_2);
  EXPECT_GE(order_u_2, 2.7);
  EXPECT_GE(order_eta_2, 1.8);
}

}  // namespace
}  // namespace flotsam
