// The numbering of build_mesh along a space-filling curve (mesh/curve_order.hpp): the Hilbert
// index, the order of a hand-checked square (its elements then in Cuthill-McKee order), and on a
// generated channel fed in shuffled order: the same mesh whatever the input's order, every node,
// element and boundary edge kept with its tag, and a numbering far more local than the input's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <random>
#include <set>
#include <tuple>
#include <utility>

#include "../support/two_pier_channel.hpp"
#include "mesh/curve_order.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_generator.hpp"

namespace flotsam {
namespace {

TEST(CurveOrder, HilbertIndexVisitsEveryCellOnceStepByStep) {
  constexpr int bits = 3, side = 8;  // an 8 x 8 grid
  std::map<std::uint64_t, std::pair<int, int>> cell_at;
  for (int x = 0; x < side; ++x)
    for (int y = 0; y < side; ++y)
      cell_at[hilbert_index(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), bits)] = {
          x, y};
  ASSERT_EQ(cell_at.size(), 64u);  // a permutation of 0 .. 63
  EXPECT_EQ(cell_at.begin()->first, 0u);
  EXPECT_EQ(cell_at.rbegin()->first, 63u);
  EXPECT_EQ(cell_at.begin()->second, std::make_pair(0, 0));          // starts lower left
  EXPECT_EQ(cell_at.rbegin()->second, std::make_pair(side - 1, 0));  // ends lower right
  for (std::uint64_t d = 1; d < 64; ++d) {  // each step to a cell sharing a side
    const auto [x0, y0] = cell_at[d - 1];
    const auto [x1, y1] = cell_at[d];
    EXPECT_EQ(std::abs(x1 - x0) + std::abs(y1 - y0), 1) << "step " << d;
  }
}

TEST(CurveOrder, SortingPermutationKeepsEqualKeysInTheirOrder) {
  EXPECT_EQ(sorting_permutation({5, 1, 5, 0, 1}), (std::vector<int>{3, 1, 4, 0, 2}));
}

TEST(CurveOrder, UnitSquareRunsLowerLeftUpperLeftUpperRightLowerRight) {
  RawMesh raw;
  raw.source = "square";
  raw.nodes = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  raw.node_tags = {11, 12, 13, 14};
  raw.triangles = {{0, 1, 2}, {0, 2, 3}};  // centroids in the lower right and upper left
  raw.triangle_tags = {101, 102};
  raw.lines = {
      {{0, 1}, "bottom", 1}, {{1, 2}, "right", 2}, {{2, 3}, "top", 3}, {{3, 0}, "left", 4}};
  const Mesh mesh = build_mesh(raw);
  ASSERT_EQ(mesh.vertex_count, 4);
  EXPECT_EQ(std::vector<long>(mesh.node_tags.begin(), mesh.node_tags.begin() + 4),
            (std::vector<long>{11, 14, 13, 12}));
  // Elements in Cuthill-McKee order (mesh/element_order.hpp): 102 comes first on the curve, and
  // George & Liu's search from it ends at the far element, 101, which starts the order.
  EXPECT_EQ(mesh.element_tags, (std::vector<long>{101, 102}));
  EXPECT_EQ(mesh.nodes[1], Vec2(0, 1));
  // Element 101 (now 0) is (0,0) (1,0) (1,1): new vertices 0 3 2 in its own local order.
  EXPECT_EQ(mesh.elements[0][0], 0);
  EXPECT_EQ(mesh.elements[0][1], 3);
  EXPECT_EQ(mesh.elements[0][2], 2);
  // Boundary edges in element order: 101's edges 0 (bottom) and 1 (right), then 102's 1 and 2.
  ASSERT_EQ(mesh.boundary.size(), 4u);
  const auto group = [&](int b) { return mesh.group_names[mesh.boundary[b].group]; };
  EXPECT_EQ(group(0), "bottom");
  EXPECT_EQ(group(1), "right");
  EXPECT_EQ(group(2), "top");
  EXPECT_EQ(group(3), "left");
  EXPECT_EQ(mesh.neighbours[0][2], 1);
  EXPECT_EQ(mesh.neighbours[1][0], 0);
}

/// The plain lists of a mesh (6-node triangles, 3-node boundary lines), as a reader gives them.
RawMesh raw_of(const Mesh& mesh) {
  RawMesh raw;
  raw.source = mesh.source;
  raw.nodes = mesh.nodes;
  raw.node_tags = mesh.node_tags;
  for (const auto& element : mesh.elements)
    raw.triangles.emplace_back(element.begin(), element.end());
  raw.triangle_tags = mesh.element_tags;
  for (std::size_t b = 0; b < mesh.boundary.size(); ++b) {
    const auto nodes = mesh.edge_nodes(mesh.boundary[b].element, mesh.boundary[b].local_edge);
    raw.lines.push_back({{nodes[0], nodes[1], nodes[2]},
                         mesh.group_names[mesh.boundary[b].group],
                         static_cast<long>(b + 1)});
  }
  return raw;
}

/// A random permutation of 0 .. n-1 (Fisher-Yates on a seeded engine: the same on any machine).
std::vector<int> shuffled_indices(int n, std::mt19937_64& random) {
  std::vector<int> p(n);
  for (int i = 0; i < n; ++i) p[i] = i;
  for (int i = n - 1; i > 0; --i) std::swap(p[i], p[random() % static_cast<std::uint64_t>(i + 1)]);
  return p;
}

/// The raw mesh with its nodes, triangles and lines in random order (tags moving with them).
RawMesh shuffled(const RawMesh& raw, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  const int n = static_cast<int>(raw.nodes.size());
  const std::vector<int> node_at = shuffled_indices(n, random);
  std::vector<int> new_index(n);
  for (int i = 0; i < n; ++i) new_index[node_at[i]] = i;
  RawMesh out;
  out.source = raw.source;
  for (int i = 0; i < n; ++i) {
    out.nodes.push_back(raw.nodes[node_at[i]]);
    out.node_tags.push_back(raw.node_tags[node_at[i]]);
  }
  for (int t : shuffled_indices(static_cast<int>(raw.triangles.size()), random)) {
    std::vector<int> triangle;
    for (int node : raw.triangles[t]) triangle.push_back(new_index[node]);
    out.triangles.push_back(triangle);
    out.triangle_tags.push_back(raw.triangle_tags[t]);
  }
  for (int l : shuffled_indices(static_cast<int>(raw.lines.size()), random)) {
    RawMesh::Line line = raw.lines[l];
    for (int& node : line.nodes) node = new_index[node];
    out.lines.push_back(line);
  }
  return out;
}

/// Mean |a - b| over the pairs of vertices of each triangle: how far apart in memory the values
/// an element reads lie.
double mean_vertex_gap(const std::vector<std::vector<int>>& triangles) {
  double sum = 0;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) sum += std::abs(t[k] - t[(k + 1) % 3]);
  return sum / (3.0 * static_cast<double>(triangles.size()));
}

