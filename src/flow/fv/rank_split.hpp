#pragma once
// One flood split over MPI ranks (issue 41; docs/model.md "One flood over MPI ranks"): the
// finite-volume cells in METIS parts (partition.hpp), one per rank. Each rank advances its own
// cells; it reads the two rings of cells around them (an edge's flux reads the reconstruction of
// the two cells beside it, and each reconstruction reads its cell's neighbours), refreshed from
// their owners after every stage by non-blocking messages, one per neighbouring part.
//
// Every cell's arithmetic is the same whatever rank does it, and every sum over cells or
// boundary edges is formed in the global order after a gather: the answer is the same bit for bit
// on any number of ranks (and threads).
#include <cstddef>
#include <span>
#include <vector>

#include "flow/fv/cell_mesh.hpp"

namespace flotsam {

class RankSplit {
 public:
  /// Rank `rank` of `size` (>= 1) over `cells`, the parts balancing `weights` (partition.hpp);
  /// `gathered` (one per edge of cells.boundary_edges; empty: all) marks the boundary edges whose
  /// values gather_boundary carries. MPI must be initialised when size > 1
  /// (std::invalid_argument when this build has no MPI).
  RankSplit(const CellMesh& cells, int rank, int size, std::span<const int> weights = {},
            std::span<const char> gathered = {});

  int rank() const { return rank_; }
  int size() const { return size_; }
  std::span<const int> own() const { return own_; }              ///< ascending
  std::span<const int> reconstructed() const { return ring1_; }  ///< own + ring 1, ascending
  std::span<const int> loaded() const { return ring2_; }         ///< own + rings 1, 2, ascending
  std::span<const int> edges() const { return edges_; }          ///< beside an own cell
  /// Positions in cells.boundary_edges of the gathered edges of own cells, ascending.
  std::span<const int> boundary_positions() const { return bedges_; }
  /// Positions in cells.boundary_edges of every rank's gathered edges, ascending.
  std::span<const int> gathered_positions() const { return gathered_; }
  bool owns(int cell) const { return ring(cell) == 0; }
  /// 0 for an own cell, 1 or 2 for a cell of the first or second ring around them, 3 beyond.
  int ring(int cell) const { return ring_[static_cast<std::size_t>(cell)]; }

  /// Refreshes rings 1 and 2 of each per-cell array from their owners.
  void exchange(std::span<double* const> arrays) const;
  /// Every cell of `data` (`per_cell` values each) from its owner, on every rank.
  void gather(double* data, int per_cell) const;
  /// `values` holds one value per edge of cells.boundary_edges (position k: the k-th), this
  /// rank's own gathered ones filled in; on return every rank's.
  void gather_boundary(std::vector<double>& values) const;
  double min(double x) const;
  bool any(bool x) const;

  /// Wall time spent in communication so far [s], and bytes this rank sent.
  double communication_seconds() const { return seconds_; }
  /// Wall time since this split was made [s].
  double seconds_since_split() const;
  double bytes_sent() const { return bytes_; }

 private:
  std::vector<double> all_of(const std::vector<double>& mine, const std::vector<int>& counts) const;

  int rank_, size_;
  std::vector<int> own_, ring1_, ring2_, edges_, bedges_, gathered_;
  std::vector<char> ring_;                     // per cell: 0 own, 1, 2 its rings, 3 beyond
  std::vector<std::vector<int>> own_of_;       // per rank: its own cells, ascending
  std::vector<std::vector<int>> bedges_of_;    // per rank: positions in boundary_edges, ascending
  std::vector<int> peers_;                     // ranks this one exchanges with
  std::vector<std::vector<int>> send_, recv_;  // per peer: cells sent (own), received (halo)
  mutable double seconds_ = 0.0, bytes_ = 0.0;
  double made_;  // [s] omp_get_wtime() when made
};

}  // namespace flotsam
