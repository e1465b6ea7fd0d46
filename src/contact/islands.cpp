#include "contact/islands.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <limits>
#include <numeric>

#include "core/parallel_for.hpp"

namespace flotsam {

namespace {

constexpr std::size_t parallel_contacts = 2000;  // [-] threads pay off from a few thousand

std::atomic_ref<int> at(std::vector<int>& v, int i) {
  return std::atomic_ref<int>(v[static_cast<std::size_t>(i)]);
}

}  // namespace

// The root of body's tree, halving the path on the way (each body then points to its
// grandparent: still an ancestor, whatever other threads do meanwhile).
int Islands::root(int body) {
  for (;;) {
    const int parent = at(parent_, body).load(std::memory_order_relaxed);
    if (parent == body) return body;
    const int grandparent = at(parent_, parent).load(std::memory_order_relaxed);
    at(parent_, body).store(grandparent, std::memory_order_relaxed);
    body = grandparent;
  }
}

// Joins the trees of a and b: the larger root goes under the smaller, by compare-and-swap, so
// that threads may join at once; each island's root ends as its smallest body, whatever the order
// of the joins.
void Islands::join(int a, int b) {
  for (;;) {
    a = root(a), b = root(b);
    if (a == b) return;
    if (a < b) std::swap(a, b);
    int expected = a;
    if (at(parent_, a).compare_exchange_strong(expected, b, std::memory_order_acq_rel)) return;
  }
}

const std::vector<int>& Islands::number(std::span<const BodyPair> ends, int body_count) {
  // Only the bodies of the contacts are touched: a small group's step costs its own size.
  parent_.resize(static_cast<std::size_t>(body_count));
  first_of_root_.resize(static_cast<std::size_t>(body_count));
  island_of_root_.resize(static_cast<std::size_t>(body_count));
  root_of_contact_.resize(ends.size());
  island_of_contact_.resize(ends.size());
  destination_.resize(ends.size());
  if (ends.size() >= parallel_contacts) {
#pragma omp parallel
    number_in_team(ends);
  } else {  // no parallel region: it costs about a microsecond even on one thread
    number_in_team(ends);
  }
  return destination_;
}

// number()'s work, by every thread of a parallel region (or by one, outside any): each thread
// takes a run of the contacts, in order, for each pass; the passes meet between them. Islands are
// numbered in the order of their first contact, and each keeps its contacts' order: the same
// numbers and destinations on any number of threads.
void Islands::number_in_team(std::span<const BodyPair> ends) {
  const auto threads = static_cast<std::size_t>(omp_get_num_threads());
  const auto t = static_cast<std::size_t>(omp_get_thread_num());
  const auto [begin, end] = team_run(ends.size());
  constexpr int none = std::numeric_limits<int>::max();
  for (std::size_t m = begin; m < end; ++m) {  // each body its own tree, no contact yet
    for (const int i : {ends[m].first, ends[m].second}) {
      if (i < 0) continue;
      at(parent_, i).store(i, std::memory_order_relaxed);
      at(first_of_root_, i).store(none, std::memory_order_relaxed);
    }
  }
#pragma omp barrier
  for (std::size_t m = begin; m < end; ++m) {
    if (ends[m].second >= 0) join(ends[m].first, ends[m].second);  // a wall joins nothing
  }
#pragma omp barrier
  // Each root's first contact, and the contacts that are one.
  const auto is_first = [&](std::size_t m) {
    return first_of_root_[static_cast<std::size_t>(root_of_contact_[m])] == static_cast<int>(m);
  };
  for (std::size_t m = begin; m < end; ++m) {
    const int r = root(ends[m].first), contact = static_cast<int>(m);
    root_of_contact_[m] = r;
    std::atomic_ref<int> first = at(first_of_root_, r);
    int seen = first.load(std::memory_order_relaxed);
    while (contact < seen &&
           !first.compare_exchange_weak(seen, contact, std::memory_order_relaxed)) {
    }
  }
#pragma omp barrier
  int firsts = 0;
  for (std::size_t m = begin; m < end; ++m) firsts += is_first(m);
  // The islands numbered in the order of their first contacts.
  int island = team_offset(run_start_, firsts);
  for (std::size_t m = begin; m < end; ++m) {
    if (is_first(m)) island_of_root_[static_cast<std::size_t>(root_of_contact_[m])] = island++;
  }
  const int islands = run_start_.back();
#pragma omp single
  thread_counts_.assign(threads * static_cast<std::size_t>(islands), 0);
  int* counts = thread_counts_.data() + t * static_cast<std::size_t>(islands);
  for (std::size_t m = begin; m < end; ++m) {
    island_of_contact_[m] = island_of_root_[static_cast<std::size_t>(root_of_contact_[m])];
    ++counts[island_of_contact_[m]];
  }
#pragma omp barrier
  // Counting sort, stable: island k's contacts start at start_[k], thread t's at the place its
  // count for k follows the counts of the threads before it.
#pragma omp single
  {
    start_.assign(static_cast<std::size_t>(islands) + 1, 0);
    for (int k = 0; k < islands; ++k) {
      int next = 0;
      for (std::size_t u = 0; u < threads; ++u) {
        int& c =
            thread_counts_[u * static_cast<std::size_t>(islands) + static_cast<std::size_t>(k)];
        const int n = c;
        c = next, next += n;
      }
      start_[static_cast<std::size_t>(k) + 1] = next;
    }
    std::partial_sum(start_.begin(), start_.end(), start_.begin());
  }
  for (std::size_t m = begin; m < end; ++m) {
    const int k = island_of_contact_[m];
    destination_[m] = start_[static_cast<std::size_t>(k)] + counts[k]++;
  }
#pragma omp single nowait
  {
    largest_first_.resize(static_cast<std::size_t>(islands));
    std::iota(largest_first_.begin(), largest_first_.end(), 0);
    std::stable_sort(largest_first_.begin(), largest_first_.end(),
                     [&](int x, int y) { return size(x) > size(y); });
  }
}

void Islands::group(std::vector<ContactConstraint>& contacts, int body_count) {
  ends_.resize(contacts.size());
  for (std::size_t m = 0; m < contacts.size(); ++m) ends_[m] = {contacts[m].a, contacts[m].b};
  number(ends_, body_count);
  // Contacts already grouped (one island, as a packed jam) are not moved: a contact is a few
  // hundred bytes.
  if (std::is_sorted(island_of_contact_.begin(), island_of_contact_.end())) return;
  sorted_.resize(contacts.size());
  for (std::size_t m = 0; m < contacts.size(); ++m) sorted_[destination_[m]] = contacts[m];
  contacts.swap(sorted_);
}

}  // namespace flotsam
