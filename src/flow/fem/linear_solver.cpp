// Eigen's sparse module trips GCC's -Wnull-dereference inside its own headers.
#pragma GCC diagnostic ignored "-Wnull-dereference"
#include "flow/fem/linear_solver.hpp"

namespace flotsam {

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
  if (x.size() != b.size()) x = Eigen::VectorXd::Zero(b.size());
  const double target = options_.tolerance * b.norm();
  Eigen::VectorXd r = b - A * x;
  double r_norm = r.norm();
  // The LU has aged too far for A: out of iterations, too slow, diverging or not finite.
  const auto aged = [&] {
    ++counts_.refinement_failures;
    return solve_direct(A, b, x);
  };
  int k = 0;
  while (r_norm > target) {
    if (k == options_.max_iterations) return aged();
    const double before = r_norm;
    x += direct_.solve(r);
    r = b - A * x;
    r_norm = r.norm();
    ++k;
    ++counts_.refinement_iterations;
    if (!(r_norm <= options_.max_contraction * before)) return aged();
  }
  if (k > options_.refresh_iterations) reusable_ = false;
  return true;
}

}  // namespace flotsam
