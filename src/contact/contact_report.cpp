#include "contact/contact_report.hpp"

#include <algorithm>
#include <numeric>

namespace flotsam {

ContactReport make_contact_report(const std::vector<ContactConstraint>& contacts,
                                  const std::vector<int>& segment_groups, int body_count) {
  ContactReport report;
  report.body_count = body_count;
  for (const ContactConstraint& c : contacts) {
    if (c.point_count == 0) continue;
    if (c.b >= 0) {
      report.body_body.emplace_back(std::min(c.a, c.b), std::max(c.a, c.b));
    } else {
      report.body_group.emplace_back(c.a, segment_groups[static_cast<std::size_t>(c.segment)]);
    }
  }
  for (auto* list : {&report.body_body, &report.body_group}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }
  return report;
}

int ContactReport::count_touching(int group) const {
  return static_cast<int>(std::count_if(body_group.begin(), body_group.end(),
                                        [&](const auto& bg) { return bg.second == group; }));
}

std::vector<int> ContactReport::anchored_cluster(int group) const {
  // Union-find over body-body contacts, then the roots of the bodies touching the group.
  std::vector<int> parent(static_cast<std::size_t>(body_count));
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& [a, b] : body_body) parent[root(a)] = root(b);
  std::vector<char> anchored_root(static_cast<std::size_t>(body_count), 0);
  for (const auto& [body, g] : body_group) {
    if (g == group) anchored_root[root(body)] = 1;
  }
  std::vector<int> cluster;
  for (int i = 0; i < body_count; ++i) {
    if (anchored_root[root(i)]) cluster.push_back(i);
  }
  return cluster;
}

}  // namespace flotsam
