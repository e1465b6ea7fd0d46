// Eigen's sparse module trips GCC's -Wnull-dereference inside its own headers.
#pragma GCC diagnostic ignored "-Wnull-dereference"
#include "flow/linear_solver.hpp"

#include <Eigen/IterativeLinearSolvers>

namespace flotsam {

namespace {

/// Eigen preconditioner that applies the LU of an earlier matrix: M^-1 r = (LU)^-1 r.
class StoredLuPreconditioner {
 public:
  using StorageIndex = int;
  enum { ColsAtCompileTime = Eigen::Dynamic, MaxColsAtCompileTime = Eigen::Dynamic };

  StoredLuPreconditioner() = default;
  template <class Matrix>
  explicit StoredLuPreconditioner(const Matrix&) {}
  template <class Matrix>
  StoredLuPreconditioner& analyzePattern(const Matrix&) {
    return *this;
  }
  template <class Matrix>
  StoredLuPreconditioner& factorize(const Matrix&) {
    return *this;
  }
  template <class Matrix>
  StoredLuPreconditioner& compute(const Matrix&) {
    return *this;
  }

  void set(const SparseDirectSolver& lu) { lu_ = &lu; }
  Eigen::VectorXd solve(const Eigen::VectorXd& r) const { return lu_->solve(r); }
  Eigen::ComputationInfo info() const { return Eigen::Success; }

 private:
  const SparseDirectSolver* lu_ = nullptr;
};

}  // namespace

LinearSolver::LinearSolver(LinearSolverOptions options)
    : options_(options), direct_(options.kind) {}

bool LinearSolver::solve_direct(const SparseMatrix& A, const Eigen::VectorXd& b,
                                Eigen::VectorXd& x) {
  ++counts_.factorisations;
  reusable_ = false;
  if (!direct_.factorize(A)) return false;
  reusable_ = options_.reuse_factorisation;
  x = direct_.solve(b);
  return true;
}

bool LinearSolver::solve(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  ++counts_.solves;
  if (!reusable_) return solve_direct(A, b, x);
  Eigen::BiCGSTAB<SparseMatrix, StoredLuPreconditioner> krylov;
  krylov.preconditioner().set(direct_);
  krylov.setTolerance(options_.tolerance);
  krylov.setMaxIterations(options_.max_iterations);
  krylov.compute(A);
  x = krylov.solve(b);
  counts_.krylov_iterations += krylov.iterations();
  // BiCGSTAB tests its updated residual; the true one may have drifted from it.
  const double b_norm = b.norm();
  if (krylov.info() == Eigen::Success && x.allFinite() &&
      (b - A * x).norm() <= options_.tolerance * b_norm) {
    if (krylov.iterations() > options_.refresh_iterations) reusable_ = false;
    return true;
  }
  ++counts_.krylov_failures;
  return solve_direct(A, b, x);
}

}  // namespace flotsam
