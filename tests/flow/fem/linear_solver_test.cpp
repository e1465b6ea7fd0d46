// Verifies that the linear solver that keeps its LU solves a slightly changed matrix by iterative
// refinement with the old LU, to its tolerance and without a new factorisation, and that it
// refactorises when the matrix changed too much for the refinement to converge, or when told to.
#include <gtest/gtest.h>

#include "flow/fem/linear_solver.hpp"

namespace flotsam {
namespace {

// Advection-diffusion on n points: -d u'' + c u' + s u, unsymmetric, with s the time term.
SparseMatrix advection_diffusion(int n, double c, double s) {
  std::vector<Eigen::Triplet<double, int>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, 2.0 + s);
    if (i > 0) entries.emplace_back(i, i - 1, -1.0 - c);
    if (i + 1 < n) entries.emplace_back(i, i + 1, -1.0 + c);
  }
  SparseMatrix A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  A.makeCompressed();
  return A;
}

double relative_residual(const SparseMatrix& A, const Eigen::VectorXd& x,
                         const Eigen::VectorXd& b) {
  return (b - A * x).norm() / b.norm();
}

// A solver that keeps its LU, which it has factorised from a first matrix (c = 0.3), and the
// right-hand side of every solve.
struct KeptLu {
  static constexpr int n = 400;
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  LinearSolver solver;
  Eigen::VectorXd x;

  explicit KeptLu(LinearSolverOptions options = {}) : solver(with_reuse(options)) {
    EXPECT_TRUE(solver.solve(advection_diffusion(n, 0.3, 0.1), b, x));
    EXPECT_EQ(solver.counts().factorisations, 1);
  }
  static LinearSolverOptions with_reuse(LinearSolverOptions options) {
    options.reuse_factorisation = true;
    return options;
  }
  const LinearSolverCounts& counts() const { return solver.counts(); }
};

// The first matrix with its values a few per cent off, same pattern.
SparseMatrix slightly_changed() {
  return advection_diffusion(KeptLu::n, 0.31, 0.1);
}

TEST(LinearSolver, ReusedLuSolvesASlightlyChangedMatrixToItsTolerance) {
  KeptLu s;
  const SparseMatrix A = slightly_changed();
  ASSERT_TRUE(s.solver.solve(A, s.b, s.x));
  EXPECT_LE(relative_residual(A, s.x, s.b), 1e-12);
  EXPECT_EQ(s.counts().factorisations, 1);
  EXPECT_GT(s.counts().refinement_iterations, 0);

  s.solver.refactorise();
  ASSERT_TRUE(s.solver.solve(A, s.b, s.x));
  EXPECT_EQ(s.counts().factorisations, 2);
}

TEST(LinearSolver, RefactorisesWhenTheRefinementStalls) {
  KeptLu s;
  const SparseMatrix A = advection_diffusion(KeptLu::n, -0.9, 0.001);  // far from the first
  ASSERT_TRUE(s.solver.solve(A, s.b, s.x));
  EXPECT_EQ(s.counts().refinement_failures, 1);
  EXPECT_EQ(s.counts().factorisations, 2);
  EXPECT_LE(relative_residual(A, s.x, s.b), 1e-12);
}

TEST(LinearSolver, AnExactFirstGuessNeedsNoIteration) {
  KeptLu s;
  const SparseMatrix A = slightly_changed();
  const Eigen::VectorXd exact = Eigen::SparseLU<SparseMatrix>(A).solve(s.b);
  ASSERT_LE(relative_residual(A, exact, s.b), 1e-13);
  Eigen::VectorXd guess = exact;
  ASSERT_TRUE(s.solver.solve(A, s.b, guess));
  EXPECT_EQ(s.counts().refinement_iterations, 0);
  EXPECT_EQ(s.counts().factorisations, 1);
  EXPECT_EQ((guess - exact).norm(), 0.0);  // returned as given
}

TEST(LinearSolver, MaxIterationsBoundTheRefinement) {
  KeptLu s({.max_iterations = 1});
  const SparseMatrix A = slightly_changed();  // needs more than one iteration
  s.x.resize(0);                              // no first guess: from zero
  ASSERT_TRUE(s.solver.solve(A, s.b, s.x));
  EXPECT_EQ(s.counts().refinement_iterations, 1);
  EXPECT_EQ(s.counts().refinement_failures, 1);
  EXPECT_EQ(s.counts().factorisations, 2);
  EXPECT_LE(relative_residual(A, s.x, s.b), 1e-12);
}

TEST(LinearSolver, AnLuThatNeedsManyIterationsIsRefreshedAtTheNextSolve) {
  KeptLu s({.refresh_iterations = 0});
  const SparseMatrix A = slightly_changed();
  ASSERT_TRUE(s.solver.solve(A, s.b, s.x));  // refined (at least 1 iteration > 0): the LU aged
  EXPECT_EQ(s.counts().factorisations, 1);
  EXPECT_GT(s.counts().refinement_iterations, 0);
  ASSERT_TRUE(s.solver.solve(A, s.b, s.x));  // factorises afresh
  EXPECT_EQ(s.counts().factorisations, 2);
  EXPECT_LE(relative_residual(A, s.x, s.b), 1e-12);
}

TEST(LinearSolver, WithoutReuseEverySolveFactorises) {
  const int n = 50;
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
  LinearSolver solver;
  Eigen::VectorXd x;
  for (int k = 0; k < 3; ++k) ASSERT_TRUE(solver.solve(advection_diffusion(n, 0.1 * k, 1.0), b, x));
  EXPECT_EQ(solver.counts().factorisations, 3);
  EXPECT_EQ(solver.counts().refinement_iterations, 0);
}

}  // namespace
}  // namespace flotsam
