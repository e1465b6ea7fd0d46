#pragma once
// Zero fill-in incomplete Cholesky factor, L L^T ~ A, of a symmetric positive definite sparse
// matrix A = diag(d) + s K on K's own pattern (IC(0)): the exact Cholesky recurrence with every
// entry outside A's lower triangle dropped. A preconditioner for conjugate gradients: its
// iterations grow with the mesh much more slowly than Jacobi's. Entries marked fixed are rows and
// columns of the identity (Dirichlet values eliminated symmetrically). When a pivot is not
// positive (A is not an M-matrix: IC(0) may break down), the factor is redone with the diagonal
// raised by a shift that doubles until it succeeds (Manteuffel's shifted IC). The rows are taken
// in parts (row_parts.hpp) and the entries that couple a part to an earlier one dropped too: a
// block diagonal factor whose parts are factorised and swept independently (block Jacobi between
// the parts, IC(0) within each), on the threads for a large matrix.
#include <Eigen/Sparse>
#include <array>
#include <vector>

#include "flow/fem/row_parts.hpp"

namespace flotsam {

class IncompleteCholesky {
 public:
  using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  /// Takes K's pattern (symmetric, compressed, each column's diagonal present); K must outlive
  /// the factor and keep that pattern (L's column indices are read from it).
  void analyse(const SparseMatrix& K);
  /// Factorises diag(d) + s K (K of the analysed pattern) with the `fixed` rows and columns
  /// replaced by the identity's.
  void factorise(const SparseMatrix& K, double s, const Eigen::VectorXd& d,
                 const std::vector<char>& fixed);
  /// z = (L L^T)^-1 r.
  void solve(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;
  /// The same for two vectors at once, interleaved (entry 2 i + c of r and z: component c of
  /// unknown i), each sweep reading L once for both; returns r_c . z_c per component.
  std::array<double, 2> solve_pair(const std::vector<double>& r, std::vector<double>& z) const;
  /// The relative diagonal shift of the last factorisation (0: none was needed) [-].
  double shift() const { return shift_; }

 private:
  bool try_factorise(const SparseMatrix& K, double s, const Eigen::VectorXd& d,
                     const std::vector<char>& fixed, double shift);
  // Row i of L is a run of K's column i (rows j of i's part with j <= i, the diagonal last),
  // from K's entry k_start_[i] on: its column indices are K's, and row_start_ places its values
  // in value_.
  int column(int i, int p) const { return index_[k_start_[i] + p - row_start_[i]]; }
  double l(int p) const { return static_cast<double>(value_[p]); }  // L's entry p
  const int* index_ = nullptr;                                      // K's row indices
  RowParts parts_;
  std::vector<int> k_start_;    // per row of L: K's entry of its first
  std::vector<int> row_start_;  // per row of L: its first entry in value_
  // L's values, in single precision: the solves' sweeps are bound by reading L, and a
  // preconditioner needs no more digits (each entry is computed in double, then rounded).
  std::vector<float> value_;
  std::vector<int> marker_;  // per column: position of the entry in the current row, or -1
  double shift_ = 0.0;
};

}  // namespace flotsam
