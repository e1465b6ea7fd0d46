#pragma once
// A numbering of a sparse matrix's unknowns by locality: reverse Cuthill-McKee (the order of
// core/cuthill_mckee.hpp over the matrix's graph, reversed). Neighbours then lie close in memory (a
// sweep over the matrix touches a window of the vectors, not all of them), and a zero fill-in
// incomplete factor on this order keeps more of the exact one than on a random order
// (docs/performance.md "The segregated step").
#include <Eigen/Sparse>
#include <vector>

namespace flotsam {

/// new_index[old] for the structurally symmetric pattern of `pattern` (values ignored); every
/// connected part numbered in turn.
std::vector<int> reverse_cuthill_mckee(
    const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& pattern);

}  // namespace flotsam
