// Verifies that the sparse LU solves a small system, and that a singular one is reported as
// singular, with the solver's status and the matrix size in the message (not as a lack of memory
// or a generic failure), for UMFPACK and KLU.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "flow/fem/sparse_direct_solver.hpp"

namespace flotsam {
namespace {

SparseMatrix matrix_of(const std::vector<Eigen::Triplet<double, int>>& entries, int n) {
  SparseMatrix A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  A.makeCompressed();
  return A;
}

class SparseDirectSolverTest : public ::testing::TestWithParam<LinearSolverKind> {};

TEST_P(SparseDirectSolverTest, SolvesARegularSystem) {
  const SparseMatrix A =
      matrix_of({{0, 0, 4.0}, {1, 0, 1.0}, {0, 1, 2.0}, {1, 1, 3.0}, {2, 2, 5.0}}, 3);
  const Eigen::Vector3d x(1.0, -2.0, 0.5);
  SparseDirectSolver solver(GetParam());
  ASSERT_TRUE(solver.factorize(A));
  EXPECT_EQ(solver.failure(), FactorizationFailure::none);
  EXPECT_LT((solver.solve(A * x) - x).norm(), 1e-14);
}

TEST_P(SparseDirectSolverTest, ASingularSystemIsReportedAsSingular) {
  // Row 1 = 2 x row 0; the pattern is full, so only the numbers make it singular.
  const SparseMatrix A =
      matrix_of({{0, 0, 1.0}, {1, 0, 2.0}, {0, 1, 2.0}, {1, 1, 4.0}, {2, 2, 1.0}}, 3);
  SparseDirectSolver solver(GetParam());
  EXPECT_FALSE(solver.factorize(A));
  EXPECT_EQ(solver.failure(), FactorizationFailure::singular);
  EXPECT_THAT(solver.failure_message(), ::testing::HasSubstr("singular matrix (status 1)"));
  EXPECT_THAT(solver.failure_message(), ::testing::HasSubstr("the 3 x 3 matrix with 5 entries"));
  EXPECT_THAT(solver.failure_message(), ::testing::Not(::testing::HasSubstr("memory")));
}

INSTANTIATE_TEST_SUITE_P(UmfpackAndKlu, SparseDirectSolverTest,
                         ::testing::Values(LinearSolverKind::umfpack, LinearSolverKind::klu));

}  // namespace
}  // namespace flotsam
