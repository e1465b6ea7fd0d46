// Verifies that the contact report lists each touching pair once and finds the jam anchored on
// a boundary group: the bodies connected to it through a chain of contacts, and no others.
#include "contact/contact_report.hpp"

#include <gtest/gtest.h>

namespace flotsam {
namespace {

ContactConstraint contact(int a, int b, int segment, int points = 1) {
  ContactConstraint c;
  c.a = a, c.b = b, c.segment = segment, c.point_count = points;
  return c;
}

TEST(ContactReport, ClustersAnchoredOnAGroup) {
  // Segments 0, 1 in group 5 (a pier), segment 2 in group 9 (a bank).
  const std::vector<int> segment_groups{5, 5, 9};
  // Chain 0-1-2 with 0 on the pier (twice, through both segments); 3-4 touch each other only;
  // 5 on the bank; 6 alone; a manifold without points does not count (7-6).
  const std::vector<ContactConstraint> contacts{
      contact(0, -1, 0), contact(0, -1, 1, 2), contact(0, 1, -1),   contact(2, 1, -1),
      contact(3, 4, -1), contact(5, -1, 2),    contact(7, 6, -1, 0)};
  const ContactReport r = make_contact_report(contacts, segment_groups, 8);
  EXPECT_EQ(r.body_body, (std::vector<std::pair<int, int>>{{0, 1}, {1, 2}, {3, 4}}));
  EXPECT_EQ(r.body_group, (std::vector<std::pair<int, int>>{{0, 5}, {5, 9}}));
  EXPECT_EQ(r.count_touching(5), 1);
  EXPECT_EQ(r.count_touching(9), 1);
  EXPECT_EQ(r.count_touching(7), 0);
  EXPECT_EQ(r.anchored_cluster(5), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(r.anchored_cluster(9), (std::vector<int>{5}));
  EXPECT_TRUE(r.anchored_cluster(7).empty());
}

}  // namespace
}  // namespace flotsam
