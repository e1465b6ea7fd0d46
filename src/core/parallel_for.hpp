#pragma once
// Loops shared among OpenMP threads.
//
// parallel_for: f(k) for every k in [0, n), on the threads (static schedule: each thread a run of
// the indices) when n is at least `threshold`, else on this thread with no parallel region at all
// (one costs about a microsecond even on one thread, and a small contact group meets many). For
// loops whose iterations are independent: the result is the same either way.
//
// team_run, team_offset: for a pass written once for a whole team, called by every thread of a
// parallel region (or by one thread outside any, a team of one): each thread takes its run of the
// items in order, and a compaction writes its items where the runs before it end.
#include <omp.h>

#include <cstddef>
#include <numeric>
#include <vector>

namespace flotsam {

template <class Index, class F>
void parallel_for(Index n, Index threshold, F&& f) {
  if (n >= threshold) {
#pragma omp parallel for schedule(static)
    for (Index k = 0; k < n; ++k) f(k);
  } else {
    for (Index k = 0; k < n; ++k) f(k);
  }
}

struct TeamRun {
  std::size_t begin, end;  // this thread's items: begin to end - 1
};

/// This thread's run of n items, the team's runs in the thread order.
inline TeamRun team_run(std::size_t n) {
  const auto threads = static_cast<std::size_t>(omp_get_num_threads());
  const auto t = static_cast<std::size_t>(omp_get_thread_num());
  return {n * t / threads, n * (t + 1) / threads};
}

/// Called by every thread of the team with its count: the sum of the counts of the threads before
/// it. `starts`, shared by the team, then holds each thread's start and, last, the total.
inline int team_offset(std::vector<int>& starts, int count) {
  const auto t = static_cast<std::size_t>(omp_get_thread_num());
#pragma omp single
  starts.assign(static_cast<std::size_t>(omp_get_num_threads()) + 1, 0);
  starts[t + 1] = count;
#pragma omp barrier
#pragma omp single
  std::partial_sum(starts.begin(), starts.end(), starts.begin());
  return starts[t];
}

}  // namespace flotsam
