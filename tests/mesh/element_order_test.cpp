// The elements' Cuthill-McKee order (mesh/element_order.hpp): neighbours within two fronts of
// each other on a long strip (where the curve's order spreads them over the mesh), the same mesh
// renumbered, and each connected part numbered in one run by build_mesh.
#include "mesh/element_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "mesh/curve_order.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

/// Largest |i - j| over the elements i, j across an edge from each other.
int bandwidth(const Mesh& mesh) {
  int width = 0;
  for (int e = 0; e < mesh.element_count(); ++e)
    for (const int across : mesh.neighbours[e])
      if (!Mesh::is_boundary(across)) width = std::max(width, std::abs(across - e));
  return width;
}

// A strip of 40 x 10 rectangles (800 triangles): breadth first from a short end, the fronts run
// across it and hold at most 2 ny + 2 = 22 triangles; an element's neighbours lie in its own
// front or the next or the previous one, so within 2 (2 ny + 2) = 44 places.
TEST(ElementOrder, NeighboursOfAStripLieWithinTwoFronts) {
  const int ny = 10;
  const Mesh along =
      ordered_along_curve(make_rectangle_mesh({.length = 40.0, .width = 10.0, .nx = 40, .ny = ny}));
  const Mesh ordered = ordered_by_cuthill_mckee(along);
  EXPECT_GT(bandwidth(along), 4 * (2 * ny + 2));  // the curve's order: quadrants apart
  EXPECT_LE(bandwidth(ordered), 2 * (2 * ny + 2));
  // The same triangles (by tag), boundary edges and nodes, only renumbered.
  std::vector<long> tags = ordered.element_tags, along_tags = along.element_tags;
  std::sort(tags.begin(), tags.end());
  std::sort(along_tags.begin(), along_tags.end());
  EXPECT_EQ(tags, along_tags);
  EXPECT_EQ(ordered.boundary.size(), along.boundary.size());
  EXPECT_EQ(ordered.nodes, along.nodes);
}

// Two squares that share nothing: each is numbered in one run, the one holding the first element
// in the curve's order first.
TEST(ElementOrder, EachConnectedPartIsNumberedInOneRun) {
  RawMesh raw = make_rectangle_raw({.length = 4.0, .width = 4.0, .nx = 4, .ny = 4});
  const RawMesh right =
      make_rectangle_raw({.x0 = 10.0, .length = 4.0, .width = 4.0, .nx = 4, .ny = 4});
  const int offset = static_cast<int>(raw.nodes.size());  // (no tags: build_mesh numbers them)
  raw.nodes.insert(raw.nodes.end(), right.nodes.begin(), right.nodes.end());
  for (std::vector<int> triangle : right.triangles) {
    for (int& node : triangle) node += offset;
    raw.triangles.push_back(triangle);
  }
  for (RawMesh::Line line : right.lines) {
    for (int& node : line.nodes) node += offset;
    raw.lines.push_back(line);
  }
  const Mesh mesh = build_mesh(raw);
  ASSERT_EQ(mesh.element_count(), 64);
  // Elements 0-31 on one side of x = 7, 32-63 on the other.
  const auto side = [&](int e) { return mesh.nodes[mesh.elements[e][0]].x() > 7.0; };
  for (int e = 1; e < 64; ++e) EXPECT_EQ(side(e), side(e < 32 ? 0 : 32)) << "element " << e;
  EXPECT_NE(side(0), side(32));
}

}  // namespace
}  // namespace flotsam
