#include "flow/fem/node_ordering.hpp"

#include "core/cuthill_mckee.hpp"

namespace flotsam {

std::vector<int> reverse_cuthill_mckee(
    const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& pattern) {
  const int n = static_cast<int>(pattern.cols());
  const std::span<const int> start(pattern.outerIndexPtr(), static_cast<std::size_t>(n) + 1);
  const std::span<const int> index(pattern.innerIndexPtr(), static_cast<std::size_t>(start[n]));
  const std::vector<int> order = cuthill_mckee(start, index);
  std::vector<int> new_index(n);
  for (int k = 0; k < n; ++k) new_index[order[k]] = n - 1 - k;
  return new_index;
}

}  // namespace flotsam
