// Verifies the scene's helpers: the clock format, the colour range rules, boundary kinds by
// name and by boundary condition, the body categories taken from a BodySet, and the boundary
// loops (a hole runs clockwise with minus its area).
#include "render/scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "../mesh/holey_mesh.hpp"
#include "bodies/body_set.hpp"
#include "mesh/structured_mesh.hpp"
#include "render/annotations.hpp"
#include "render/boundary_layer.hpp"
#include "render/colour_bar.hpp"
#include "render/derived_fields.hpp"

namespace flotsam {
namespace {

TEST(Scene, ClockIsHoursMinutesSeconds) {
  EXPECT_EQ(format_clock(0.0), "0:00:00");
  EXPECT_EQ(format_clock(3725.4), "1:02:05");
  EXPECT_EQ(format_clock(59.6), "0:01:00");  // rounded to the second
  EXPECT_EQ(format_clock(36000.0), "10:00:00");
  EXPECT_EQ(format_clock(-5.0), "-0:00:05");
}

struct Square {
  Mesh mesh = make_rectangle_mesh({.length = 2.0, .width = 1.0, .nx = 2, .ny = 1});
  Scene scene;
  Square(const Square&) = delete;
  Square() {
    scene.mesh = &mesh;
    for (int v = 0; v < mesh.vertex_count; ++v) {
      scene.field.values.push_back(mesh.nodes[v].x() - 0.5);  // [-0.5, 1.5]
    }
  }
};

TEST(Scene, DataRangeIsTheFieldsExtremesInTheWindow) {
  Square square;
  const auto [lo, hi] = resolve_colour_range(square.scene, {-1, 3, -1, 2});
  EXPECT_DOUBLE_EQ(lo, -0.5);
  EXPECT_DOUBLE_EQ(hi, 1.5);
  // Only the vertices at x = 1 and x = 2 are in this window.
  const auto [lo2, hi2] = resolve_colour_range(square.scene, {0.9, 3, -1, 2});
  EXPECT_DOUBLE_EQ(lo2, 0.5);
  EXPECT_DOUBLE_EQ(hi2, 1.5);
}

TEST(Scene, SymmetricRangeIsPlusMinusTheLargestMagnitude) {
  Square square;
  square.scene.range.kind = ColourRange::Kind::symmetric;
  const auto [lo, hi] = resolve_colour_range(square.scene, {-1, 3, -1, 2});
  EXPECT_DOUBLE_EQ(lo, -1.5);
  EXPECT_DOUBLE_EQ(hi, 1.5);
}

TEST(Scene, FixedRangeIsKeptAndConstantFieldWidened) {
  Square square;
  square.scene.range = {ColourRange::Kind::fixed, -2.0, 4.0};
  EXPECT_EQ(resolve_colour_range(square.scene, {-1, 3, -1, 2}), std::pair(-2.0, 4.0));
  square.scene.range = {};
  square.scene.field.values.assign(square.mesh.vertex_count, 10.0);
  EXPECT_EQ(resolve_colour_range(square.scene, {-1, 3, -1, 2}), std::pair(9.5, 10.5));
  square.scene.field.values.assign(square.mesh.vertex_count, 0.0);
  EXPECT_EQ(resolve_colour_range(square.scene, {-1, 3, -1, 2}), std::pair(-1.0, 1.0));
}

TEST(Scene, NanValuesAreLeftOutOfTheRange) {
  Square square;
  square.scene.field.values[0] = std::numeric_limits<double>::quiet_NaN();  // vertex (0, 0)
  const auto [lo, hi] = resolve_colour_range(square.scene, {-1, 3, -1, 2});
  EXPECT_DOUBLE_EQ(lo, -0.5);  // vertex (0, 1) still has -0.5
  EXPECT_DOUBLE_EQ(hi, 1.5);
}

TEST(Scene, BoundaryKindsByNameAndByCondition) {
  EXPECT_EQ(default_boundary_kind("inflow"), BoundaryKind::open);
  EXPECT_EQ(default_boundary_kind("outflow"), BoundaryKind::open);
  EXPECT_EQ(default_boundary_kind("bank_left"), BoundaryKind::wall);
  EXPECT_EQ(default_boundary_kind("pier_1"), BoundaryKind::wall);
  const Mesh mesh = make_rectangle_mesh({});  // groups left, right, bottom, top
  BoundaryCondition left;
  left.group = "left";
  left.kind = BoundaryCondition::Kind::discharge;
  BoundaryCondition right;
  right.group = "right";
  right.kind = BoundaryCondition::Kind::elevation;
  BoundaryCondition top;
  top.group = "top";
  top.kind = BoundaryCondition::Kind::noslip;
  const std::vector<BoundaryCondition> conditions{left, right, top};
  const auto kinds = boundary_kinds(mesh, conditions);
  ASSERT_EQ(kinds.size(), mesh.group_names.size());
  EXPECT_EQ(kinds[mesh.find_group("left")], BoundaryKind::open);
  EXPECT_EQ(kinds[mesh.find_group("right")], BoundaryKind::open);
  EXPECT_EQ(kinds[mesh.find_group("top")], BoundaryKind::wall);
  EXPECT_EQ(kinds[mesh.find_group("bottom")], BoundaryKind::wall);  // by name
}

TEST(Scene, BodyCategoriesFollowStateAndJamFlags) {
  BodySet set;
  for (int i = 0; i < 4; ++i) {
    set.position.push_back(Vec2(i, 0.0));
    set.angle.push_back(0.1 * i);
    set.length.push_back(10.0);
    set.width.push_back(1.0);
  }
  set.state = {BodyState::floating, BodyState::grounded, BodyState::floating, BodyState::gone};
  const std::vector<std::uint8_t> jammed{0, 0, 1, 1};
  const SceneBodies bodies = scene_bodies(set, jammed);
  ASSERT_EQ(bodies.size(), 4);
  EXPECT_EQ(bodies.category[0], BodyCategory::floating);
  EXPECT_EQ(bodies.category[1], BodyCategory::grounded);
  EXPECT_EQ(bodies.category[2], BodyCategory::jammed);
  EXPECT_EQ(bodies.category[3], BodyCategory::gone);  // gone wins over a stale jam flag
  EXPECT_DOUBLE_EQ(bodies.angle[2], 0.2);
  EXPECT_EQ(scene_bodies(set).category[2], BodyCategory::floating);
}

TEST(BoundaryLoops, RectangleIsOneCounterClockwiseLoop) {
  const Mesh mesh = make_rectangle_mesh({.length = 3.0, .width = 2.0, .nx = 3, .ny = 2});
  const auto loops = boundary_loops(mesh);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].edges.size(), 10u);
  EXPECT_NEAR(loops[0].signed_area, 6.0, 1e-12);
  EXPECT_FALSE(loops[0].is_hole());
}

