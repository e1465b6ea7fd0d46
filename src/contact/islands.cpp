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

void Islands::group(std::vector<ContactConstraint>& contacts, int body_count) {
  // Only the bodies of the contacts are touched: a small group's step costs its own size.
  parent_.resize(static_cast<std::size_t>(body_count));
  island_of_root_.resize(static_cast<std::size_t>(body_count));
  for (const ContactConstraint& c : contacts) {
    parent_[c.a] = c.a, island_of_root_[c.a] = -1;
    if (c.b >= 0) parent_[c.b] = c.b, island_of_root_[c.b] = -1;
  }
  for (const ContactConstraint& c : contacts) {
    if (c.b < 0) continue;  // a wall joins nothing
    const int ra = root(c.a), rb = root(c.b);
    if (ra != rb) parent_[std::max(ra, rb)] = std::min(ra, rb);
  }
  // Number the islands in the order of their first contact; count their contacts.
  island_of_contact_.resize(contacts.size());
  start_.assign(1, 0);
  for (std::size_t m = 0; m < contacts.size(); ++m) {
    int& island = island_of_root_[root(contacts[m].a)];
    if (island < 0) island = static_cast<int>(start_.size()) - 1, start_.push_back(0);
    island_of_contact_[m] = island;
    ++start_[island + 1];
  }
  std::partial_sum(start_.begin(), start_.end(), start_.begin());
  // Counting sort: stable, so each island keeps its contacts' order. Contacts already grouped
  // (one island, as a packed jam) are not moved: a contact is a few hundred bytes.
  if (!std::is_sorted(island_of_contact_.begin(), island_of_contact_.end())) {
    sorted_.resize(contacts.size());
    next_.assign(start_.begin(), start_.end() - 1);  // next free slot of each island
    for (std::size_t m = 0; m < contacts.size(); ++m) {
      sorted_[next_[island_of_contact_[m]]++] = contacts[m];
    }
    contacts.swap(sorted_);
  }
  largest_first_.resize(static_cast<std::size_t>(count()));
  std::iota(largest_first_.begin(), largest_first_.end(), 0);
  std::stable_sort(largest_first_.begin(), largest_first_.end(),
                   [&](int x, int y) { return size(x) > size(y); });
}

}  // namespace flotsam
