// Unit tests of the finite-volume cells (flow/fv/cell_mesh.hpp): the split of each six-node
// triangle into four cells, their edges, boundary groups and least-squares gradient weights, on
// rectangle meshes whose geometry is known exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "flow/fv/cell_mesh.hpp"
#include "fv_test_cases.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

constexpr double Lx = 10.0, Ly = 4.0;  // [m] the rectangle

Mesh rectangle(bool alternate_diagonals = true) {
  return make_rectangle_mesh({0.0, 0.0, Lx, Ly, 5, 2, alternate_diagonals});
}

TEST(CellMesh, FourCellsPerElementWithPositiveAreasSummingToTheRectangle) {
  const Mesh mesh = rectangle();
  const CellMesh c = build_cell_mesh(mesh);
  ASSERT_EQ(c.cell_count, 4 * mesh.element_count());
  double total = 0.0;
  for (int i = 0; i < c.cell_count; ++i) {
    EXPECT_GT(c.area[i], 0.0) << "cell " << i << " is not counter-clockwise";
    total += c.area[i];
  }
  EXPECT_NEAR(total, Lx * Ly, 1e-12 * Lx * Ly);
  // Each element's four cells share its area equally (straight edges, mid nodes at midpoints).
  for (int e = 0; e < mesh.element_count(); ++e)
    for (int q = 0; q < 4; ++q) EXPECT_NEAR(c.area[4 * e + q], mesh.area[e] / 4.0, 1e-12);
}

TEST(CellMesh, EdgeVectorsOfEveryCellCloseTheTriangle) {
  // sum_k l_k n_k (outward) = 0 for any closed polygon (divergence theorem with a constant).
  const CellMesh c = build_cell_mesh(rectangle());
  for (int i = 0; i < c.cell_count; ++i) {
    Vec2 sum = Vec2::Zero();
    for (int k = 0; k < 3; ++k) {
      const int e = c.cell_edges[i][k];
      sum += (c.cell_is_left[i][k] ? 1.0 : -1.0) * c.length[e] * c.normal[e];
    }
    EXPECT_LT(sum.norm(), 1e-12) << "cell " << i;
  }
}

TEST(CellMesh, InteriorEdgesJoinTwoCellsWithTheNormalFromLeftToRight) {
  const CellMesh c = build_cell_mesh(rectangle());
  int interior = 0;
  for (int e = 0; e < c.edge_count; ++e) {
    EXPECT_NEAR(c.normal[e].norm(), 1.0, 1e-14);
    const int L = c.left[e], R = c.right[e];
    // The normal points out of the left cell: from its centroid towards the edge's midpoint.
    EXPECT_GT(c.normal[e].dot(c.to_edge[L][c.left_slot[e]]), 0.0) << "edge " << e;
    if (R < 0) continue;
    ++interior;
    EXPECT_NE(L, R);
    EXPECT_GT(c.normal[e].dot(c.centroid[R] - c.centroid[L]), 0.0) << "edge " << e;
    EXPECT_EQ(c.group[e], -1);
    EXPECT_EQ(c.cell_edges[L][c.left_slot[e]], e);
    EXPECT_EQ(c.cell_edges[R][c.right_slot[e]], e);
    EXPECT_EQ(c.neighbour[L][c.left_slot[e]], R);
    EXPECT_EQ(c.neighbour[R][c.right_slot[e]], L);
    EXPECT_TRUE(c.cell_is_left[L][c.left_slot[e]]);
    EXPECT_FALSE(c.cell_is_left[R][c.right_slot[e]]);
  }
  // Euler for a triangulation: 3 F = 2 E_interior + E_boundary.
  EXPECT_EQ(3 * c.cell_count, 2 * interior + static_cast<int>(c.boundary_edges.size()));
}

TEST(CellMesh, BoundaryEdgesCarryTheirSideGroupAndItsLength) {
  const Mesh mesh = rectangle();
  const CellMesh c = build_cell_mesh(mesh);
  const std::map<std::string, std::pair<double, Vec2>> sides = {{"left", {Ly, Vec2(-1, 0)}},
                                                                {"right", {Ly, Vec2(1, 0)}},
                                                                {"bottom", {Lx, Vec2(0, -1)}},
                                                                {"top", {Lx, Vec2(0, 1)}}};
  std::map<std::string, double> length;
  ASSERT_EQ(c.boundary_edges.size(), 2u * mesh.boundary.size());  // two cell edges per mesh edge
  for (int e : c.boundary_edges) {
    ASSERT_EQ(c.right[e], -1);
    ASSERT_GE(c.group[e], 0);
    const std::string& name = mesh.group_names.at(c.group[e]);
    ASSERT_TRUE(sides.count(name)) << name;
    length[name] += c.length[e];
    EXPECT_NEAR((c.normal[e] - sides.at(name).second).norm(), 0.0, 1e-14) << "outward normal";
    EXPECT_EQ(c.neighbour[c.left[e]][c.left_slot[e]], -1);
  }
  for (const auto& [name, side] : sides) EXPECT_NEAR(length[name], side.first, 1e-12) << name;
}

