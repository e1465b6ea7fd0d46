// Verifies the reverse Cuthill-McKee numbering (node_ordering.hpp): a permutation, which brings
// a grid whose nodes were numbered at random back to a bandwidth of the order of the grid's width,
// and numbers every part of a disconnected pattern.
#include "flow/fem/node_ordering.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace flotsam {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// The 5-point pattern of a k x k grid, its nodes numbered by `label`.
SparseMatrix grid_pattern(int k, const std::vector<int>& label) {
  std::vector<Eigen::Triplet<double>> t;
  for (int y = 0; y < k; ++y)
    for (int x = 0; x < k; ++x) {
      const int i = label[x + k * y];
      t.emplace_back(i, i, 1.0);
      if (x + 1 < k) {
        t.emplace_back(i, label[x + 1 + k * y], 1.0);
        t.emplace_back(label[x + 1 + k * y], i, 1.0);
      }
      if (y + 1 < k) {
        t.emplace_back(i, label[x + k * (y + 1)], 1.0);
        t.emplace_back(label[x + k * (y + 1)], i, 1.0);
      }
    }
  SparseMatrix A(k * k, k * k);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

int bandwidth(const SparseMatrix& A, const std::vector<int>& order) {
  int band = 0;
  for (int j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator e(A, j); e; ++e)
      band = std::max(band, std::abs(order[e.row()] - order[j]));
  return band;
}

TEST(ReverseCuthillMcKee, RestoresAGridsBandwidth) {
  const int k = 40;
  std::vector<int> label(k * k);
  for (int i = 0; i < k * k; ++i) label[i] = i;
  std::shuffle(label.begin(), label.end(), std::mt19937(7));
  const SparseMatrix A = grid_pattern(k, label);
  std::vector<int> identity(k * k);
  for (int i = 0; i < k * k; ++i) identity[i] = i;
  ASSERT_GT(bandwidth(A, identity), 10 * k);  // the shuffle spread the neighbours
  const std::vector<int> order = reverse_cuthill_mckee(A);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, identity);  // a permutation
  // Levels from a corner are the grid's anti-diagonals (at most k nodes): a neighbour lies in the
  // same or the next level, so at most 2k - 1 places away.
  EXPECT_LT(bandwidth(A, order), 2 * k);
}

TEST(ReverseCuthillMcKee, NumbersEveryPart) {
  // Two separate 3 x 3 grids' patterns side by side and an isolated node.
  std::vector<Eigen::Triplet<double>> t;
  const SparseMatrix g = grid_pattern(3, {0, 1, 2, 3, 4, 5, 6, 7, 8});
  for (int j = 0; j < 9; ++j)
    for (SparseMatrix::InnerIterator e(g, j); e; ++e) {
      t.emplace_back(static_cast<int>(e.row()), j, 1.0);
      t.emplace_back(static_cast<int>(e.row()) + 9, j + 9, 1.0);
    }
  t.emplace_back(18, 18, 1.0);
  SparseMatrix A(19, 19);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  std::vector<int> order = reverse_cuthill_mckee(A);
  std::sort(order.begin(), order.end());
  for (int i = 0; i < 19; ++i) EXPECT_EQ(order[i], i);
}

}  // namespace
}  // namespace flotsam
