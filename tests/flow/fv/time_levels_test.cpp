// Tests the local time stepping's levels (flow/fv/time_levels.hpp) on a strip of 40 x 1
// rectangles (80 triangles) whose neighbours are known: levels fall by at most one per cell
// towards the finest, ties and the rings ahead of a shoreline lower them, and the parts of L
// hold exactly the edges and cells of their levels; over MPI ranks each rank's share of a part
// holds the part's edges beside its cells and all they read; the parts' weights are each cell's
// updates per cycle; `auto` takes three levels where the cells' sizes predict the gain.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <queue>
#include <set>

#include "flow/fv/cell_mesh.hpp"
#include "flow/fv/rank_split.hpp"
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

// Over 3 ranks: the shares of every part together hold its edges, each edge in the share of
// every rank owning one of its cells and only there; each share holds the cells its edges'
// fluxes read and their neighbours, within what the rank loads; cells_upto is split by owner.
TEST(TimeLevels, EachRankSharesThePartsBesideItsCells) {
  const CellMesh& c = strip();
  const TimeLevels t = build_time_levels(c, levels_around_the_fine_cell(2));
  ASSERT_EQ(t.top, cap);
  constexpr int ranks = 3;
  std::vector<RankSplit> splits;
  std::vector<TimeLevels> shares;
  for (int r = 0; r < ranks; ++r) {
    splits.emplace_back(c, r, ranks);
    shares.push_back(rank_share(c, t, splits.back()));
  }
  const auto check = [&](const EdgeSet& whole, const EdgeSet& share, const RankSplit& split) {
    for (const int e : whole.edges) {
      const bool beside = split.owns(c.left[e]) || (c.right[e] >= 0 && split.owns(c.right[e]));
      EXPECT_EQ(std::binary_search(share.edges.begin(), share.edges.end(), e), beside) << e;
    }
    for (const int e : share.edges)
      for (const int i : {c.left[e], c.right[e]}) {
        if (i < 0) continue;
        EXPECT_TRUE(std::binary_search(share.cells.begin(), share.cells.end(), i));
        for (const int j : c.neighbour[i]) {
          if (j >= 0) {
            EXPECT_TRUE(std::binary_search(share.loaded.begin(), share.loaded.end(), j));
          }
        }
      }
    for (const int i : share.loaded)
      EXPECT_TRUE(std::binary_search(split.loaded().begin(), split.loaded().end(), i));
    for (const int e : share.boundary_edges) EXPECT_LT(c.right[e], 0);
  };
  for (int a = 0; a <= t.top; ++a) {
    std::set<int> edges, cells;
    for (int r = 0; r < ranks; ++r) {
      check(t.upto[a], shares[r].upto[a], splits[r]);
      check(t.at[a], shares[r].at[a], splits[r]);
      edges.insert(shares[r].upto[a].edges.begin(), shares[r].upto[a].edges.end());
      for (const int i : shares[r].cells_upto[a]) {
        EXPECT_TRUE(splits[r].owns(i));
        EXPECT_TRUE(cells.insert(i).second) << "cell " << i << " shared twice";
      }
    }
    EXPECT_EQ(edges, std::set<int>(t.upto[a].edges.begin(), t.upto[a].edges.end()));
    EXPECT_EQ(cells, std::set<int>(t.cells_upto[a].begin(), t.cells_upto[a].end()));
  }
}

// Cells whose sizes double at each edge crossed away from cell `fine`: the level its size gives
// a cell is its distance (capped), smoothed to one level every two cells; its weight the
// updates it takes per cycle, 2^(top - level) (exact); with one level, none.
TEST(TimeLevels, SizeWeightsAreEachCellsUpdatesPerCycle) {
  CellMesh c = strip();
  const std::vector<int> d = distances(c, fine);
  for (int i = 0; i < c.cell_count; ++i) c.length_scale[i] = 0.25 * std::ldexp(1.0, d[i]);
  const std::vector<int> w = size_weights(c, cap + 1);
  ASSERT_EQ(static_cast<int>(w.size()), c.cell_count);
  for (int i = 0; i < c.cell_count; ++i) EXPECT_EQ(w[i], 1 << (cap - std::min(cap, d[i] / 2))) << i;
  const std::vector<int> uniform = size_weights(strip(), cap + 1);
  EXPECT_TRUE(std::all_of(uniform.begin(), uniform.end(), [](int x) { return x == 1; }));
  EXPECT_TRUE(size_weights(c, 1).empty()) << "one level: no weights, every cell 1";
}

// `time_levels: auto`: the gain the sizes predict is the cycle's updates with one level over
// those of the weights (exact); three levels on the graded strip (gain about 3.8), one on the
// uniform strip (gain 1); levels set are kept.
TEST(TimeLevels, AutoTakesThreeLevelsWhereTheSizesPredictTheGain) {
  CellMesh c = strip();
  const std::vector<int> d = distances(c, fine);
  for (int i = 0; i < c.cell_count; ++i) c.length_scale[i] = 0.25 * std::ldexp(1.0, d[i]);
  double work = 0.0;  // per cycle of 4 steps of the finest cell
  for (int i = 0; i < c.cell_count; ++i) work += 1 << (2 - std::min(2, d[i] / 2));
  EXPECT_DOUBLE_EQ(size_gain(c, auto_levels), 4.0 * c.cell_count / work);
  EXPECT_GT(size_gain(c, auto_levels), auto_gain);
  EXPECT_EQ(size_gain(strip(), auto_levels), 1.0);
  const int automatic = FiniteVolumeConfig{}.time_levels;
  ASSERT_EQ(automatic, 0) << "auto is the default";
  EXPECT_EQ(choose_time_levels(c, automatic), auto_levels);
  EXPECT_EQ(choose_time_levels(strip(), automatic), 1);
  EXPECT_EQ(choose_time_levels(strip(), 2), 2);
  EXPECT_EQ(choose_time_levels(c, 1), 1);
}

}  // namespace
}  // namespace flotsam