// grad phi = sum_k w_k (phi(x_k) - phi(x_i)) is exact for phi = a + b x + c y on every cell,
// with x_k the neighbour's centroid, or the centroid mirrored in a boundary edge (least squares
// reproduces a linear function whatever the points, as long as they span the plane).
TEST(CellMesh, GradientWeightsReproduceALinearFunctionExactly) {
  for (bool alternate : {true, false}) {
    const CellMesh c = build_cell_mesh(rectangle(alternate));
    const double a = 1.5, b = -0.7, d = 2.3;
    auto phi = [&](const Vec2& x) { return a + b * x.x() + d * x.y(); };
    for (int i = 0; i < c.cell_count; ++i) {
      Vec2 g = Vec2::Zero();
      for (int k = 0; k < 3; ++k) {
        const int j = c.neighbour[i][k];
        const Vec2& n = c.normal[c.cell_edges[i][k]];
        const Vec2 x_k =
            j >= 0 ? c.centroid[j] : Vec2(c.centroid[i] + 2.0 * c.to_edge[i][k].dot(n) * n);
        g += c.gradient_weight[i][k] * (phi(x_k) - phi(c.centroid[i]));
      }
      EXPECT_NEAR(g.x(), b, 1e-10) << "cell " << i;
      EXPECT_NEAR(g.y(), d, 1e-10) << "cell " << i;
    }
  }
}

TEST(CellMesh, SubCellPicksTheCornerAndMiddleCells) {
  EXPECT_EQ(CellMesh::sub_cell(0, 0.1, 0.1), 0);  // near v0
  EXPECT_EQ(CellMesh::sub_cell(0, 0.8, 0.1), 1);  // near v1
  EXPECT_EQ(CellMesh::sub_cell(0, 0.1, 0.8), 2);  // near v2
  EXPECT_EQ(CellMesh::sub_cell(0, 1.0 / 3.0, 1.0 / 3.0), 3);
  EXPECT_EQ(CellMesh::sub_cell(7, 0.3, 0.3), 31);
  EXPECT_EQ(CellMesh::sub_cell(7, 0.0, 0.0), 28);
  EXPECT_EQ(CellMesh::sub_cell(7, 1.0, 0.0), 29);
  EXPECT_EQ(CellMesh::sub_cell(7, 0.0, 1.0), 30);
}

TEST(CellMesh, SubCellHoldsThePointOfItsReferenceCoordinates) {
  // x = X0 + J (r, s): the chosen cell must contain x, on a grid of points over every element.
  const Mesh mesh = rectangle();
  const CellMesh c = build_cell_mesh(mesh);
  for (int e = 0; e < mesh.element_count(); ++e)
    for (int a = 1; a < 12; ++a)
      for (int b = 1; a + b < 12; ++b) {
        const double r = a / 12.0 + 0.013, s = b / 12.0 - 0.007;
        if (r + s > 1.0) continue;
        const Vec2 x = mesh.nodes[mesh.elements[e][0]] + mesh.jacobian(e) * Vec2(r, s);
        const int i = CellMesh::sub_cell(e, r, s);
        EXPECT_GE(test::barycentric(mesh, c, i, x).minCoeff(), -1e-12)
            << "element " << e << " (r, s) = (" << r << ", " << s << ")";
      }
}

TEST(CellMesh, CourantLengthIsTwoAreasOverThreeLongestEdges) {
  // A corner cell of an element of the unit square's lower triangle (legs 1/2): A = 1/8,
  // l_max = sqrt(2)/2, so 2 A / (3 l_max) = sqrt(2) / 12.
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 1.0, 1.0, 1, 1, false});
  const CellMesh c = build_cell_mesh(mesh);
  for (int i = 0; i < c.cell_count; ++i)
    EXPECT_NEAR(c.length_scale[i], std::sqrt(2.0) / 12.0, 1e-15) << "cell " << i;
}

}  // namespace
}  // namespace flotsam
