#include "contact/islands.hpp"

#include <algorithm>
#include <numeric>

namespace flotsam {

int Islands::root(int body) {
  while (parent_[body] != body) {
    parent_[body] = parent_[parent_[body]];  // path halving
    body = parent_[body];
  }
  return body;
}

const std::vector<int>& Islands::number(std::span<const BodyPair> ends, int body_count) {
  // Only the bodies of the contacts are touched: a small group's step costs its own size.
  parent_.resize(static_cast<std::size_t>(body_count));
  island_of_root_.resize(static_cast<std::size_t>(body_count));
  for (const auto& [a, b] : ends) {
    parent_[a] = a, island_of_root_[a] = -1;
    if (b >= 0) parent_[b] = b, island_of_root_[b] = -1;
  }
  for (const auto& [a, b] : ends) {
    if (b < 0) continue;  // a wall joins nothing
    const int ra = root(a), rb = root(b);
    if (ra != rb) parent_[std::max(ra, rb)] = std::min(ra, rb);
  }
  // Number the islands in the order of their first contact; count their contacts.
  island_of_contact_.resize(ends.size());
  start_.assign(1, 0);
  for (std::size_t m = 0; m < ends.size(); ++m) {
    int& island = island_of_root_[root(ends[m].first)];
    if (island < 0) island = static_cast<int>(start_.size()) - 1, start_.push_back(0);
    island_of_contact_[m] = island;
    ++start_[island + 1];
  }
  std::partial_sum(start_.begin(), start_.end(), start_.begin());
  // Counting sort: stable, so each island keeps its contacts' order.
  next_.assign(start_.begin(), start_.end() - 1);  // next free slot of each island
  destination_.resize(ends.size());
  for (std::size_t m = 0; m < ends.size(); ++m) destination_[m] = next_[island_of_contact_[m]]++;
  largest_first_.resize(static_cast<std::size_t>(count()));
  std::iota(largest_first_.begin(), largest_first_.end(), 0);
  std::stable_sort(largest_first_.begin(), largest_first_.end(),
                   [&](int x, int y) { return size(x) > size(y); });
  return destination_;
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
