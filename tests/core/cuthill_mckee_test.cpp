// Cuthill-McKee order of a graph (core/cuthill_mckee.hpp): a path given in scrambled numbering
// is walked from an end, a ring's levels come in pairs, and each connected part is numbered in
// one run.
#include "core/cuthill_mckee.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <utility>
#include <vector>

namespace flotsam {
namespace {

/// CSR adjacency (increasing neighbours) of the undirected graph with `edges` on n nodes.
struct Graph {
  std::vector<int> start, index;
};
Graph graph(int n, const std::vector<std::pair<int, int>>& edges) {
  std::vector<std::vector<int>> lists(n);
  for (const auto& [a, b] : edges) lists[a].push_back(b), lists[b].push_back(a);
  Graph g{{0}, {}};
  for (auto& l : lists) {
    std::sort(l.begin(), l.end());
    g.index.insert(g.index.end(), l.begin(), l.end());
    g.start.push_back(static_cast<int>(g.index.size()));
  }
  return g;
}

// The path 3 - 0 - 4 - 1 - 2 (its nodes scrambled): from node 0 the last level is {2} (and 3 at
// the other end), George & Liu's search ends at an end, and the walk is the path.
TEST(CuthillMcKee, WalksAPathFromAnEnd) {
  const Graph g = graph(5, {{3, 0}, {0, 4}, {4, 1}, {1, 2}});
  const std::vector<int> order = cuthill_mckee(g.start, g.index);
  EXPECT_EQ(order, (std::vector<int>{3, 0, 4, 1, 2}));
}

// A ring of 8: every level but the first and last holds two nodes, so the neighbours of the
// k-th node are at most two places away.
TEST(CuthillMcKee, KeepsARingsNeighboursWithinTwoPlaces) {
  std::vector<std::pair<int, int>> edges;
  for (int i = 0; i < 8; ++i) edges.push_back({(3 * i) % 8, (3 * i + 3) % 8});  // scrambled
  const Graph g = graph(8, edges);
  const std::vector<int> order = cuthill_mckee(g.start, g.index);
  ASSERT_EQ(order.size(), 8u);
  std::vector<int> place(8, -1);
  for (int k = 0; k < 8; ++k) place[order[k]] = k;
  for (int p : place) ASSERT_GE(p, 0);  // a permutation
  for (const auto& [a, b] : edges) EXPECT_LE(std::abs(place[a] - place[b]), 2);
}

// Two triangles {0, 2, 4} and {1, 3, 5}: the part of node 0 first, then the other, each whole.
TEST(CuthillMcKee, NumbersEachConnectedPartInOneRun) {
  const Graph g = graph(6, {{0, 2}, {2, 4}, {4, 0}, {1, 3}, {3, 5}, {5, 1}});
  const std::vector<int> order = cuthill_mckee(g.start, g.index);
  ASSERT_EQ(order.size(), 6u);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(order[k] % 2, 0) << k;
  for (int k = 3; k < 6; ++k) EXPECT_EQ(order[k] % 2, 1) << k;
}

}  // namespace
}  // namespace flotsam
