#include "contact/sweep_and_prune.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>

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
  list_in_bands();
  // The sweep in parallel: each thread sweeps a run of the order into its own list, and the
  // lists join in the order's order, the same pairs in the same order on any number of threads.
  const auto sweep = [this](std::size_t begin, std::size_t end, std::vector<BodyPair>& found,
                            std::vector<int>& partners) {
    for (std::size_t k = begin; k < end; ++k) sweep_box(k, found, partners);
  };
  if (!parallel) {
    runs_.resize(1);
    sweep(0, count, pairs, runs_[0].partners);
    return;
  }
  runs_.resize(static_cast<std::size_t>(omp_get_max_threads()));
#pragma omp parallel
  {
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    const auto threads = static_cast<std::size_t>(omp_get_num_threads());
    runs_[t].pairs.clear();
    sweep(count * t / threads, count * (t + 1) / threads, runs_[t].pairs, runs_[t].partners);
#pragma omp barrier
#pragma omp single
    {
      std::size_t total = 0;
      for (std::size_t r = 0; r < threads; ++r) total += runs_[r].pairs.size();
      pairs.reserve(total);
      for (std::size_t r = 0; r < threads; ++r)
        pairs.insert(pairs.end(), runs_[r].pairs.begin(), runs_[r].pairs.end());
    }
  }
}

// Bands across the other axis, about twice the boxes' mean extent along it wide (and at most one
// per 32 boxes); each box is listed, in the order's order, in every band it spans, with its
// bounds copied contiguously for the sweep.
void SweepAndPrune::list_in_bands() {
  const std::size_t count = order_.size();
  double low = std::numeric_limits<double>::infinity(), high = -low, extent = 0.0;  // [m]
  for (std::size_t k = 0; k < count; ++k) {
    low = std::min(low, other_lower_[k]), high = std::max(high, other_upper_[k]);
    extent += other_upper_[k] - other_lower_[k];
  }
  constexpr double width_per_extent = 2.0;  // [-] band width / mean extent
  constexpr std::size_t boxes_per_band = 32;
  const double span = high - low;  // [m]
  const double most = static_cast<double>(std::max<std::size_t>(1, count / boxes_per_band));
  const double width =
      std::max(width_per_extent * extent / static_cast<double>(count), span / most);
  const double bands = std::isfinite(span) && width > 0.0 ? std::ceil(span / width) : 1.0;
  band_low_ = low;
  band_count_ = static_cast<int>(std::clamp(bands, 1.0, most));
  band_scale_ = band_count_ > 1 ? band_count_ / span : 0.0;  // [1/m]

  // Counting sort of the boxes' entries by band, stable in the order.
  band_start_.assign(static_cast<std::size_t>(band_count_) + 1, 0);
  first_band_.resize(count + 1);
  entry_start_.resize(count + 1);
  entry_start_[0] = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const int first = band_of(other_lower_[k]), last = band_of(other_upper_[k]);
    first_band_[k] = first;
    for (int b = first; b <= last; ++b) ++band_start_[static_cast<std::size_t>(b) + 1];
    entry_start_[k + 1] = entry_start_[k] + (last - first + 1);
  }
  std::partial_sum(band_start_.begin(), band_start_.end(), band_start_.begin());
  const auto entries = static_cast<std::size_t>(band_start_.back());
  member_.resize(entries), position_.resize(entries);
  band_lower_.resize(entries), band_other_lower_.resize(entries), band_other_upper_.resize(entries);
  fill_.assign(band_start_.begin(), band_start_.end() - 1);
  for (std::size_t k = 0; k < count; ++k) {
    for (int e = entry_start_[k]; e < entry_start_[k + 1]; ++e) {
      const int b = first_band_[k] + (e - entry_start_[k]);
      const int at = fill_[static_cast<std::size_t>(b)]++;
      position_[static_cast<std::size_t>(e)] = at;
      member_[static_cast<std::size_t>(at)] = static_cast<int>(k);
      band_lower_[at] = lower_[k];
      band_other_lower_[at] = other_lower_[k], band_other_upper_[at] = other_upper_[k];
    }
  }
}

int SweepAndPrune::band_of(double v) const {
  const double t = (v - band_low_) * band_scale_;  // [-]
  if (!(t > 0.0)) return 0;                        // NaN too
  return t >= band_count_ - 1 ? band_count_ - 1 : static_cast<int>(t);
}

// The pairs of box k with the boxes after it in the order (Lanes: four at a time while the fourth
// is open, as the lower bounds ascend), in every band of k's; a pair that shares two bands is
// taken in the one where their overlap along the other axis starts. Appended to `found` in the
// order's order, the same list as one sweep over all the boxes gives.
void SweepAndPrune::sweep_box(std::size_t k, std::vector<BodyPair>& found,
                              std::vector<int>& partners) const {
  const double end = upper_[k], lo = other_lower_[k], hi = other_upper_[k];
  const double* lower = band_lower_.data();  // local: not reloaded per test
  const double *other_lower = band_other_lower_.data(), *other_upper = band_other_upper_.data();
  partners.clear();
  for (int e = entry_start_[k]; e < entry_start_[k + 1]; ++e) {
    const int b = first_band_[k] + (e - entry_start_[k]);
    const auto stop = static_cast<std::size_t>(band_start_[static_cast<std::size_t>(b) + 1]);
    const auto take = [&](std::size_t m) {
      if (band_of(std::max(lo, other_lower[m])) == b) partners.push_back(member_[m]);
    };
    std::size_t m = static_cast<std::size_t>(position_[static_cast<std::size_t>(e)]) + 1;
    for (; m + 4 <= stop && lower[m + 3] <= end; m += 4) {
      const Mask hit = (load(other_lower + m) <= hi) & (lo <= load(other_upper + m));
      for (std::size_t l = 0; l < 4; ++l)
        if (hit[l]) take(m + l);
    }
    for (; m < stop && lower[m] <= end; ++m)
      if (other_lower[m] <= hi && lo <= other_upper[m]) take(m);
  }
  if (entry_start_[k + 1] - entry_start_[k] > 1) std::sort(partners.begin(), partners.end());
  const int i = order_[k];
  for (const int m : partners) {
    const int j = order_[static_cast<std::size_t>(m)];
    found.emplace_back(std::min(i, j), std::max(i, j));
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
