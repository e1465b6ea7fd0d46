// Tests the local time stepping's levels (flow/fv/time_levels.hpp) on a strip of 40 x 1
// rectangles (80 triangles) whose neighbours are known: levels fall by at most one per cell
// towards the finest, ties and the rings ahead of a shoreline lower them, and the parts of L
// hold exactly the edges and cells of their levels.
#include <gtest/gtest.h>

#include <algorithm>
#include <queue>

#include "flow/fv/cell_mesh.hpp"
#include "flow/fv/time_levels.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

const CellMesh& strip() {
  static const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 40.0, 1.0, 40, 1, false});
  static const CellMesh cells = build_cell_mesh(mesh, FvCells::elements);
  return cells;
}

// The number of edges crossed from cell `from` to each cell.
std::vector<int> distances(const CellMesh& c, int from) {
  std::vector<int> d(c.cell_count, -1);
  std::queue<int> q;
  d[from] = 0;
  q.push(from);
  while (!q.empty()) {
    const int i = q.front();
    q.pop();
    for (int j : c.neighbour[i])
      if (j >= 0 && d[j] < 0) d[j] = d[i] + 1, q.push(j);
  }
  return d;
}

constexpr int cap = 3, fine = 40;  // levels 0..3; the one cell at level 0

// The levels of the strip, all wet and untied, when only cell `fine` needs level 0.
std::vector<int> levels_around_the_fine_cell(int width) {
  const CellMesh& c = strip();
  std::vector<int> raw(c.cell_count, cap);
  raw.at(fine) = 0;
  return cell_levels(c, raw, cap, {}, std::vector<char>(c.cell_count, 0), width);
}

TEST(TimeLevels, RiseByOneLevelPerCellAwayFromTheFinest) {
  const CellMesh& c = strip();
  const TimeLevels t = build_time_levels(c, levels_around_the_fine_cell(1));
  const std::vector<int> d = distances(c, fine);
  for (int i = 0; i < c.cell_count; ++i) EXPECT_EQ(t.cell_level[i], std::min(cap, d[i])) << i;
  EXPECT_EQ(t.top, cap);
  for (int e = 0; e < c.edge_count; ++e) {
    const int r = c.right[e];
    EXPECT_EQ(t.edge_level[e],
              r < 0 ? t.cell_level[c.left[e]] : std::min(t.cell_level[c.left[e]], t.cell_level[r]));
  }
  // The parts: at[e] the edges of level e, upto[a] those of level <= a, their cells and the
  // cells' neighbours loaded; cells_upto[a] the cells of level <= a.
  for (int a = 0; a <= t.top; ++a) {
    for (int e : t.at[a].edges) EXPECT_EQ(t.edge_level[e], a);
    long upto = 0;
    for (int e = 0; e < c.edge_count; ++e) upto += t.edge_level[e] <= a;
    EXPECT_EQ(static_cast<long>(t.upto[a].edges.size()), upto);
    for (int i : t.cells_upto[a]) EXPECT_LE(t.cell_level[i], a);
    for (int e : t.upto[a].edges)
      for (int i : {c.left[e], c.right[e]}) {
        if (i < 0) continue;
        EXPECT_TRUE(std::binary_search(t.upto[a].cells.begin(), t.upto[a].cells.end(), i));
        for (int j : c.neighbour[i]) {
          if (j < 0) continue;
          EXPECT_TRUE(std::binary_search(t.upto[a].loaded.begin(), t.upto[a].loaded.end(), j));
        }
      }
  }
  EXPECT_EQ(static_cast<int>(t.cells_upto[t.top].size()), c.cell_count);
  EXPECT_EQ(static_cast<int>(t.upto[t.top].edges.size()), c.edge_count);
}

TEST(TimeLevels, TiedCellsTakeTheSmallestLevelAndDryRingsTheShorelines) {
  const CellMesh& c = strip();
  std::vector<int> raw(c.cell_count, cap);
  raw.at(10) = 0;
  std::vector<char> dry(c.cell_count, 0);
  for (int i = 0; i < c.cell_count; ++i)  // the strip's cells form a chain along x
    dry[i] = c.centroid[i].x() > c.centroid[10].x();
  // cell 79 (the strip's far end) tied with cell 10: level 0 there too
  const std::vector<int> level = cell_levels(c, raw, cap, {{10, 79}}, dry, 1);
  const std::vector<int> d10 = distances(c, 10), d79 = distances(c, 79);
  for (int i = 0; i < c.cell_count; ++i) {
    // the two dry rings past cell 10 stay at level 0; beyond, one level per cell
    const int from10 = dry[i] ? std::max(0, d10[i] - 2) : d10[i];
    EXPECT_EQ(level[i], std::min({cap, from10, d79[i]})) << i;
  }
}

TEST(TimeLevels, AWidthOfTwoRaisesALevelEveryTwoCells) {
  const CellMesh& c = strip();
  const std::vector<int> level = levels_around_the_fine_cell(2);
  const std::vector<int> d = distances(c, fine);
  for (int i = 0; i < c.cell_count; ++i) EXPECT_EQ(level[i], std::min(cap, d[i] / 2)) << i;
}

}  // namespace
}  // namespace flotsam
