// parallel_for (core/parallel_for.hpp): every index once, on this thread below the threshold and
// shared among the threads from it.
#include "core/parallel_for.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <vector>

namespace flotsam {
namespace {

// Which thread ran each of n indices with two threads available, the count of visits per index
// in `visits`.
std::vector<int> threads_of(int n, int threshold, std::vector<int>& visits) {
  const int old_threads = omp_get_max_threads();
  omp_set_num_threads(2);
  std::vector<int> thread(static_cast<std::size_t>(n), -1);
  visits.assign(static_cast<std::size_t>(n), 0);
  parallel_for(n, threshold, [&](int k) {
    thread[static_cast<std::size_t>(k)] = omp_get_thread_num();
    ++visits[static_cast<std::size_t>(k)];
  });
  omp_set_num_threads(old_threads);
  return thread;
}

TEST(ParallelFor, EveryIndexOnceOnThisThreadBelowTheThreshold) {
  std::vector<int> visits;
  const std::vector<int> thread = threads_of(999, 1000, visits);
  for (int k = 0; k < 999; ++k) {
    EXPECT_EQ(visits[static_cast<std::size_t>(k)], 1) << k;
    EXPECT_EQ(thread[static_cast<std::size_t>(k)], 0) << k;  // no parallel region
  }
}

TEST(ParallelFor, EveryIndexOnceInRunsOfTheThreadsFromTheThreshold) {
  std::vector<int> visits;
  const std::vector<int> thread = threads_of(1000, 1000, visits);
  for (int k = 0; k < 1000; ++k) EXPECT_EQ(visits[static_cast<std::size_t>(k)], 1) << k;
  // Static schedule on two threads: the first half on thread 0, the second on thread 1.
  EXPECT_EQ(thread.front(), 0);
  EXPECT_EQ(thread.back(), 1);
  for (int k = 1; k < 1000; ++k)
    EXPECT_GE(thread[static_cast<std::size_t>(k)], thread[static_cast<std::size_t>(k - 1)]) << k;
}

}  // namespace
}  // namespace flotsam
