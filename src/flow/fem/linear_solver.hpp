#pragma once
// Solves the flow system A x = b of each linearised step (linear_system.hpp) with a sparse LU
// (sparse_direct_solver.hpp), either freshly factorised every time, or kept across steps: the
// matrix changes little from one step to the next, so the last LU, of an older A, is a good
// approximate inverse of the new one. Then (iterative refinement with an aged LU):
//
//   solve(A, b, x):
//     if no LU yet, or told to refactorise:  factorise A, x = LU^-1 b
//     else, from the first guess x (the last state):
//       repeat  r = b - A x,  x += LU^-1 r   until |r| <= tolerance |b| (the true residual)
//       if an iteration shrinks |r| by less than max_contraction, or max_iterations pass:
//         factorise A, x = LU^-1 b
//       if it took more than refresh_iterations: the next solve factorises
//
// Each iteration costs one LU solve and one product with A, half what a BiCGSTAB iteration
// costs; on the paper's channel an iteration shrinks the residual 1e3-1e4 times, so a Krylov
// method would not take fewer solves (docs/performance.md). The arithmetic is serial, so the
// result does not depend on the number of threads.
#include <Eigen/Sparse>

#include "flow/fem/sparse_direct_solver.hpp"

namespace flotsam {

struct LinearSolverOptions {
  LinearSolverKind kind = LinearSolverKind::umfpack;
  bool reuse_factorisation = false;  // keep the LU across solves (iterative refinement)
  // [-] |b - A x| / |b| a reused LU's solve must reach. The water balance is computed from the
  // assembled rows (water_balance.hpp), so an inexact solve shows there: 1e-12 keeps it within
  // the tests' 1e-9 (relative to the volume) over their runs.
  double tolerance = 1e-12;
  int max_iterations = 20;       // refinement iterations (an LU solve and a product with A each)
  double max_contraction = 0.5;  // [-] |r| must shrink at least this much per iteration
  // Iterations above which the LU has aged: the next solve factorises afresh. On the paper's
  // channel at dt = 1 s (docs/performance.md): over the first 300 s, 3 is fastest (2 refreshes
  // 36 times, 4 and 6 take more solves); over the hour 3, 4 and 5 take 172, 168 and 184 s.
  int refresh_iterations = 3;
};

struct LinearSolverCounts {
  long solves = 0;
  long factorisations = 0;         // numeric LU factorisations
  long refinement_iterations = 0;  // iterations with a reused LU, all solves
  long refinement_failures = 0;    // reused LU solves that stalled (then refactorised)
};

class LinearSolver {
 public:
  explicit LinearSolver(LinearSolverOptions options = {});

  /// x = A^-1 b. A's pattern must be the one of the first call. On entry x is the first guess
  /// of the refinement when it has b's size (zero otherwise). False when a factorisation
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
