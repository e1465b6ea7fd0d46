// Unit tests of summarize_mesh and format_mesh_summary on meshes whose statistics are known in
// closed form: a structured rectangle, one equilateral triangle, one curved element.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesh/mesh_summary.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

using ::testing::HasSubstr;

TEST(MeshSummary, RectangleCountsLengthsSizesAndQuality) {
  // 4 m x 2 m in 8 x 4 cells of 0.5 m: right isosceles triangles with legs a = 0.5 m, longest
  // edge a sqrt(2), quality 4 sqrt(3) (a^2/2) / (4 a^2) = sqrt(3)/2.
  const Mesh mesh = make_rectangle_mesh({.length = 4, .width = 2, .nx = 8, .ny = 4});
  const MeshSummary s = summarize_mesh(mesh);
  EXPECT_EQ(s.element_count, 64);
  EXPECT_EQ(s.vertex_count, 45);
  EXPECT_EQ(s.node_count, 45 + (3 * 64 + 24) / 2);
  EXPECT_EQ(s.curved_element_count, 0);
  EXPECT_NEAR(s.total_area, 8.0, 1e-12);
  EXPECT_NEAR(s.min_element_size, 0.5 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(s.max_element_size, 0.5 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(s.min_quality, std::sqrt(3.0) / 2, 1e-12);
  EXPECT_NEAR(s.mean_quality, std::sqrt(3.0) / 2, 1e-12);
  ASSERT_EQ(s.groups.size(), 4u);  // bottom, left, right, top
  const double lengths[] = {4, 2, 2, 4}, edges[] = {8, 4, 4, 8};
  for (int g = 0; g < 4; ++g) {
    EXPECT_EQ(s.groups[g].name, mesh.group_names[g]);
    EXPECT_NEAR(s.groups[g].length, lengths[g], 1e-12) << s.groups[g].name;
    EXPECT_EQ(s.groups[g].edge_count, edges[g]) << s.groups[g].name;
  }
  EXPECT_EQ(s.lower_corner, Vec2(0, 0));
  EXPECT_EQ(s.upper_corner, Vec2(4, 2));
}

Mesh one_triangle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& mid_bc) {
  RawMesh raw;
  raw.source = "one";
  raw.nodes = {a, b, c, 0.5 * (a + b), mid_bc, 0.5 * (c + a)};
  raw.triangles = {{0, 1, 2, 3, 4, 5}};
  raw.lines = {{{0, 1}, "wall", 1}, {{1, 2, 4}, "wall", 2}, {{2, 0}, "wall", 3}};
  return build_mesh(raw);
}

TEST(MeshSummary, EquilateralTriangleHasQualityOne) {
  const Vec2 a(0, 0), b(2, 0), c(1, std::sqrt(3.0));
  const MeshSummary s = summarize_mesh(one_triangle(a, b, c, 0.5 * (b + c)));
  EXPECT_NEAR(s.min_quality, 1.0, 1e-14);
  EXPECT_NEAR(s.max_element_size, 2.0, 1e-14);
  EXPECT_NEAR(s.total_area, std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(s.groups[0].length, 6.0, 1e-14);
}

TEST(MeshSummary, CurvedEdgeAddsTheParabolicSegment) {
  // Mid node of edge (1,0)-(0,1) pushed out by delta along the normal: the P2 edge is a
  // parabola and the area grows by its segment, (2/3) chord delta (Archimedes).
  const double delta = 0.1, chord = std::sqrt(2.0);
  const Vec2 normal = Vec2(1, 1) / chord;
  const Mesh mesh = one_triangle({0, 0}, {1, 0}, {0, 1}, Vec2(0.5, 0.5) + delta * normal);
  const MeshSummary s = summarize_mesh(mesh);
  EXPECT_EQ(s.curved_element_count, 1);
  EXPECT_NEAR(s.total_area, 0.5 + 2.0 / 3.0 * chord * delta, 1e-14);
  // Quality and size use the straight triangle.
  EXPECT_NEAR(s.max_element_size, chord, 1e-14);
  EXPECT_NEAR(s.min_quality, 4 * std::sqrt(3.0) * 0.5 / 4, 1e-14);
}

TEST(MeshSummary, ParabolicEdgeLength) {
  // y = x^2 / 4 on [-1, 1] through (-1, 1/4), (0, 0), (1, 1/4): length
  // integral sqrt(1 + x^2/4) dx = sqrt(5)/2 + 2 asinh(1/2). 5-point Gauss on this smooth
  // integrand is accurate to ~1e-7.
  const double exact = std::sqrt(5.0) / 2 + 2 * std::asinh(0.5);
  EXPECT_NEAR(p2_edge_length({-1, 0.25}, {1, 0.25}, {0, 0}), exact, 1e-6 * exact);
  EXPECT_DOUBLE_EQ(p2_edge_length({0, 0}, {3, 4}, {1.5, 2}), 5.0);
}

TEST(MeshSummary, FormatIsAnAlignedTableWithUnits) {
  const Mesh mesh = make_rectangle_mesh({.length = 4, .width = 2, .nx = 8, .ny = 4});
  const std::string text = format_mesh_summary(summarize_mesh(mesh));
  EXPECT_THAT(text, HasSubstr("nodes          153 (45 vertices, 108 mid nodes)\n"));
  EXPECT_THAT(text, HasSubstr("elements       64 six-node triangles (0 curved)\n"));
  EXPECT_THAT(text, HasSubstr("area           8 m^2\n"));
  EXPECT_THAT(text, HasSubstr("element size   0.7071 .. 0.7071 m (longest edge)\n"));
  EXPECT_THAT(text, HasSubstr("quality        min 0.866, mean 0.866 (1 = equilateral)\n"));
  EXPECT_THAT(text, HasSubstr("  group     edges    length [m]\n"
                              "  bottom        8             4\n"
                              "  left          4             2\n"));
}

}  // namespace
}  // namespace flotsam
