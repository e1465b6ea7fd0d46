// Unit tests of build_mesh: numbering, adjacency, mid nodes, boundary groups, and every rejected
// input with the message it gives.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "mesh/mesh.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

using ::testing::HasSubstr;

std::string error_of(const RawMesh& raw) {
  try {
    build_mesh(raw);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

RawMesh two_triangles() {
  RawMesh raw;
  raw.source = "two.msh";
  raw.nodes = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  raw.node_tags = {11, 12, 13, 14};
  raw.triangles = {{0, 1, 2}, {0, 2, 3}};
  raw.triangle_tags = {101, 102};
  raw.lines = {
      {{0, 1}, "bottom", 1}, {{1, 2}, "right", 2}, {{2, 3}, "top", 3}, {{3, 0}, "left", 4}};
  return raw;
}

TEST(MeshBuilder, CountsAndEulerFormulaOnARectangle) {
  const Mesh mesh = make_rectangle_mesh({.length = 4, .width = 2, .nx = 8, .ny = 4});
  EXPECT_EQ(mesh.element_count(), 64);
  EXPECT_EQ(mesh.vertex_count, 9 * 5);
  // P2 nodes = vertices + edges; edges = (3 T + boundary edges) / 2.
  const int boundary_edges = 2 * (8 + 4);
  EXPECT_EQ(static_cast<int>(mesh.boundary.size()), boundary_edges);
  EXPECT_EQ(mesh.node_count(), mesh.vertex_count + (3 * 64 + boundary_edges) / 2);
  double total_area = 0;
  for (double a : mesh.area) total_area += a;
  EXPECT_NEAR(total_area, 8.0, 1e-12);
  EXPECT_EQ(mesh.group_names, (std::vector<std::string>{"bottom", "left", "right", "top"}));
}

TEST(MeshBuilder, AdjacencyIsSymmetricAndMidNodesAreShared) {
  const Mesh mesh = make_rectangle_mesh({.length = 3, .width = 2, .nx = 6, .ny = 5});
  for (int e = 0; e < mesh.element_count(); ++e)
    for (int k = 0; k < 3; ++k) {
      const int n = mesh.neighbours[e][k];
      const auto nodes = mesh.edge_nodes(e, k);
      EXPECT_NEAR(
          (mesh.nodes[nodes[2]] - 0.5 * (mesh.nodes[nodes[0]] + mesh.nodes[nodes[1]])).norm(), 0.0,
          1e-14);
      if (Mesh::is_boundary(n)) {
        const auto& b = mesh.boundary[Mesh::boundary_edge_of(n)];
        EXPECT_EQ(b.element, e);
        EXPECT_EQ(b.local_edge, k);
        continue;
      }
      int back = -1;
      for (int j = 0; j < 3; ++j)
        if (mesh.neighbours[n][j] == e) back = j;
      ASSERT_GE(back, 0) << "element " << n << " does not point back to " << e;
      EXPECT_EQ(mesh.elements[n][3 + back], mesh.elements[e][3 + k]);
    }
}

TEST(MeshBuilder, VerticesComeFirstAndAreaIsHalfJacobian) {
  const Mesh mesh = build_mesh(two_triangles());
  EXPECT_EQ(mesh.vertex_count, 4);
  EXPECT_EQ(mesh.node_count(), 4 + 5);
  for (int e = 0; e < 2; ++e) {
    for (int k = 0; k < 3; ++k) EXPECT_LT(mesh.elements[e][k], 4);
    for (int k = 3; k < 6; ++k) EXPECT_GE(mesh.elements[e][k], 4);
    EXPECT_DOUBLE_EQ(mesh.area[e], 0.5);
    EXPECT_DOUBLE_EQ(mesh.jacobian(e).determinant(), 1.0);
  }
  EXPECT_EQ(mesh.node_tags[0], 11);
}

TEST(MeshBuilder, ThreeNodeLineGivesTheCurvedMidNode) {
  RawMesh raw = two_triangles();
  raw.nodes.push_back({0.5, -0.1});  // on a (pretend) curve below the bottom edge
  raw.node_tags.push_back(15);
  raw.lines[0].nodes = {0, 1, 4};
  const Mesh mesh = build_mesh(raw);
  // Element 101's local edge 0 is the bottom (elements are found by tag: build_mesh numbers
  // them along a curve).
  const int e101 = mesh.element_tags[0] == 101 ? 0 : 1;
  ASSERT_EQ(mesh.element_tags[e101], 101);
  const int mid = mesh.elements[e101][3];
  EXPECT_DOUBLE_EQ(mesh.nodes[mid].y(), -0.1);
  EXPECT_TRUE(mesh.is_curved(e101));
  EXPECT_FALSE(mesh.is_curved(1 - e101));
}

TEST(MeshBuilder, RejectsAnInvertedElementNamingIt) {
  RawMesh raw = two_triangles();
  raw.triangles[1] = {0, 3, 2};
  EXPECT_THAT(error_of(raw), HasSubstr("two.msh: element 102 is inverted"));
}

TEST(MeshBuilder, RejectsADegenerateElementNamingIt) {
  RawMesh raw = two_triangles();
  raw.nodes[3] = {0.5, 0.5};  // on the diagonal 0-2
  EXPECT_THAT(error_of(raw), HasSubstr("two.msh: element 102 is degenerate"));
}

TEST(MeshBuilder, RejectsAnUnusedNodeNamingIt) {
  RawMesh raw = two_triangles();
  raw.nodes.push_back({5, 5});
  raw.node_tags.push_back(99);
  EXPECT_THAT(error_of(raw), HasSubstr("two.msh: node 99 is not used by any triangle"));
}

TEST(MeshBuilder, RejectsANonManifoldEdgeNamingItsElements) {
  RawMesh raw = two_triangles();
  raw.nodes.push_back({2, 0.5});
  raw.node_tags.push_back(16);
  raw.triangles.push_back({0, 4, 2});  // a third triangle on edge 0-2
  raw.triangle_tags.push_back(103);
  EXPECT_THAT(error_of(raw), HasSubstr("shared by more than two elements (101, 102 and 103)"));
}

TEST(MeshBuilder, RejectsABoundaryEdgeWithoutAName) {
  RawMesh raw = two_triangles();
  raw.lines[1].group = "";
  EXPECT_THAT(error_of(raw),
              HasSubstr("two.msh: the boundary edge between nodes 12 and 13 (element 101) belongs "
                        "to no named physical group"));
  raw.lines.erase(raw.lines.begin() + 1);
  EXPECT_THAT(error_of(raw), HasSubstr("belongs to no named physical group"));
}

TEST(MeshBuilder, RejectsNeighboursDisagreeingOnAMidNode) {
  RawMesh raw = two_triangles();
  for (Vec2 p :
       {Vec2(0.5, 0), Vec2(1, 0.5), Vec2(0.5, 0.5), Vec2(0.5, 0.5), Vec2(0.5, 1), Vec2(0, 0.5)})
    raw.nodes.push_back(p), raw.node_tags.push_back(20 + static_cast<long>(raw.nodes.size()));
  raw.triangles[0] = {0, 1, 2, 4, 5, 6};
  raw.triangles[1] = {0, 2, 3, 7, 8, 9};  // 7 duplicates 6 at the same place: not shared
  EXPECT_THAT(error_of(raw),
              HasSubstr("share the edge between nodes 11 and 13 but not its mid node"));
}

}  // namespace
}  // namespace flotsam

