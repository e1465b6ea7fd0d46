// Verifies the cells' split into parts for MPI ranks (flow/fv/partition.hpp) on a rectangle of
// 40 x 10 squares (800 triangles): every cell in one part, the parts' weights within METIS's
// default 3 % of the mean (with equal and with unequal cell weights), the same parts on every
// call, and the summary's counts against a split made by hand (cells left and right of x = 20 m:
// 20 cut edges, a halo of two rings of cells on each side).
#include "flow/fv/partition.hpp"

#include <gtest/gtest.h>

#include <numeric>

#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

CellMesh rectangle_cells() {
  const Mesh mesh = make_rectangle_mesh({.length = 40.0, .width = 10.0, .nx = 40, .ny = 10});
  return build_cell_mesh(mesh, FvCells::elements);
}

TEST(Partition, EveryCellInOnePartAndThePartsBalanced) {
  const CellMesh cells = rectangle_cells();
  ASSERT_EQ(cells.cell_count, 800);
  for (const int parts : {2, 3, 4, 8}) {
    const std::vector<int> part = partition_cells(cells, parts);
    ASSERT_EQ(static_cast<int>(part.size()), cells.cell_count);
    for (const int p : part) ASSERT_TRUE(p >= 0 && p < parts) << p;
    const PartitionSummary s = summarize_partition(cells, part, parts);
    EXPECT_EQ(std::accumulate(s.cells.begin(), s.cells.end(), 0), cells.cell_count);
    EXPECT_LE(s.imbalance, 1.03 + 1e-12) << parts << " parts";
    for (int p = 0; p < parts; ++p) EXPECT_GE(s.neighbours[p], 1) << parts << " parts";
    EXPECT_EQ(partition_cells(cells, parts), part) << "the same parts on every call";
  }
}

TEST(Partition, WeightsBalanceTheWorkNotTheCells) {
  const CellMesh cells = rectangle_cells();
  std::vector<int> weight(static_cast<std::size_t>(cells.cell_count), 1);
  for (int i = 0; i < cells.cell_count; ++i)
    if (cells.centroid[i].x() < 10.0) weight.at(i) = 4;  // fine cells' work, as with time levels
  const std::vector<int> part = partition_cells(cells, 2, weight);
  const PartitionSummary s = summarize_partition(cells, part, 2, weight);
  EXPECT_LE(s.imbalance, 1.03 + 1e-12);
  EXPECT_EQ(s.weight[0] + s.weight[1], 4 * 200 + 600);
  // 1,400 of work in two parts of ~700: the part holding the heavy quarter has ~275 cells.
  EXPECT_LT(std::min(s.cells[0], s.cells[1]), 300);
}

TEST(Partition, SummaryOfAHandMadeSplit) {
  const CellMesh cells = rectangle_cells();
  std::vector<int> part(static_cast<std::size_t>(cells.cell_count));
  for (int i = 0; i < cells.cell_count; ++i) part.at(i) = cells.centroid[i].x() < 20.0 ? 0 : 1;
  const PartitionSummary s = summarize_partition(cells, part, 2);
  EXPECT_EQ(s.cells, (std::vector<int>{400, 400}));
  EXPECT_EQ(s.cut_edges, 10);  // one vertical edge per row of squares
  // Two rings across x = 20: the 10 triangles touching the line, and the 10 behind them (each
  // ring-1 triangle's other neighbour inside the square, then across the square's diagonal).
  EXPECT_EQ(s.halo, (std::vector<int>{20, 20}));
  EXPECT_EQ(s.neighbours, (std::vector<int>{1, 1}));
  EXPECT_DOUBLE_EQ(s.imbalance, 1.0);
}

}  // namespace
}  // namespace flotsam
