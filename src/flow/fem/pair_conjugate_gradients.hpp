#pragma once
// Preconditioned conjugate gradients for two systems with one symmetric positive definite matrix,
// A x_c = b_c (c = 0, 1): the u and v components of the momentum predictor (M-21). The vectors
// are interleaved, entry 2 i + c holding component c of unknown i, so that every sweep reads the
// matrix and the preconditioner once for both components (the predictor's time at 500k elements
// is the memory traffic of those reads). Each component follows the single-system iteration of
// preconditioned conjugate gradients and stops on its own tolerance; its updates are then frozen
// while the other goes on. Every sweep runs by the rows' parts (row_parts.hpp): on the threads
// for a large system, with the same results on any number of them.
#include <Eigen/Sparse>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "flow/fem/row_parts.hpp"

namespace flotsam {

/// y = d .* x + s K x for both components (K symmetric, column-major: column i is row i), d
/// optional (nullptr: none); rows marked fixed (when `fixed` is given) are set to zero. Returns
/// x_c . y_c per component. The rows by parts (row_parts.hpp).
inline std::array<double, 2> pair_product(
    const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& K, double s, const double* d,
    const std::vector<char>* fixed, const std::vector<double>& x, std::vector<double>& y) {
  const int* outer = K.outerIndexPtr();
  const int* index = K.innerIndexPtr();
  const double* value = K.valuePtr();
  return sum_over_parts(RowParts(static_cast<int>(K.cols())), [&](int begin, int end) {
    std::array<double, 2> xy{0.0, 0.0};
    for (int i = begin; i < end; ++i) {
      if (fixed && (*fixed)[i]) {
        y[2 * i] = y[2 * i + 1] = 0.0;
        continue;
      }
      double sum_0 = 0.0, sum_1 = 0.0;
      for (int k = outer[i]; k < outer[i + 1]; ++k) {
        sum_0 += value[k] * x[2 * index[k]];
        sum_1 += value[k] * x[2 * index[k] + 1];
      }
      const double d_i = d ? d[i] : 0.0;
      y[2 * i] = d_i * x[2 * i] + s * sum_0;
      y[2 * i + 1] = d_i * x[2 * i + 1] + s * sum_1;
      xy[0] += x[2 * i] * y[2 * i];
      xy[1] += x[2 * i + 1] * y[2 * i + 1];
    }
    return xy;
  });
}

/// The work vectors of pair_conjugate_gradients, kept from one solve to the next.
struct PairWorkspace {
  std::vector<double> r, z, p, q;
};

/// Conjugate gradients for A x_c = b_c on the free entries (fixed ones keep their value in x),
/// vectors interleaved: apply(p, q) sets q = A p, zero at fixed entries, and returns p_c . q_c;
/// precondition(r, z) sets z = P^-1 r (zero at fixed entries where r is) and returns r_c . z_c.
/// Component c stops when |r_c| <= tolerance |b_c| (free entries). Returns the iterations per
/// component, max_iterations + 1 for one that did not converge.
template <class Apply, class Precondition>
std::array<int, 2> pair_conjugate_gradients(const Apply& apply, const Precondition& precondition,
                                            const std::vector<char>& fixed,
                                            const std::vector<double>& b, std::vector<double>& x,
                                            double tolerance, int max_iterations,
                                            PairWorkspace& w) {
  const int n = static_cast<int>(fixed.size());
  const RowParts parts(n);
  w.r.resize(2 * static_cast<size_t>(n));
  w.z.resize(w.r.size());
  w.p.resize(w.r.size());
  w.q.resize(w.r.size());
  // A sweep over the vectors' entries of each part, 2 begin to 2 end (both components).
  const auto entries = [&](const auto& body) {
    return sum_over_parts(parts, [&](int begin, int end) {
      std::array<double, 2> sum{0.0, 0.0};
      for (size_t k = 2 * static_cast<size_t>(begin); k < 2 * static_cast<size_t>(end); ++k)
        body(k, sum);
      return sum;
    });
  };
  apply(x, w.q);
  const std::array<double, 2> bb = entries([&](size_t k, std::array<double, 2>& sum) {
    const bool is_free = !fixed[k / 2];
    w.r[k] = is_free ? b[k] - w.q[k] : 0.0;
    if (is_free) sum[k & 1] += b[k] * b[k];
  });
  std::array<double, 2> rr =
      entries([&](size_t k, std::array<double, 2>& sum) { sum[k & 1] += w.r[k] * w.r[k]; });
  std::array<double, 2> stop{}, live{};
  std::array<int, 2> iterations{max_iterations + 1, max_iterations + 1};
  for (int c = 0; c < 2; ++c) {
    stop[c] = tolerance * std::max(std::sqrt(bb[c]), 1e-300);
    live[c] = std::sqrt(rr[c]) <= stop[c] ? 0.0 : 1.0;
    if (live[c] == 0.0) iterations[c] = 0;
  }
  if (live[0] + live[1] == 0.0) return iterations;
  std::array<double, 2> rz = precondition(w.r, w.z);
  entries([&](size_t k, std::array<double, 2>&) {
    w.p[k] = live[k & 1] * w.z[k];  // a frozen p is zero
  });
  for (int it = 1; it <= max_iterations; ++it) {
    const std::array<double, 2> pq = apply(w.p, w.q);
    std::array<double, 2> alpha{};
    for (int c = 0; c < 2; ++c) alpha[c] = live[c] != 0.0 ? rz[c] / pq[c] : 0.0;
    rr = entries([&](size_t k, std::array<double, 2>& sum) {
      x[k] += alpha[k & 1] * w.p[k];
      w.r[k] -= alpha[k & 1] * w.q[k];
      sum[k & 1] += w.r[k] * w.r[k];
    });
    for (int c = 0; c < 2; ++c)
      if (live[c] != 0.0 && std::sqrt(rr[c]) <= stop[c]) {
        live[c] = 0.0;
        iterations[c] = it;
      }
    if (live[0] + live[1] == 0.0) return iterations;
    const std::array<double, 2> rz_new = precondition(w.r, w.z);
    std::array<double, 2> beta{};
    for (int c = 0; c < 2; ++c) beta[c] = live[c] != 0.0 ? rz_new[c] / rz[c] : 0.0;
    entries([&](size_t k, std::array<double, 2>&) {
      w.p[k] = live[k & 1] * w.z[k] + beta[k & 1] * w.p[k];
    });
    rz = rz_new;
  }
  return iterations;
}

}  // namespace flotsam
