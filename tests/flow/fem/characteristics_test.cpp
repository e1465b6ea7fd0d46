// Advection by characteristics (src/flow/characteristics.hpp) in the stagnation-point flow
// u = (c (x - x0), -c (y - y0)): a path through x over dt started at X = x0 + (x - x0) e^{-c dt},
// Y = y0 + (y - y0) e^{c dt}, and since u is linear its P2 interpolation is exact, so the
// departure values are u_d = (c (X - x0), -c (Y - y0)) up to the midpoint rule's error: sub-steps
// of half an element give about 4 (c dt/4)^3/6 ~ 1e-4 relative per path, up to 1.5e-4 of c L near
// the edges the paths come in through; tolerance 3e-4 of c L. Nodes whose path starts outside
// the domain take the velocity where the path enters it (checked: within the inflow's range).
#include <gtest/gtest.h>

#include <cmath>

#include "flow/fem/characteristics.hpp"
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

// A velocity linear in time: uniform U_before at t^{n-1} = t^n - dt_before and U at t^n, so
// w(t) = U + (t - t^n) (U - U_before) / dt_before, extrapolated to t^{n+1} = t^n + dt. The path
// from x is straight, and the midpoint rule integrates a velocity linear in time exactly: the
// foot at lag tau is x - integral over [t^{n+1} - tau, t^{n+1}] of w. The carried fields
// q = (x^2, y) (at t^n) and (x, x y) (at t^{n-1}) must arrive at their feet to round-off
// (tolerance 1e-9 of their range) at every node whose path stays inside.
TEST(Characteristics, PathsOfAVelocityLinearInTimeReachBothFeet) {
  const double L = 100.0, W = 20.0, U = 1.5, U_before = 0.5;  // [m], [m], [m/s], [m/s]
  const double dt = 8.0, dt_before = 4.0;                     // [s]
  const Mesh mesh = make_rectangle_mesh({.length = L, .width = W, .nx = 20, .ny = 4});
  const int n = mesh.node_count();
  const std::vector<double> u(n, U), u_before(n, U_before), zero(n, 0.0);
  std::vector<double> a_x(n), a_y(n), b_x(n), b_y(n), a_x_d, a_y_d, b_x_d, b_y_d;
  for (int i = 0; i < n; ++i) {
    const Vec2& p = mesh.nodes[i];
    a_x[i] = p.x() * p.x();
    a_y[i] = p.y();
    b_x[i] = p.x();
    b_y[i] = p.x() * p.y();
  }
  const Foot feet[2] = {{dt, a_x, a_y, a_x_d, a_y_d}, {dt + dt_before, b_x, b_y, b_x_d, b_y_d}};
  Characteristics(mesh).advect(PathVelocity{u, zero, u_before, zero, dt_before}, dt, feet);
  // Distance travelled back from t^{n+1} to t^n - s [m]: the integral of w from t^n - s to
  // t^n + dt, w(t^n + r) = U + r (U - U_before) / dt_before.
  const double a = (U - U_before) / dt_before;  // [m s^-2]
  const auto travelled = [&](double s) { return U * (dt + s) + 0.5 * a * (dt * dt - s * s); };
  int checked = 0;
  for (int i = 0; i < n; ++i) {
    const Vec2& p = mesh.nodes[i];
    const double foot_n = p.x() - travelled(0.0), foot_before = p.x() - travelled(dt_before);
    if (foot_before < 1e-9) continue;  // its path leaves through the inflow
    EXPECT_NEAR(a_x_d[i], foot_n * foot_n, 1e-9 * L * L) << "node " << i;
    EXPECT_NEAR(a_y_d[i], p.y(), 1e-9 * W) << "node " << i;
    EXPECT_NEAR(b_x_d[i], foot_before, 1e-9 * L) << "node " << i;
    EXPECT_NEAR(b_y_d[i], foot_before * p.y(), 1e-9 * L * W) << "node " << i;
    ++checked;
  }
  EXPECT_GT(checked, n / 4);
}

}  // namespace
}  // namespace flotsam
