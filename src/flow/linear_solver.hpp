#pragma once
// Solves the flow system A x = b of each linearised step (linear_system.hpp) with a sparse LU
// (sparse_direct_solver.hpp), either freshly factorised every time, or kept across steps: the
// matrix changes little from one step to the next, so the last LU is a good preconditioner for
// the new one. Then:
//
//   solve(A, b):
//     if no LU yet, or told to refactorise:  factorise A, x = LU^-1 b
//     else: x = BiCGSTAB(A, b, preconditioner LU^-1 of an older A), from x = 0,
//           until |b - A x| <= tolerance |b| (true residual, checked after the iterations)
//           if not reached within max_iterations: factorise A, x = LU^-1 b
//           if reached in more than refresh_iterations: the next solve factorises
//
// The Krylov arithmetic is serial (Eigen's BiCGSTAB on a column-major matrix), so the result
// does not depend on the number of threads.
#include <Eigen/Sparse>

#include "flow/sparse_direct_solver.hpp"

namespace flotsam {

struct LinearSolverOptions {
  LinearSolverKind kind = LinearSolverKind::umfpack;
  bool reuse_factorisation = false;  // keep the LU across solves (BiCGSTAB preconditioner)
  // [-] |b - A x| / |b| a reused LU's solve must reach. The water balance is computed from the
  // assembled rows (water_balance.hpp), so an inexact solve shows there: 1e-12 keeps it within
  // the tests' 1e-9 (relative to the volume) over their runs.
  double tolerance = 1e-12;
  int max_iterations = 20;  // BiCGSTAB iterations (2 LU solves, 2 products with A each)
  // BiCGSTAB iterations above which the LU has aged: the next solve factorises afresh. On the
  // paper's channel (1 h at dt = 1 s) 2 costs 12 factorisations per 900 steps and cuts a step
  // by a quarter against never refreshing (docs/performance.md).
  int refresh_iterations = 2;
};

struct LinearSolverCounts {
  long solves = 0;
  long factorisations = 0;     // numeric LU factorisations
  long krylov_iterations = 0;  // BiCGSTAB iterations, all solves
  long krylov_failures = 0;    // reused LU solves that missed the tolerance (then refactorised)
};

class LinearSolver {
 public:
  explicit LinearSolver(LinearSolverOptions options = {});

  /// x = A^-1 b. A's pattern must be the one of the first call. False when a factorisation
  /// failed: failure() and failure_message() say why (SparseDirectSolver).
  bool solve(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x);
  /// The next solve factorises A afresh.
  void refactorise() { reusable_ = false; }

  const LinearSolverCounts& counts() const { return counts_; }
  FactorizationFailure failure() const { return direct_.failure(); }
  const std::string& failure_message() const { return direct_.failure_message(); }

 private:
  bool solve_direct(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x);

  LinearSolverOptions options_;
  SparseDirectSolver direct_;
  bool reusable_ = false;  // direct_ holds an LU that may be reused
  LinearSolverCounts counts_;
};

}  // namespace flotsam
