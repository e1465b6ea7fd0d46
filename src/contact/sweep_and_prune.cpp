#include "contact/sweep_and_prune.hpp"

#include <algorithm>
#include <cstring>

#include <omp.h>

#include "core/parallel_for.hpp"

// load() returns a 32-byte vector; it stays within this file, so the calling convention GCC
// notes (AVX's differs from SSE2's) is never crossed.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace flotsam {
namespace {

using Lanes = double __attribute__((vector_size(4 * sizeof(double))));
using Mask = long long __attribute__((vector_size(4 * sizeof(long long))));

Lanes load(const double* x) {  // four bounds from x
  Lanes v;
  std::memcpy(&v, x, sizeof v);
  return v;
}

// Axis along which the listed boxes' centres have the larger variance.
int spread_axis(const std::vector<Aabb>& boxes, const std::vector<int>& listed) {
  Vec2 sum = Vec2::Zero(), sum_squares = Vec2::Zero();
  int n = 0;
  for (const int i : listed) {
    const Vec2 c = 0.5 * (boxes[i].lower + boxes[i].upper);
    sum += c;
    sum_squares += c.cwiseProduct(c);
    ++n;
  }
  if (n == 0) return 0;
  const Vec2 variance = sum_squares / n - (sum / n).cwiseProduct(sum / n);
  return variance.y() > variance.x() ? 1 : 0;
}

}  // namespace

void SweepAndPrune::find_pairs(const std::vector<Aabb>& boxes, const std::vector<char>& active,
                               std::vector<BodyPair>& pairs) {
  std::vector<int> listed;
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
    if (active[i]) listed.push_back(i);
  find_pairs(boxes, active, listed, pairs);
}

void SweepAndPrune::find_pairs(const std::vector<Aabb>& boxes, const std::vector<char>& active,
                               const std::vector<int>& listed, std::vector<BodyPair>& pairs) {
  pairs.clear();
  const int n = static_cast<int>(boxes.size());
  const int axis = spread_axis(boxes, listed);
  const int other = 1 - axis;

  // Keep the previous order, dropping bodies no longer active and appending new ones.
  in_order_.resize(static_cast<std::size_t>(n), 0);
  std::erase_if(order_, [&](int i) {
    if (i < n && active[i]) return false;
    if (i < n) in_order_[i] = 0;
    return true;
  });
  for (const int i : listed) {
    if (!in_order_[i]) order_.push_back(i), in_order_[i] = 1;
  }

  auto key = [&](int i) { return boxes[i].lower[axis]; };
  swaps_ = 0;
  if (axis != axis_) {
    axis_ = axis;
    std::sort(order_.begin(), order_.end(), [&](int a, int b) { return key(a) < key(b); });
  } else {
    // Insertion sort: O(N + number of swaps) on a nearly sorted list.
    for (std::size_t k = 1; k < order_.size(); ++k) {
      const int body = order_[k];
      const double value = key(body);
      std::size_t m = k;
      while (m > 0 && key(order_[m - 1]) > value) {
        order_[m] = order_[m - 1];
        --m;
      }
      swaps_ += static_cast<long>(k - m);
      order_[m] = body;
    }
  }

  const std::size_t count = order_.size();
  constexpr std::size_t parallel_boxes = 2000;  // [-] threads pay off from a few thousand
  const bool parallel = count >= parallel_boxes && omp_get_max_threads() > 1;
  lower_.resize(count), upper_.resize(count), other_lower_.resize(count),
      other_upper_.resize(count);
  const auto copy_bounds = [&](long k) {
    const Aabb& b = boxes[order_[static_cast<std::size_t>(k)]];
    lower_[k] = b.lower[axis], upper_[k] = b.upper[axis];
    other_lower_[k] = b.lower[other], other_upper_[k] = b.upper[other];
  };
  parallel_for(static_cast<long>(count), static_cast<long>(parallel_boxes), copy_bounds);
  // The sweep in parallel: each thread sweeps a run of the order into its own list, and the
  // lists join in the order's order, the same pairs in the same order on any number of threads.
  const double *lower = lower_.data(), *upper = upper_.data();  // local: not reloaded per test
  const double *other_lower = other_lower_.data(), *other_upper = other_upper_.data();
  const int* order = order_.data();
  // Four boxes at a time while the fourth is open (the lower bounds ascend, so then all four
  // are), the rest one by one: the pairs in the same order either way.
  const auto sweep = [=](std::size_t begin, std::size_t end_k, std::vector<BodyPair>& found) {
    for (std::size_t k = begin; k < end_k; ++k) {
      const double end = upper[k], lo = other_lower[k], hi = other_upper[k];
      const int i = order[k];
      std::size_t m = k + 1;
      for (; m + 4 <= count && lower[m + 3] <= end; m += 4) {
        const Mask hit = (load(other_lower + m) <= hi) & (lo <= load(other_upper + m));
        for (std::size_t l = 0; l < 4; ++l) {
          if (!hit[l]) continue;
          const int j = order[m + l];
          found.emplace_back(std::min(i, j), std::max(i, j));
        }
      }
      for (; m < count && lower[m] <= end; ++m) {
        if (other_lower[m] <= hi && lo <= other_upper[m]) {
          const int j = order[m];
          found.emplace_back(std::min(i, j), std::max(i, j));
        }
      }
    }
  };
  if (!parallel) {
    sweep(0, count, pairs);
    return;
  }
  runs_.resize(static_cast<std::size_t>(omp_get_max_threads()));
#pragma omp parallel
  {
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    const auto threads = static_cast<std::size_t>(omp_get_num_threads());
    runs_[t].clear();
    sweep(count * t / threads, count * (t + 1) / threads, runs_[t]);
#pragma omp barrier
#pragma omp single
    {
      std::size_t total = 0;
      for (std::size_t r = 0; r < threads; ++r) total += runs_[r].size();
      pairs.reserve(total);
      for (std::size_t r = 0; r < threads; ++r)
        pairs.insert(pairs.end(), runs_[r].begin(), runs_[r].end());
    }
  }
}

void brute_force_pairs(const std::vector<Aabb>& boxes, const std::vector<char>& active,
                       std::vector<BodyPair>& pairs) {
  pairs.clear();
  const int n = static_cast<int>(boxes.size());
  for (int i = 0; i < n; ++i) {
    if (!active[i]) continue;
    for (int j = i + 1; j < n; ++j) {
      if (active[j] && boxes[i].overlaps(boxes[j])) pairs.emplace_back(i, j);
    }
  }
}

}  // namespace flotsam