TEST(CurveOrder, ShuffledInputGivesTheSameLocalMeshWithEveryTag) {
  const Mesh mesh = generate_mesh(test::two_pier_channel(3));
  const RawMesh input = shuffled(raw_of(mesh), 7);
  const Mesh built = build_mesh(input);

  // The same mesh whatever the input's order (no two keys equal here: 1.4 mm cells).
  EXPECT_EQ(built.vertex_count, mesh.vertex_count);
  EXPECT_EQ(built.nodes, mesh.nodes);
  EXPECT_EQ(built.node_tags, mesh.node_tags);
  EXPECT_EQ(built.elements, mesh.elements);
  EXPECT_EQ(built.element_tags, mesh.element_tags);
  EXPECT_EQ(built.neighbours, mesh.neighbours);
  EXPECT_EQ(built.area, mesh.area);
  EXPECT_EQ(built.group_names, mesh.group_names);
  ASSERT_EQ(built.boundary.size(), mesh.boundary.size());
  for (std::size_t b = 0; b < mesh.boundary.size(); ++b) {
    EXPECT_EQ(built.boundary[b].element, mesh.boundary[b].element);
    EXPECT_EQ(built.boundary[b].local_edge, mesh.boundary[b].local_edge);
    EXPECT_EQ(built.boundary[b].group, mesh.boundary[b].group);
  }

  // Every input node, element and boundary line is there, by its tag: a permutation.
  std::map<long, Vec2> input_node;
  for (std::size_t n = 0; n < input.nodes.size(); ++n)
    input_node.emplace(input.node_tags[n], input.nodes[n]);
  ASSERT_EQ(input_node.size(), input.nodes.size());  // tags are unique
  ASSERT_EQ(built.node_count(), static_cast<int>(input.nodes.size()));
  std::set<long> seen_nodes;
  for (int n = 0; n < built.node_count(); ++n) {
    seen_nodes.insert(built.node_tags[n]);
    EXPECT_EQ(built.nodes[n], input_node.at(built.node_tags[n])) << "node " << built.node_tags[n];
  }
  EXPECT_EQ(seen_nodes.size(), input_node.size());
  std::map<long, std::vector<long>> input_element;  // tag -> its 6 nodes' tags
  for (std::size_t t = 0; t < input.triangles.size(); ++t)
    for (int node : input.triangles[t])
      input_element[input.triangle_tags[t]].push_back(input.node_tags[node]);
  ASSERT_EQ(built.element_count(), static_cast<int>(input_element.size()));
  std::set<long> seen_elements;
  for (int e = 0; e < built.element_count(); ++e) {
    seen_elements.insert(built.element_tags[e]);
    std::vector<long> tags;
    for (int node : built.elements[e]) tags.push_back(built.node_tags[node]);
    EXPECT_EQ(tags, input_element.at(built.element_tags[e])) << "element " << built.element_tags[e];
    const Vec2 a = input_node.at(tags[0]), b = input_node.at(tags[1]), c = input_node.at(tags[2]);
    EXPECT_DOUBLE_EQ(built.area[e], 0.5 * cross(b - a, c - a));
  }
  EXPECT_EQ(seen_elements.size(), input_element.size());
  std::set<std::tuple<long, long, long, std::string>> input_lines, built_lines;
  for (const auto& line : input.lines)
    input_lines.insert({input.node_tags[line.nodes[0]], input.node_tags[line.nodes[1]],
                        input.node_tags[line.nodes[2]], line.group});
  for (const auto& edge : built.boundary) {
    const auto nodes = built.edge_nodes(edge.element, edge.local_edge);
    built_lines.insert({built.node_tags[nodes[0]], built.node_tags[nodes[1]],
                        built.node_tags[nodes[2]], built.group_names[edge.group]});
  }
  EXPECT_EQ(built_lines, input_lines);

  // Local: an element's vertices lie close together in the numbering, and so do neighbours. A
  // random order puts them a third of the nodes apart; along a curve the mean gap grows like
  // the square root of the count (16.7 of 425 vertices, 19.5 of 741 elements here): bound
  // 2 sqrt(count), 41 and 54 here, where a random order gives 142 and 247.
  std::vector<std::vector<int>> built_triangles;
  for (const auto& element : built.elements)
    built_triangles.emplace_back(element.begin(), element.begin() + 3);
  EXPECT_GT(mean_vertex_gap(input.triangles), 0.25 * static_cast<double>(input.nodes.size()));
  EXPECT_LT(mean_vertex_gap(built_triangles), 2 * std::sqrt(built.vertex_count));
  double neighbour_gap = 0;
  int pairs = 0;
  for (int e = 0; e < built.element_count(); ++e)
    for (int across : built.neighbours[e])
      if (!Mesh::is_boundary(across)) neighbour_gap += std::abs(across - e), ++pairs;
  EXPECT_LT(neighbour_gap / pairs, 2 * std::sqrt(built.element_count()));
}

}  // namespace
}  // namespace flotsam
