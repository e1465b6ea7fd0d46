#pragma once
// The finite-volume cells split into parts, one per MPI rank (issue 41; docs/model.md "Parts for
// MPI ranks"): METIS's k-way partition of the cells' edge graph (a cell is a vertex, an inner
// edge a graph edge), each cell weighted by the work it costs (1, or its updates per cycle with
// local time stepping). METIS is seeded, so the same mesh gives the same parts on every run.
//
// And what a split costs a rank: its cells and their weight, its halo (the cells of other parts
// that its own step reads: two rings around its cells, since an edge's flux reads the values
// reconstructed in the two cells beside it, and each reconstruction reads that cell's
// neighbours), the parts it exchanges with (one message each per stage), and the edges cut.
#include <span>
#include <vector>

#include "flow/fv/cell_mesh.hpp"

namespace flotsam {

/// The part (0 .. parts-1) of every cell; `weights` (optional, one per cell, >= 1) the work of
/// each. parts >= 1; a part may be empty only when there are fewer cells than parts.
std::vector<int> partition_cells(const CellMesh& cells, int parts,
                                 std::span<const int> weights = {});

struct PartitionSummary {
  std::vector<int> cells;       // per part
  std::vector<long> weight;     // per part: the sum of its cells' weights
  std::vector<int> halo;        // per part: the cells of other parts within two rings
  std::vector<int> neighbours;  // per part: the other parts its halo reads from
  int cut_edges = 0;            // inner edges between two parts
  double imbalance = 1.0;       // largest part weight over the mean [-]
};

PartitionSummary summarize_partition(const CellMesh& cells, const std::vector<int>& part, int parts,
                                     std::span<const int> weights = {});

}  // namespace flotsam
