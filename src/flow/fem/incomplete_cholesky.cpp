#include "flow/fem/incomplete_cholesky.hpp"

#include <cmath>

#include "core/error.hpp"

namespace flotsam {

// K is symmetric: its column i is its row i, and the entries with index <= i form row i of the
// lower triangle, in increasing column, the diagonal last; those of i's part are L's row i.
void IncompleteCholesky::analyse(const SparseMatrix& K) {
  const int n = static_cast<int>(K.cols());
  const int* outer = K.outerIndexPtr();
  index_ = K.innerIndexPtr();
  parts_ = RowParts(n);
  k_start_.assign(n, 0);
  row_start_.assign(n + 1, 0);
  for (int i = 0; i < n; ++i) {
    const int first = parts_.start[parts_.part_of(i)];  // the part's first row
    int p = outer[i];
    while (p < outer[i + 1] && index_[p] < first) ++p;
    k_start_[i] = p;
    while (p < outer[i + 1] && index_[p] < i) ++p;
    if (p == outer[i + 1] || index_[p] != i)
      throw_run_error("incomplete Cholesky: row {} of the pattern has no diagonal entry", i);
    row_start_[i + 1] = row_start_[i] + (p - k_start_[i]) + 1;
  }
  value_.assign(static_cast<size_t>(row_start_[n]), 0.0f);
  marker_.assign(n, -1);
}

void IncompleteCholesky::factorise(const SparseMatrix& K, double s, const Eigen::VectorXd& d,
                                   const std::vector<char>& fixed) {
  for (double shift = 0.0;; shift = shift == 0.0 ? 1e-3 : 2.0 * shift) {
    if (try_factorise(K, s, d, fixed, shift)) {
      shift_ = shift;
      return;
    }
    if (shift > 1e3) throw_run_error("incomplete Cholesky: the matrix is not positive definite");
  }
}

// Row by row: L_ij = (A_ij - sum_{k<j} L_ik L_jk) / L_jj for j < i in the pattern,
// L_ii = sqrt(A_ii (1 + shift) - sum_{k<i} L_ik^2); the sums over the pattern's common columns.
bool IncompleteCholesky::try_factorise(const SparseMatrix& K, double s, const Eigen::VectorXd& d,
                                       const std::vector<char>& fixed, double shift) {
  const int n = static_cast<int>(row_start_.size()) - 1;
  for (int i = 0; i < n; ++i) {
    const int begin = row_start_[i], diagonal = row_start_[i + 1] - 1;
    const double* k = K.valuePtr() + k_start_[i] - begin;  // k[p]: K's value of L's entry p
    if (fixed[i]) {
      for (int p = begin; p < diagonal; ++p) value_[p] = 0.0f;
      value_[diagonal] = 1.0f;
      continue;
    }
    for (int p = begin; p < diagonal; ++p) marker_[column(i, p)] = p;
    double pivot = (d[i] + s * k[diagonal]) * (1.0 + shift);
    for (int p = begin; p < diagonal; ++p) {
      const int j = column(i, p);
      double sum = fixed[j] ? 0.0 : s * k[p];
      for (int q = row_start_[j]; q < row_start_[j + 1] - 1; ++q) {
        const int m = marker_[column(j, q)];
        if (m >= 0 && m < p) sum -= l(m) * l(q);
      }
      value_[p] = static_cast<float>(sum / l(row_start_[j + 1] - 1));
      pivot -= l(p) * l(p);
    }
    for (int p = begin; p < diagonal; ++p) marker_[column(i, p)] = -1;
    if (!(pivot > 0.0)) return false;
    value_[diagonal] = static_cast<float>(std::sqrt(pivot));
    if (!(value_[diagonal] > 0.0f) || !std::isfinite(value_[diagonal]))
      return false;  // float range
  }
  return true;
}

void IncompleteCholesky::solve(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  const int n = static_cast<int>(row_start_.size()) - 1;
  z = r;
  for (int i = 0; i < n; ++i) {  // L y = r
    double sum = z[i];
    const int diagonal = row_start_[i + 1] - 1;
    for (int p = row_start_[i]; p < diagonal; ++p) sum -= l(p) * z[column(i, p)];
    z[i] = sum / l(diagonal);
  }
  for (int i = n - 1; i >= 0; --i) {  // L^T z = y, by rows of L
    const int diagonal = row_start_[i + 1] - 1;
    const double z_i = z[i] / l(diagonal);
    z[i] = z_i;
    for (int p = row_start_[i]; p < diagonal; ++p) z[column(i, p)] -= l(p) * z_i;
  }
}

// solve's two sweeps on both components, part by part (no entry of L couples two parts):
// component c's operations are those of solve on it.
std::array<double, 2> IncompleteCholesky::solve_pair(const std::vector<double>& r,
                                                     std::vector<double>& z) const {
  return sum_over_parts(parts_, [&](int begin, int end) {
    for (int i = begin; i < end; ++i) {  // L y = r
      double sum_0 = r[2 * i], sum_1 = r[2 * i + 1];
      const int diagonal = row_start_[i + 1] - 1;
      const int* index = index_ + k_start_[i] - row_start_[i];  // index[p]: column of entry p
      for (int p = row_start_[i]; p < diagonal; ++p) {
        const int j = index[p];
        sum_0 -= l(p) * z[2 * j];
        sum_1 -= l(p) * z[2 * j + 1];
      }
      z[2 * i] = sum_0 / l(diagonal);
      z[2 * i + 1] = sum_1 / l(diagonal);
    }
    std::array<double, 2> rz{0.0, 0.0};
    for (int i = end - 1; i >= begin; --i) {  // L^T z = y, by rows of L; z_i final once divided
      const int diagonal = row_start_[i + 1] - 1;
      const int* index = index_ + k_start_[i] - row_start_[i];
      const double z_0 = z[2 * i] / l(diagonal), z_1 = z[2 * i + 1] / l(diagonal);
      z[2 * i] = z_0;
      z[2 * i + 1] = z_1;
      rz[0] += r[2 * i] * z_0;
      rz[1] += r[2 * i + 1] * z_1;
      for (int p = row_start_[i]; p < diagonal; ++p) {
        const int j = index[p];
        z[2 * j] -= l(p) * z_0;
        z[2 * j + 1] -= l(p) * z_1;
      }
    }
    return rz;
  });
}

}  // namespace flotsam