TEST(BoundaryLoops, HolesRunClockwiseWithMinusTheirArea) {
  const Mesh mesh = build_mesh(fixtures::make_holey_raw(2));
  const auto loops = boundary_loops(mesh);
  ASSERT_EQ(loops.size(), 4u);  // the outside and three holes
  int holes = 0;
  double total = 0.0;  // [m^2] outer area minus the holes: the mesh's area
  for (const auto& loop : loops) {
    holes += loop.is_hole();
    total += loop.signed_area;
  }
  EXPECT_EQ(holes, 3);
  double mesh_area = 0.0;
  for (const double a : mesh.area) mesh_area += a;
  EXPECT_NEAR(total, mesh_area, 1e-9);
  // The square hole [2, 4] x [2, 5]: the loop made of group hole_1's edges.
  const int hole_1 = mesh.find_group("hole_1");
  for (const auto& loop : loops) {
    if (mesh.boundary[loop.edges[0]].group == hole_1) {
      EXPECT_NEAR(loop.signed_area, -6.0, 1e-12);
    }
  }
}

TEST(ColourBar, TicksAreRoundAndInsideTheRange) {
  const auto unit = nice_ticks(0.0, 1.0, 5);  // step 0.2
  ASSERT_EQ(unit.size(), 6u);
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(unit[k], 0.2 * k, 1e-15);
  const auto ticks = nice_ticks(9.67, 10.0, 6);  // step 0.05
  ASSERT_EQ(ticks.size(), 7u);                   // 9.70, 9.75, ..., 10.00
  EXPECT_NEAR(ticks.front(), 9.70, 1e-12);
  EXPECT_NEAR(ticks.back(), 10.0, 1e-12);
  EXPECT_DOUBLE_EQ(nice_step(0.33, 6), 0.05);
  EXPECT_DOUBLE_EQ(nice_step(700.0, 5), 100.0);
  EXPECT_DOUBLE_EQ(nice_step(3.0, 5), 0.5);
  EXPECT_EQ(format_tick(0.25, 0.05), "0.25");
  EXPECT_EQ(format_tick(-3.0, 1.0), "-3");
  EXPECT_EQ(format_tick(0.0, 0.0002), "0");
  EXPECT_EQ(format_tick(0.0004, 0.0002), "0.0004");
  EXPECT_EQ(format_tick(9.8, 0.05), "9.80");
  EXPECT_EQ(format_tick(2.0e6, 5.0e5), "2e+06");
}

