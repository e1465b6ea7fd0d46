// Advection by characteristics (src/flow/characteristics.hpp) in the stagnation-point flow
// u = (c (x - x0), -c (y - y0)): a path through x over dt started at X = x0 + (x - x0) e^{-c dt},
// Y = y0 + (y - y0) e^{c dt}, and since u is linear its P2 interpolation is exact, so the
// departure values are u_d = (c (X - x0), -c (Y - y0)) up to the midpoint rule's error: sub-steps
// of half an element give about 4 (c dt/4)^3/6 ~ 1e-4 relative per path, up to 1.5e-4 of c L near
// the edges the paths come in through; tolerance 3e-4 of c L. Nodes whose path starts outside
// the domain take the velocity where the path enters it (checked: within the inflow's range).
#include <gtest/gtest.h>

#include <cmath>

#include "flow/characteristics.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

TEST(Characteristics, DepartureValuesOfAStagnationPointFlow) {
  const double L = 100.0, W = 60.0, c = 0.02, dt = 10.0;  // [m], [m], [1/s], [s]
  const Mesh mesh = make_rectangle_mesh({.length = L, .width = W, .nx = 20, .ny = 12});
  const double x0 = 0.5 * L, y0 = 0.5 * W;
  std::vector<double> u(mesh.node_count()), v(mesh.node_count()), u_d, v_d;
  for (int i = 0; i < mesh.node_count(); ++i) {
    u[i] = c * (mesh.nodes[i].x() - x0);
    v[i] = -c * (mesh.nodes[i].y() - y0);
  }
  const Characteristics characteristics(mesh);
  characteristics.advect(u, v, dt, u, v, u_d, v_d);
  int checked = 0;
  for (int i = 0; i < mesh.node_count(); ++i) {
    const double X = x0 + (mesh.nodes[i].x() - x0) * std::exp(-c * dt);
    const double Y = y0 + (mesh.nodes[i].y() - y0) * std::exp(c * dt);
    if (Y < 0.0 || Y > W) {  // the path enters through y = 0 or y = W: the value stays in range
      EXPECT_LE(std::abs(v_d[i]), c * 0.5 * W * (1 + 1e-12)) << "node " << i;
      continue;
    }
    EXPECT_NEAR(u_d[i], c * (X - x0), 3e-4 * c * L) << "node " << i;
    EXPECT_NEAR(v_d[i], -c * (Y - y0), 3e-4 * c * L) << "node " << i;
    ++checked;
  }
  EXPECT_GT(checked, mesh.node_count() / 2);
  EXPECT_GE(characteristics.max_substeps(), 1);
}

TEST(Characteristics, StillWaterStaysStill) {
  const Mesh mesh = make_rectangle_mesh({.length = 10.0, .width = 10.0, .nx = 3, .ny = 3});
  const std::vector<double> zero(mesh.node_count(), 0.0);
  std::vector<double> u_d, v_d;
  Characteristics(mesh).advect(zero, zero, 100.0, zero, zero, u_d, v_d);
  for (int i = 0; i < mesh.node_count(); ++i) {
    EXPECT_EQ(u_d[i], 0.0);
    EXPECT_EQ(v_d[i], 0.0);
  }
}

}  // namespace
}  // namespace flotsam

namespace flotsam {
namespace {

// The carried field is not the velocity: in a uniform flow (U, 0) the path from x is the
// straight segment back to x - U dt (the midpoint rule is exact), so a carried quadratic field
// q = (x^2, y) arrives as ((x - U dt)^2, y), to round-off (tolerance 1e-9 of q's range), at
// every node whose path stays inside.
TEST(Characteristics, CarriesAFieldOtherThanTheVelocity) {
  const double L = 100.0, W = 20.0, U = 1.5, dt = 12.0;  // [m], [m], [m/s], [s]
  const Mesh mesh = make_rectangle_mesh({.length = L, .width = W, .nx = 20, .ny = 4});
  std::vector<double> u(mesh.node_count(), U), v(mesh.node_count(), 0.0);
  std::vector<double> q_x(mesh.node_count()), q_y(mesh.node_count()), q_x_d, q_y_d;
  for (int i = 0; i < mesh.node_count(); ++i) {
    q_x[i] = mesh.nodes[i].x() * mesh.nodes[i].x();
    q_y[i] = mesh.nodes[i].y();
  }
  Characteristics(mesh).advect(u, v, dt, q_x, q_y, q_x_d, q_y_d);
  int checked = 0;
  for (int i = 0; i < mesh.node_count(); ++i) {
    const Vec2& p = mesh.nodes[i];
    if (p.x() < U * dt + 1e-9) continue;  // its path leaves through the inflow
    const double foot = p.x() - U * dt;
    EXPECT_NEAR(q_x_d[i], foot * foot, 1e-9 * L * L) << "node " << i;
    EXPECT_NEAR(q_y_d[i], p.y(), 1e-9 * L) << "node " << i;
    ++checked;
  }
  EXPECT_GT(checked, mesh.node_count() / 2);
}

}  // namespace
}  // namespace flotsam
