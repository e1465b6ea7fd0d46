// Verifies what each rank of a flood split over MPI ranks advances and reads
// (flow/fv/rank_split.hpp), on a rectangle of 40 x 10 squares (800 triangles) split in 2, 3 and
// 4 parts: the own cells of the ranks cover every cell once; each rank loads exactly its cells
// and the two rings around them (an edge's flux reads the reconstruction of the two cells beside
// it, each reconstruction reads its cell's neighbours) and reconstructs its cells and the first
// ring; its edges are those beside its cells; every boundary edge belongs to exactly one rank,
// the owner of the cell inside it; a split with more ranks than cells is refused. (That the
// messages refresh these rings, and the answer is the same bit for bit on 1-4 ranks, is checked
// under mpirun: tests/scripts/ranks_check.sh.)
#include "flow/fv/rank_split.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>
#include <vector>

#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

std::set<int> rings_around(const CellMesh& c, std::span<const int> cells, int rings) {
  std::set<int> all(cells.begin(), cells.end());
  for (int r = 0; r < rings; ++r) {
    const std::set<int> front = all;
    for (const int i : front)
      for (const int j : c.neighbour[static_cast<std::size_t>(i)])
        if (j >= 0) all.insert(j);
  }
  return all;
}

TEST(RankSplit, EachRankAdvancesItsCellsAndReadsTwoRingsAroundThem) {
  const Mesh mesh = make_rectangle_mesh({.length = 40.0, .width = 10.0, .nx = 40, .ny = 10});
  const CellMesh c = build_cell_mesh(mesh, FvCells::elements);
  ASSERT_EQ(c.cell_count, 800);
  for (const int size : {2, 3, 4}) {
    std::vector<int> owners(static_cast<std::size_t>(c.cell_count), 0);
    std::vector<int> boundary_owners(c.boundary_edges.size(), 0);
    for (int rank = 0; rank < size; ++rank) {
      const RankSplit split(c, rank, size);
      EXPECT_GT(split.own().size(), 0u);
      EXPECT_TRUE(std::is_sorted(split.own().begin(), split.own().end()));
      for (const int i : split.own()) {
        ++owners[static_cast<std::size_t>(i)];
        EXPECT_TRUE(split.owns(i));
      }
      const std::set<int> ring1 = rings_around(c, split.own(), 1);
      const std::set<int> ring2 = rings_around(c, split.own(), 2);
      EXPECT_EQ(std::set<int>(split.reconstructed().begin(), split.reconstructed().end()), ring1)
          << "rank " << rank << " of " << size;
      EXPECT_EQ(std::set<int>(split.loaded().begin(), split.loaded().end()), ring2)
          << "rank " << rank << " of " << size;
      EXPECT_LT(split.loaded().size(), static_cast<std::size_t>(c.cell_count))
          << "a rank reads part of the mesh, not all of it";
      std::set<int> edges;
      for (const int i : split.own())
        for (const int e : c.cell_edges[static_cast<std::size_t>(i)]) edges.insert(e);
      EXPECT_EQ(std::set<int>(split.edges().begin(), split.edges().end()), edges);
      for (const int k : split.boundary_positions()) {
        ++boundary_owners[static_cast<std::size_t>(k)];
        EXPECT_TRUE(split.owns(c.left[c.boundary_edges[static_cast<std::size_t>(k)]]));
      }
    }
    for (const int n : owners) EXPECT_EQ(n, 1) << size << " ranks: a cell in one part only";
    for (const int n : boundary_owners) EXPECT_EQ(n, 1) << size << " ranks";
  }
}

TEST(RankSplit, MoreRanksThanCellsIsRefused) {
  const Mesh mesh = make_rectangle_mesh({.length = 2.0, .width = 1.0, .nx = 2, .ny = 1});
  const CellMesh c = build_cell_mesh(mesh, FvCells::elements);
  ASSERT_EQ(c.cell_count, 4);
  EXPECT_THROW(RankSplit(c, 0, 5), std::invalid_argument);
  EXPECT_THROW(RankSplit(c, 3, 3), std::invalid_argument);
}

// Only the marked boundary edges (those water may cross) are gathered: each by the rank owning
// the cell inside it, every marked one by exactly one rank.
TEST(RankSplit, GathersOnlyTheMarkedBoundaryEdges) {
  const Mesh mesh = make_rectangle_mesh({.length = 40.0, .width = 10.0, .nx = 40, .ny = 10});
  const CellMesh c = build_cell_mesh(mesh, FvCells::elements);
  std::vector<char> marked(c.boundary_edges.size(), 0);
  std::vector<int> expected;
  for (std::size_t k = 0; k < marked.size(); k += 3) {
    marked[k] = 1;
    expected.push_back(static_cast<int>(k));
  }
  std::vector<int> counted(marked.size(), 0);
  for (int rank = 0; rank < 3; ++rank) {
    const RankSplit split(c, rank, 3, {}, marked);
    EXPECT_EQ(
        std::vector<int>(split.gathered_positions().begin(), split.gathered_positions().end()),
        expected);
    for (const int k : split.boundary_positions()) {
      EXPECT_EQ(marked[static_cast<std::size_t>(k)], 1);
      EXPECT_TRUE(split.owns(c.left[c.boundary_edges[static_cast<std::size_t>(k)]]));
      ++counted[static_cast<std::size_t>(k)];
    }
  }
  for (std::size_t k = 0; k < marked.size(); ++k) EXPECT_EQ(counted[k], marked[k]) << k;
}

}  // namespace
}  // namespace flotsam