TEST(Annotations, ScaleBarIsARoundLength) {
  EXPECT_DOUBLE_EQ(scale_bar_length(370.0), 200.0);
  EXPECT_DOUBLE_EQ(scale_bar_length(99.0), 50.0);
  EXPECT_DOUBLE_EQ(scale_bar_length(0.12), 0.1);
  EXPECT_EQ(format_distance(200.0), "200 m");
  EXPECT_EQ(format_distance(2000.0), "2 km");
  EXPECT_EQ(format_distance(0.5), "0.5 m");
}

TEST(DerivedFields, SpeedAndVorticityOfASolidBodyRotation) {
  // u = Omega (-y, x): |u| = Omega r, vorticity 2 Omega everywhere, exact for the P2 field.
  const Mesh mesh =
      make_rectangle_mesh({.x0 = -1, .y0 = -1, .length = 2, .width = 2, .nx = 3, .ny = 3});
  const double Omega = 0.7;  // [1/s]
  std::vector<double> u_x, u_y;
  for (const Vec2& p : mesh.nodes) {
    u_x.push_back(-Omega * p.y());
    u_y.push_back(Omega * p.x());
  }
  const auto speed = speed_field(u_x, u_y);
  for (int k = 0; k < mesh.node_count(); ++k) {
    EXPECT_NEAR(speed[k], Omega * mesh.nodes[k].norm(), 1e-14);
  }
  const auto omega = vorticity_at_vertices(mesh, u_x, u_y);
  ASSERT_EQ(omega.size(), static_cast<std::size_t>(mesh.vertex_count));
  for (const double w : omega) EXPECT_NEAR(w, 2 * Omega, 1e-12);
}

TEST(DerivedFields, VorticityOfAQuadraticShearIsExactAtVertices) {
  // u = (y^2, 0): vorticity -2 y, the P2 field's gradient is exact and continuous at vertices.
  const Mesh mesh = make_rectangle_mesh({.length = 2, .width = 2, .nx = 4, .ny = 4});
  std::vector<double> u_x, u_y(mesh.node_count(), 0.0);
  for (const Vec2& p : mesh.nodes) u_x.push_back(p.y() * p.y());
  const auto omega = vorticity_at_vertices(mesh, u_x, u_y);
  for (int v = 0; v < mesh.vertex_count; ++v) {
    EXPECT_NEAR(omega[v], -2 * mesh.nodes[v].y(), 1e-12) << "vertex " << v;
  }
}

}  // namespace
}  // namespace flotsam
