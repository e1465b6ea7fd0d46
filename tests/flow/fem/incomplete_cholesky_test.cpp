// Verifies the zero fill-in incomplete Cholesky factor (incomplete_cholesky.hpp) as the momentum
// predictor (M-21) uses it: exact where IC(0) has no fill (a tridiagonal matrix), and, on a grid
// matrix of the predictor's form diag(d) + s K with fixed entries, a preconditioner with which
// conjugate gradients reach their tolerance, agree with a direct Cholesky solve, and need a
// bounded number of iterations, fewer than with Jacobi's. The predictor's two components at once
// (pair_conjugate_gradients.hpp, IncompleteCholesky::solve_pair) are those single solves.
#include "flow/fem/incomplete_cholesky.hpp"

#include <gtest/gtest.h>

#include <omp.h>

#include <Eigen/SparseCholesky>
#include <cmath>

#include "../../support/conjugate_gradients.hpp"
#include "flow/fem/node_ordering.hpp"
#include "flow/fem/pair_conjugate_gradients.hpp"

namespace flotsam {
namespace {

using SparseMatrix = IncompleteCholesky::SparseMatrix;
using Vector = Eigen::VectorXd;

// The P1 stiffness of the unit square's k x k grid of nodes (right triangles), spacing h = 1/(k-1):
// the 5-point stencil (4, -1, -1, -1, -1) inside, every row summing to zero (Neumann).
SparseMatrix grid_stiffness(int k) {
  std::vector<Eigen::Triplet<double>> t;
  const auto id = [k](int x, int y) { return x + k * y; };
  for (int y = 0; y < k; ++y)
    for (int x = 0; x < k; ++x)
      for (auto [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
        if (x + dx >= k || y + dy >= k) continue;
        const int i = id(x, y), j = id(x + dx, y + dy);
        t.emplace_back(i, i, 1.0);
        t.emplace_back(j, j, 1.0);
        t.emplace_back(i, j, -1.0);
        t.emplace_back(j, i, -1.0);
      }
  SparseMatrix K(k * k, k * k);
  K.setFromTriplets(t.begin(), t.end());
  K.makeCompressed();
  return K;
}

// diag(d) + s K with the fixed rows and columns of the identity, and b with the fixed values
// eliminated, as a matrix for a direct solve.
SparseMatrix assembled(const SparseMatrix& K, double s, const Vector& d,
                       const std::vector<char>& fixed) {
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < K.cols(); ++j)
    for (SparseMatrix::InnerIterator e(K, j); e; ++e) {
      const int i = static_cast<int>(e.row());
      if (fixed[i] || fixed[j]) continue;
      t.emplace_back(i, j, s * e.value() + (i == j ? d[i] : 0.0));
    }
  for (int i = 0; i < K.cols(); ++i)
    if (fixed[i]) t.emplace_back(i, i, 1.0);
  SparseMatrix A(K.rows(), K.cols());
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

TEST(IncompleteCholesky, IsExactOnATridiagonalMatrixWithinEachPart) {
  // 1D: the exact Cholesky factor of a tridiagonal matrix has no fill, so IC(0) is that of A's
  // parts (row_parts.hpp: the entries coupling two parts dropped), up to its entries' rounding
  // to single precision (relative 6e-8 each, times cond(A) = 81 here); A itself it is not.
  const int n = 50;
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i + 1 < n; ++i) {
    t.emplace_back(i, i, 1.0);
    t.emplace_back(i + 1, i + 1, 1.0);
    t.emplace_back(i, i + 1, -1.0);
    t.emplace_back(i + 1, i, -1.0);
  }
  SparseMatrix K(n, n);
  K.setFromTriplets(t.begin(), t.end());
  K.makeCompressed();
  const Vector d = Vector::Constant(n, 0.1);
  const std::vector<char> fixed(n, 0);
  IncompleteCholesky factor;
  factor.analyse(K);
  factor.factorise(K, 2.0, d, fixed);
  EXPECT_EQ(factor.shift(), 0.0);
  const SparseMatrix A = assembled(K, 2.0, d, fixed);
  const RowParts parts(n);
  ASSERT_GT(RowParts::count, 1);
  SparseMatrix A_parts = A;  // A without the entries between parts
  A_parts.prune([&](int i, int j, double) { return parts.part_of(i) == parts.part_of(j); });
  ASSERT_EQ(A_parts.nonZeros(), A.nonZeros() - 2 * (RowParts::count - 1));
  Vector x(n);
  for (int i = 0; i < n; ++i) x[i] = std::sin(0.3 * i) + 0.01 * i;
  Vector z;
  factor.solve(A_parts * x, z);
  EXPECT_LT((z - x).norm() / x.norm(), 1e-5);
  factor.solve(A * x, z);
  EXPECT_GT((z - x).norm() / x.norm(), 1e-3);
}

// The predictor's system on a k x k grid: mass m h^2 / dt on the diagonal (dt = 1 s, m = 1),
// nu theta K with nu dt / h^2 = 2 at k = 64 (viscosity dominant at the finest grid, as at the
// piers), the left column fixed at given values.
struct GridSystem {
  SparseMatrix K;
  Vector d, b, x_fixed;
  std::vector<char> fixed;
  double s;
};

GridSystem grid_system(int k) {
  GridSystem g;
  g.K = grid_stiffness(k);
  const int n = k * k;
  const double h = 1.0 / (k - 1), nu = 2.0 / (63.0 * 63.0), theta = 0.6;  // [m], [m^2/s], [-]
  g.s = theta * nu;
  g.d = Vector::Constant(n, h * h);
  for (int i = 0; i < n; ++i) g.d[i] *= 1.0 + 0.5 * std::sin(0.7 * i);  // uneven lumped mass
  g.fixed.assign(n, 0);
  g.x_fixed = Vector::Zero(n);
  g.b.resize(n);
  for (int i = 0; i < n; ++i) {
    const int x = i % k, y = i / k;
    g.b[i] = h * h * std::cos(3.0 * x * h) * std::sin(2.0 * y * h);
    if (x == 0) {
      g.fixed[i] = 1;
      g.x_fixed[i] = 0.5 + y * h;
    }
  }
  return g;
}

// Conjugate gradients from zero (the fixed values set) with the given preconditioner.
template <class Precondition>
int solve(const GridSystem& g, const Precondition& precondition, Vector& x) {
  x = g.x_fixed;
  const auto apply = [&](const Vector& p, Vector& y) {
    y.noalias() = g.s * (g.K * p);
    y += g.d.cwiseProduct(p);
  };
  return conjugate_gradients(apply, precondition, g.fixed, g.b, x, 1e-10, 1000);
}

// The same system solved directly (CHOLMOD is not needed: Eigen's simplicial LL^T), the fixed
// values eliminated.
Vector direct_solution(const GridSystem& g) {
  const SparseMatrix A = assembled(g.K, g.s, g.d, g.fixed);
  Vector rhs = g.b;
  const Vector coupling = g.s * (g.K * g.x_fixed);
  for (int i = 0; i < rhs.size(); ++i) rhs[i] = g.fixed[i] ? g.x_fixed[i] : rhs[i] - coupling[i];
  Eigen::SimplicialLLT<SparseMatrix> llt(A);
  return llt.solve(rhs);
}

TEST(IncompleteCholesky, PreconditionedSolveMatchesTheDirectOneInBoundedIterations) {
  for (int k : {16, 32, 64}) {
    const GridSystem g = grid_system(k);
    IncompleteCholesky factor;
    factor.analyse(g.K);
    factor.factorise(g.K, g.s, g.d, g.fixed);
    Vector x;
    const int ic = solve(
        g, [&](const Vector& r, Vector& z) { factor.solve(r, z); }, x);
    const Vector exact = direct_solution(g);
    // |r| <= 1e-10 |b| and cond(A) < 1e3 here: the error within 1e-7 of the solution's size.
    EXPECT_LT((x - exact).norm() / exact.norm(), 1e-7) << k;
    for (int i = 0; i < x.size(); ++i)
      if (g.fixed[i]) {
        EXPECT_EQ(x[i], g.x_fixed[i]);
      }
    const Vector diagonal = g.d + g.s * Vector(g.K.diagonal());
    Vector y;
    const int jacobi = solve(
        g, [&](const Vector& r, Vector& z) { z = r.cwiseQuotient(diagonal); }, y);
    EXPECT_GT(ic, 0) << k;
    EXPECT_LE(ic, 20) << k;              // converged, in few iterations
    EXPECT_LT(4 * ic, 3 * jacobi) << k;  // and in less than 3/4 of Jacobi's (half at k = 64)
  }
}

TEST(IncompleteCholesky, WorksOnTheReorderedSystem) {
  // The predictor factorises in reverse Cuthill-McKee order: same solution, no more iterations
  // than in the grid's natural (already local) order plus a few.
  const int k = 32;
  const GridSystem g = grid_system(k);
  const std::vector<int> order = reverse_cuthill_mckee(g.K);
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P(k * k);
  for (int i = 0; i < k * k; ++i) P.indices()[i] = order[i];
  GridSystem r = g;
  r.K = g.K.twistedBy(P);
  r.K.makeCompressed();
  r.d = P * g.d;
  r.b = P * g.b;
  r.x_fixed = P * g.x_fixed;
  for (int i = 0; i < k * k; ++i) r.fixed[order[i]] = g.fixed[i];
  IncompleteCholesky natural, reordered;
  natural.analyse(g.K);
  natural.factorise(g.K, g.s, g.d, g.fixed);
  reordered.analyse(r.K);
  reordered.factorise(r.K, r.s, r.d, r.fixed);
  Vector x, y;
  const int n_natural = solve(
      g, [&](const Vector& v, Vector& z) { natural.solve(v, z); }, x);
  const int n_reordered = solve(
      r, [&](const Vector& v, Vector& z) { reordered.solve(v, z); }, y);
  EXPECT_LT((P.transpose() * y - x).norm() / x.norm(), 1e-7);
  EXPECT_LE(n_reordered, n_natural + 3);
}

// Two vectors interleaved (entry 2 i + c) from two apart, and back.
std::vector<double> interleaved(const Vector& a, const Vector& b) {
  std::vector<double> out(2 * a.size());
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    out[2 * i] = a[i];
    out[2 * i + 1] = b[i];
  }
  return out;
}

Vector component(const std::vector<double>& pair, int c) {
  Vector out(pair.size() / 2);
  for (Eigen::Index i = 0; i < out.size(); ++i) out[i] = pair[2 * i + c];
  return out;
}

TEST(IncompleteCholesky, PairSolveIsTheSingleSolveOnEachComponent) {
  // The same operations in the same order on each component: bit-identical to solve.
  const GridSystem g = grid_system(32);
  IncompleteCholesky factor;
  factor.analyse(g.K);
  factor.factorise(g.K, g.s, g.d, g.fixed);
  Vector r_0 = g.b, r_1(g.b.size());
  for (Eigen::Index i = 0; i < r_1.size(); ++i) r_1[i] = g.fixed[i] ? 0.0 : std::cos(0.37 * i);
  for (Eigen::Index i = 0; i < r_0.size(); ++i)
    if (g.fixed[i]) r_0[i] = 0.0;
  const std::vector<double> r = interleaved(r_0, r_1);
  std::vector<double> z(r.size());
  const std::array<double, 2> rz = factor.solve_pair(r, z);
  Vector z_0, z_1;
  factor.solve(r_0, z_0);
  factor.solve(r_1, z_1);
  for (Eigen::Index i = 0; i < z_0.size(); ++i) {
    EXPECT_EQ(z[2 * i], z_0[i]);
    EXPECT_EQ(z[2 * i + 1], z_1[i]);
  }
  // r . z summed in another order than Eigen's dot: equal to round-off (1e-12 relative).
  EXPECT_NEAR(rz[0], r_0.dot(z_0), 1e-12 * std::abs(r_0.dot(z_0)));
  EXPECT_NEAR(rz[1], r_1.dot(z_1), 1e-12 * std::abs(r_1.dot(z_1)));
}

// Both components of a grid system at once: b and a second load, the same fixed values.
std::array<int, 2> solve_pair(const GridSystem& g, const Vector& b_1,
                              const IncompleteCholesky& factor, std::vector<double>& x) {
  x = interleaved(g.x_fixed, g.x_fixed);
  const std::vector<double> b = interleaved(g.b, b_1);
  PairWorkspace work;
  const auto apply = [&](const std::vector<double>& p, std::vector<double>& y) {
    return pair_product(g.K, g.s, g.d.data(), &g.fixed, p, y);
  };
  const auto precondition = [&](const std::vector<double>& r, std::vector<double>& z) {
    return factor.solve_pair(r, z);
  };
  return pair_conjugate_gradients(apply, precondition, g.fixed, b, x, 1e-10, 1000, work);
}

TEST(PairConjugateGradients, SolvesBothComponentsAsTheSingleSolvesDo) {
  const GridSystem g = grid_system(64);
  IncompleteCholesky factor;
  factor.analyse(g.K);
  factor.factorise(g.K, g.s, g.d, g.fixed);
  Vector b_1(g.b.size());
  for (Eigen::Index i = 0; i < b_1.size(); ++i) b_1[i] = 1e-3 * std::sin(0.011 * i);
  std::vector<double> x;
  const std::array<int, 2> iterations = solve_pair(g, b_1, factor, x);
  GridSystem g_1 = g;
  g_1.b = b_1;
  const auto precondition = [&](const Vector& r, Vector& z) { factor.solve(r, z); };
  Vector single_0, single_1;
  const int n_0 = solve(g, precondition, single_0), n_1 = solve(g_1, precondition, single_1);
  // Each component converges as its single solve does (the sums' order may move the last
  // iteration by one), to the direct solution within 1e-7 (|r| <= 1e-10 |b|, cond(A) < 1e3).
  EXPECT_NEAR(iterations[0], n_0, 1);
  EXPECT_NEAR(iterations[1], n_1, 1);
  EXPECT_GT(iterations[0], 0);
  EXPECT_LT((component(x, 0) - direct_solution(g)).norm() / direct_solution(g).norm(), 1e-7);
  EXPECT_LT((component(x, 1) - direct_solution(g_1)).norm() / direct_solution(g_1).norm(), 1e-7);
  for (Eigen::Index i = 0; i < single_0.size(); ++i)
    if (g.fixed[i]) {
      EXPECT_EQ(x[2 * i], g.x_fixed[i]);
      EXPECT_EQ(x[2 * i + 1], g.x_fixed[i]);
    }
}

TEST(PairConjugateGradients, AComponentSolvedAtTheStartStaysFrozen) {
  // Component 1's start is its solution (b_1 = A x_start: zero residual): no iteration, x_1
  // unchanged, while component 0 converges as alone.
  const GridSystem g = grid_system(32);
  IncompleteCholesky factor;
  factor.analyse(g.K);
  factor.factorise(g.K, g.s, g.d, g.fixed);
  Vector b_1 = g.s * (g.K * g.x_fixed) + g.d.cwiseProduct(g.x_fixed);
  std::vector<double> x;
  const std::array<int, 2> iterations = solve_pair(g, b_1, factor, x);
  EXPECT_EQ(iterations[1], 0);
  EXPECT_GT(iterations[0], 0);
  EXPECT_LE(iterations[0], 20);
  for (Eigen::Index i = 0; i < g.x_fixed.size(); ++i) EXPECT_EQ(x[2 * i + 1], g.x_fixed[i]);
  EXPECT_LT((component(x, 0) - direct_solution(g)).norm() / direct_solution(g).norm(), 1e-7);
}

TEST(PairConjugateGradients, OneAndTwoThreadsGiveBitIdenticalSolutions) {
  // A system large enough for the parts to be swept on the threads (row_parts.hpp): the factor,
  // the products, the sweeps and the sums do not depend on the thread count.
  const GridSystem g = grid_system(240);
  ASSERT_GE(g.K.cols(), RowParts::parallel_rows);
  Vector b_1(g.b.size());
  for (Eigen::Index i = 0; i < b_1.size(); ++i) b_1[i] = 1e-3 * std::sin(0.011 * i);
  const int saved = omp_get_max_threads();
  std::array<std::vector<double>, 2> x;
  std::array<std::array<int, 2>, 2> iterations{};
  for (int threads = 1; threads <= 2; ++threads) {
    omp_set_num_threads(threads);
    IncompleteCholesky factor;
    factor.analyse(g.K);
    factor.factorise(g.K, g.s, g.d, g.fixed);
    iterations[threads - 1] = solve_pair(g, b_1, factor, x[threads - 1]);
  }
  omp_set_num_threads(saved);
  EXPECT_GT(iterations[0][0], 0);
  EXPECT_EQ(iterations[0], iterations[1]);
  EXPECT_EQ(x[0], x[1]);
  EXPECT_LT((component(x[0], 0) - direct_solution(g)).norm() / direct_solution(g).norm(), 1e-7);
}

}  // namespace
}  // namespace flotsam
