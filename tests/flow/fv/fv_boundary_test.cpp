// Unit tests of the finite-volume boundary conditions (flow/fv/fv_boundary.hpp): the ghost state
// each kind of condition puts outside a boundary edge, and how the case's conditions are matched
// to the mesh's groups.
#include <gtest/gtest.h>

#include <cmath>

#include "flow/fv/fv_boundary.hpp"
#include "fv_test_cases.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

using Kind = BoundaryCondition::Kind;

constexpr double g = 9.81;  // [m s^-2]
const Vec2 n(0.6, 0.8);     // outward unit normal of the edge
const FaceState inside{1.2, 0.3, 1.5, -0.5};

BoundaryCondition condition(Kind kind, TimeSeries value = TimeSeries(0.0),
                            TimeSeries value_y = TimeSeries(0.0)) {
  return {kind, "side", std::move(value), std::move(value_y)};
}

Vec2 velocity(const FaceState& s) {
  return {s.u, s.v};
}

TEST(FvBoundary, WallMirrorsTheNormalVelocityAndKeepsTheTangent) {
  for (Kind kind : {Kind::wall, Kind::noslip}) {
    const FaceState ghost = ghost_state(condition(kind), inside, n, 0.0, 0.0, g);
    EXPECT_EQ(ghost.h, inside.h);
    EXPECT_EQ(ghost.z, inside.z);
    EXPECT_NEAR(velocity(ghost).dot(n), -velocity(inside).dot(n), 1e-15);
    EXPECT_NEAR(velocity(ghost).dot(perp(n)), velocity(inside).dot(perp(n)), 1e-15);
  }
}

TEST(FvBoundary, ElevationSetsTheDepthAndKeepsTheOutgoingRiemannInvariant) {
  // eta_b(t) from 1.0 at t = 0 to 2.0 at t = 10 s: at t = 5 s, 1.5 m, so h = 1.5 - 0.3 = 1.2 m.
  // The characteristic leaving the domain carries u_n + 2 c: the ghost's equals the inside's;
  // the tangential velocity is the inside's.
  const BoundaryCondition bc = condition(Kind::elevation, TimeSeries({{0.0, 1.0}, {10.0, 2.0}}));
  FaceState lower = inside;
  lower.h = 0.8;  // below the boundary's level: water is pushed in
  const FaceState ghost = ghost_state(bc, lower, n, 5.0, 0.0, g);
  EXPECT_NEAR(ghost.h, 1.2, 1e-15);
  const double invariant = velocity(lower).dot(n) + 2.0 * std::sqrt(g * lower.h);
  EXPECT_NEAR(velocity(ghost).dot(n) + 2.0 * std::sqrt(g * ghost.h), invariant, 1e-14);
  EXPECT_LT(velocity(ghost).dot(n), velocity(lower).dot(n));  // a higher level outside: inflow
  EXPECT_NEAR(velocity(ghost).dot(perp(n)), velocity(lower).dot(perp(n)), 1e-15);
  // At the boundary's own level the ghost is the inside state.
  const FaceState level =
      ghost_state(condition(Kind::elevation, TimeSeries(1.5)), inside, n, 0.0, 0.0, g);
  EXPECT_NEAR(level.h, inside.h, 1e-15);
  EXPECT_NEAR(level.u, inside.u, 1e-14);
  EXPECT_NEAR(level.v, inside.v, 1e-14);
  // A supercritical outflow takes no condition: the inside state leaves as it is.
  FaceState fast = inside;
  fast.u = 6.0 * n.x(), fast.v = 6.0 * n.y();  // 6 m/s > c = 3.43 m/s
  const FaceState out = ghost_state(bc, fast, n, 5.0, 0.0, g);
  EXPECT_EQ(out.h, fast.h);
  EXPECT_EQ(out.u, fast.u);
  EXPECT_EQ(out.v, fast.v);
  // A level below the bed: dry ghost.
  const FaceState dry =
      ghost_state(condition(Kind::elevation, TimeSeries(0.1)), inside, n, 0.0, 0.0, g);
  EXPECT_EQ(dry.h, 0.0);
}

TEST(FvBoundary, DischargeEntersAtLeastAtCriticalDepth) {
  const double q = 0.3;                            // [m^2/s]
  const double h_critical = std::cbrt(q * q / g);  // [m] 0.2093
  FaceState shallow = inside;
  shallow.h = 0.01;
  const FaceState onto_dry = ghost_state(condition(Kind::discharge), shallow, n, 0.0, q, g);
  EXPECT_NEAR(onto_dry.h, h_critical, 1e-15);
  // The ghost carries q along the inward normal: h u = -q n.
  EXPECT_NEAR((onto_dry.h * velocity(onto_dry) + q * n).norm(), 0.0, 1e-15);
  // Froude number 1 at critical depth.
  EXPECT_NEAR(velocity(onto_dry).norm() / std::sqrt(g * onto_dry.h), 1.0, 1e-14);

  const FaceState deep = ghost_state(condition(Kind::discharge), inside, n, 0.0, q, g);
  EXPECT_EQ(deep.h, inside.h);
  EXPECT_NEAR((velocity(deep) + q / inside.h * n).norm(), 0.0, 1e-15);
}

TEST(FvBoundary, FreeCopiesTheInside) {
  const FaceState ghost = ghost_state(condition(Kind::free), inside, n, 3.0, 0.0, g);
  EXPECT_EQ(ghost.h, inside.h);
  EXPECT_EQ(ghost.z, inside.z);
  EXPECT_EQ(ghost.u, inside.u);
  EXPECT_EQ(ghost.v, inside.v);
}

TEST(FvBoundary, VelocityImposesItsValueAtTheTime) {
  const BoundaryCondition bc =
      condition(Kind::velocity, TimeSeries({{0.0, 0.0}, {10.0, 1.0}}), TimeSeries(-0.25));
  const FaceState ghost = ghost_state(bc, inside, n, 4.0, 0.0, g);
  EXPECT_NEAR(ghost.u, 0.4, 1e-15);
  EXPECT_EQ(ghost.v, -0.25);
  EXPECT_EQ(ghost.h, inside.h);
}

TEST(FvBoundary, ResolveMatchesConditionsToGroupsAndLeavesTheOthersWalls) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 10.0, 4.0, 5, 2, true});
  FlowConfig flow;
  flow.boundaries = {{Kind::discharge, "left", TimeSeries(1.0), TimeSeries(0.0)},
                     {Kind::elevation, "right", TimeSeries(1.0), TimeSeries(0.0)}};
  const FvBoundaries b = FvBoundaries::resolve(mesh, flow);
  ASSERT_EQ(b.group_condition.size(), mesh.group_names.size());
  EXPECT_EQ(b.group_condition[mesh.find_group("left")], 0);
  EXPECT_EQ(b.group_condition[mesh.find_group("right")], 1);
  EXPECT_EQ(b.group_condition[mesh.find_group("bottom")], -1);
  EXPECT_EQ(b.group_condition[mesh.find_group("top")], -1);
}

}  // namespace
}  // namespace flotsam
