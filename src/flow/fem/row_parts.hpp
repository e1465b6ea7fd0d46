#pragma once
// A matrix's rows in a fixed number of runs of consecutive rows ("parts"), the unit of the
// momentum predictor's parallel loops (pair_conjugate_gradients.hpp, incomplete_cholesky.hpp).
// Each part is swept by one thread, its sums taken in row order, and the parts' sums added in
// part order: the results are the same bit for bit whatever the threads, which decide only who
// sweeps which part. The incomplete factor drops the entries that couple one part to an earlier
// one, so that its triangular sweeps run part by part too (on the nodes in reverse
// Cuthill-McKee order a part's rows couple to the part before it only across one level of the
// ordering: a few hundred entries of millions at 500k elements).
#include <array>

#include "core/parallel_for.hpp"

namespace flotsam {

struct RowParts {
  // [-] Two: the machine's cores (docs/performance.md). A fixed number, not the threads', so
  // that the factor, and every result, is the thread count's no matter.
  static constexpr int count = 2;
  // Below this many rows the parts are swept one after the other on this thread, with no
  // parallel region (waking a sleeping thread costs more than such a sweep) [-].
  static constexpr int parallel_rows = 50'000;
  std::array<int, count + 1> start{};  // part p: rows start[p] to start[p + 1] - 1

  RowParts() = default;
  explicit RowParts(int rows) {
    for (int p = 0; p <= count; ++p)
      start[p] = static_cast<int>(static_cast<long>(rows) * p / count);
  }
  int rows() const { return start[count]; }
  int part_of(int row) const {
    int p = 0;
    while (row >= start[p + 1]) ++p;
    return p;
  }
};

/// sweep(begin, end) for the rows of each part, on the threads when the rows are many; returns
/// the sum over the parts, in part order, of the two sums each returns.
template <class Sweep>
std::array<double, 2> sum_over_parts(const RowParts& parts, const Sweep& sweep) {
  std::array<std::array<double, 2>, RowParts::count> sums{};
  // parallel_for's threshold is on its items, the parts: all of them, or more than there are.
  const int threshold = parts.rows() >= RowParts::parallel_rows ? 0 : RowParts::count + 1;
  parallel_for(RowParts::count, threshold,
               [&](int p) { sums[p] = sweep(parts.start[p], parts.start[p + 1]); });
  std::array<double, 2> total{0.0, 0.0};
  for (const auto& s : sums) {
    total[0] += s[0];
    total[1] += s[1];
  }
  return total;
}

}  // namespace flotsam
