#pragma once
// Sparse LU of the flow system: UMFPACK or KLU (SuiteSparse) through Eigen's wrappers. The first
// factorisation computes the symbolic analysis; later ones reuse it (same pattern).
//
// UMFPACK runs through its 64-bit interface (umfpack_dl_*): the 32-bit one (umfpack_di_*) counts
// the memory of the LU in int units of 8 bytes and gives up ("out of memory") beyond 2^31 units
// = 16 GiB, which the paper's channel reaches at about 500k elements. The system keeps 32-bit
// indices (its pattern is far below 2^31 entries, and KLU's wrapper takes no other); the solver
// keeps a 64-bit copy of the pattern (set once) and reads the values in place.
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
  /// the size of the LU the symbolic analysis predicted, e.g. "UMFPACK: out of memory (status
  /// -1) factorising the 2250000 x 2250000 matrix with 81000000 entries: the LU needs 20.1 GiB".
  const std::string& failure_message() const { return failure_message_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  FactorizationFailure failure_ = FactorizationFailure::none;
  std::string failure_message_;
};

}  // namespace flotsam
