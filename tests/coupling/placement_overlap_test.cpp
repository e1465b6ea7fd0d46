// Verifies that bodies placed on top of each other are found, with both ids and the depth of
// their overlap (issue 20 item 6), and that bodies apart or barely touching are not.
#include "coupling/placement_overlap.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace flotsam {
namespace {

BodySpec log_at(double x, double y, long id) {
  BodySpec spec;
  spec.length = 10.0;
  spec.width = 1.0;
  spec.position = Vec2(x, y);
  spec.id = id;
  return spec;
}

TEST(PlacementOverlap, NamesBothBodiesAndTheDepth) {
  BodySet bodies;
  bodies.add(log_at(0.0, 0.0, 3));
  bodies.add(log_at(2.0, 0.6, 7));    // side by side, 0.4 m into body 3
  bodies.add(log_at(0.0, -1.0, 9));   // touches body 3 along a side
  bodies.add(log_at(50.0, 0.0, 11));  // far from all
  const auto overlaps = placement_overlaps(bodies, 0.01);
  ASSERT_EQ(overlaps.size(), 1u) << describe_overlaps(bodies, overlaps, "logs.yaml");
  EXPECT_EQ(bodies.id[overlaps[0].a], 3);
  EXPECT_EQ(bodies.id[overlaps[0].b], 7);
  EXPECT_NEAR(overlaps[0].depth, 0.4, 1e-12);
  EXPECT_EQ(describe_overlaps(bodies, overlaps, "logs.yaml"),
            "bodies 3 and 7 overlap by 0.4 m where logs.yaml places them; the contacts push them "
            "apart in the first step");
}

}  // namespace
}  // namespace flotsam
