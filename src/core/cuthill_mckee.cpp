#include "core/cuthill_mckee.hpp"

#include <algorithm>

namespace flotsam {

std::vector<int> cuthill_mckee(std::span<const int> start, std::span<const int> index) {
  const int n = static_cast<int>(start.size()) - 1;
  const auto degree = [&](int i) { return start[i + 1] - start[i]; };
  std::vector<int> order, level(n, -1);
  order.reserve(n);
  std::vector<char> numbered(n, 0);
  // Breadth-first levels from `root` over the nodes not yet numbered; appends them to `out`.
  const auto sweep = [&](int root, std::vector<int>& out, bool by_degree) {
    const std::size_t first = out.size();
    out.push_back(root);
    numbered[root] = 1;
    level[root] = 0;
    for (std::size_t head = first; head < out.size(); ++head) {
      const int i = out[head];
      const std::size_t children = out.size();
      for (int p = start[i]; p < start[i + 1]; ++p)
        if (!numbered[index[p]]) {
          numbered[index[p]] = 1;
          level[index[p]] = level[i] + 1;
          out.push_back(index[p]);
        }
      if (by_degree)
        std::stable_sort(out.begin() + static_cast<long>(children), out.end(),
                         [&](int a, int b) { return degree(a) < degree(b); });
    }
  };
  std::vector<int> trial;
  for (int seed = 0; seed < n; ++seed) {
    if (numbered[seed]) continue;
    int root = seed, depth = -1;
    for (int round = 0; round < 8; ++round) {
      trial.clear();
      sweep(root, trial, false);
      for (int i : trial) numbered[i] = 0;
      const int last = level[trial.back()];
      if (last <= depth) break;
      depth = last;
      int best = trial.back();
      for (auto it = trial.rbegin(); it != trial.rend() && level[*it] == last; ++it)
        if (degree(*it) < degree(best)) best = *it;
      root = best;
    }
    sweep(root, order, true);
  }
  return order;
}

}  // namespace flotsam