namespace flotsam {
namespace {

// At UTM coordinates (x ~ 5e5, y ~ 6e6 m) a mesh file's mid nodes are off their straight edges
// by the rounding of such numbers (up to 1.9e-9 m seen from Gmsh on a 1 m mesh): the elements are
// straight. A mid node 1e-4 m off (a 1 m edge on a 1 km curve) is curved there as anywhere.
TEST(Mesh, AStraightMeshAtUtmCoordinatesHasNoCurvedElement) {
  Mesh mesh = make_rectangle_mesh(
      {.x0 = 499990.0, .y0 = 5999990.0, .length = 20.0, .width = 10.0, .nx = 20, .ny = 10});
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)  // rounding-sized jitter on every node
    mesh.nodes[n] += Vec2(n % 2 ? 1.9e-9 : -1.9e-9, n % 3 ? -1.9e-9 : 1.9e-9);
  int curved = 0;
  for (int e = 0; e < static_cast<int>(mesh.elements.size()); ++e) curved += mesh.is_curved(e);
  EXPECT_EQ(curved, 0);
  const int mid = mesh.elements[7][3];
  mesh.nodes[mid] += Vec2(0.0, 1e-4);
  EXPECT_TRUE(mesh.is_curved(7));
}

}  // namespace
}  // namespace flotsam
