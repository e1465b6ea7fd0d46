#pragma once
// Which body touches which (spec 4.1 item 4): the raw material of the jam statistics of spec 6.3
// (bodies in contact with each pier, jams as clusters of touching bodies anchored on a boundary).
#include <utility>
#include <vector>

#include "contact/impulse_solver.hpp"

namespace flotsam {

struct ContactReport {
  std::vector<std::pair<int, int>> body_body;   // (a, b), a < b, body indices, each pair once
  std::vector<std::pair<int, int>> body_group;  // (body, boundary group), each pair once
  int body_count = 0;

  /// Number of bodies touching boundary group `group` directly.
  int count_touching(int group) const;

  /// Bodies connected to boundary group `group` through a chain of contacts (the jam anchored
  /// on it), ascending body indices.
  std::vector<int> anchored_cluster(int group) const;
};

/// The report of one contact solve. `segment_groups[s]` is the group of wall segment s.
ContactReport make_contact_report(const std::vector<ContactConstraint>& contacts,
                                  const std::vector<int>& segment_groups, int body_count);

}  // namespace flotsam
