#pragma once
// Sparse LU of the flow system: UMFPACK or KLU (SuiteSparse) through Eigen's wrappers. The first
// factorisation computes the symbolic analysis; later ones reuse it (same pattern).
//
// UMFPACK runs through its 64-bit interface (umfpack_dl_*). The 32-bit one (umfpack_di_*) returns
// "out of memory" (status -1) without factorising when the symbolic analysis' upper bound on the
// LU's memory passes what its int counters hold (2^31 units of 8 bytes, 16 GiB): on the paper's
// channel at 431k elements that bound is 393 GiB, while the LU takes 4.9 GiB. The system keeps
// 32-bit indices (its pattern is far below 2^31 entries, and Eigen's KLU wrapper takes no other);
// the solver keeps a 64-bit copy of the pattern (set once, 8 bytes per entry) and reads the values
// in place.
#include <Eigen/Sparse>
#include <memory>
#include <string>

namespace flotsam {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

enum class LinearSolverKind { umfpack, klu };

/// Why a factorisation failed.
enum class FactorizationFailure { none, singular, out_of_memory, other };

class SparseDirectSolver {
 public:
  explicit SparseDirectSolver(LinearSolverKind kind = LinearSolverKind::umfpack);
  ~SparseDirectSolver();
  SparseDirectSolver(SparseDirectSolver&&) noexcept;
  SparseDirectSolver& operator=(SparseDirectSolver&&) noexcept;

  /// Numeric factorisation of A (symbolic analysis first when the pattern is new). A's storage
  /// must stay alive and unchanged in pattern until the next factorize. False on failure: then
  /// failure() says why.
  bool factorize(const SparseMatrix& A);
  /// x = A^-1 b with the last factorisation (not with A as it is now, if A changed since).
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

  FactorizationFailure failure() const { return failure_; }
  /// The last failure in words: the solver's status and the matrix size, and for lack of memory
  /// UMFPACK's bounds on the memory of the LU, e.g. "UMFPACK: out of memory (status -1)
  /// factorising the 1954467 x 1954467 matrix with 57743361 entries: the analysis bounds the LU
  /// by 412.4 GiB (5.01e+10 entries) and the factorisation's peak by 415.7 GiB".
  const std::string& failure_message() const { return failure_message_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  FactorizationFailure failure_ = FactorizationFailure::none;
  std::string failure_message_;
};

}  // namespace flotsam
