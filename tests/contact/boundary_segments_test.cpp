// Verifies that the wall segments are the mesh's `wall`/`noslip` boundary edges with the water
// on their left, that a curved P2 edge is split at its mid node, that the grid query finds
// exactly the segments near a box, and that an unknown group is reported by name.
#include "contact/boundary_segments.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace flotsam {
namespace {

// One six-node triangle (0,0), (2,0), (0,2): bottom edge "bank", hypotenuse "pier" curved
// outwards (mid node (1.2, 1.2)), left edge "inflow".
Mesh small_mesh() {
  RawMesh raw;
  raw.source = "small.msh";
  raw.nodes = {{0.0, 0.0}, {2.0, 0.0}, {0.0, 2.0}, {1.0, 0.0}, {1.2, 1.2}, {0.0, 1.0}};
  raw.node_tags = {1, 2, 3, 4, 5, 6};
  raw.triangles = {{0, 1, 2, 3, 4, 5}};
  raw.triangle_tags = {1};
  raw.lines = {{{0, 1, 3}, "bank", 1}, {{1, 2, 4}, "pier", 2}, {{2, 0, 5}, "inflow", 3}};
  return build_mesh(raw);
}

std::vector<BoundaryCondition> conditions() {
  BoundaryCondition bank, pier, inflow;
  bank.group = "bank";
  pier.group = "pier";
  pier.kind = BoundaryCondition::Kind::noslip;
  inflow.group = "inflow";
  inflow.kind = BoundaryCondition::Kind::discharge;
  return {bank, pier, inflow};
}

TEST(BoundarySegments, WallAndNoslipEdgesCurvedOnesSplitAtTheirMidNode) {
  const Mesh mesh = small_mesh();
  const BoundarySegments s =
      extract_boundary_segments(mesh, solid_group_indices(mesh, conditions()));
  ASSERT_EQ(s.size(), 3);  // the bank, the pier in two halves; not the inflow
  const double tol = 1e-14;
  int bank = -1, first_half = -1, second_half = -1;
  for (int k = 0; k < s.size(); ++k) {
    if ((s.start[k] - Vec2(0.0, 0.0)).norm() < tol) bank = k;
    if ((s.start[k] - Vec2(2.0, 0.0)).norm() < tol) first_half = k;
    if ((s.start[k] - Vec2(1.2, 1.2)).norm() < tol) second_half = k;
  }
  ASSERT_GE(bank, 0);
  ASSERT_GE(first_half, 0);
  ASSERT_GE(second_half, 0);
  EXPECT_NEAR((s.end[bank] - Vec2(2.0, 0.0)).norm(), 0.0, tol);
  EXPECT_NEAR((s.normal[bank] - Vec2(0.0, 1.0)).norm(), 0.0, tol);  // into the water
  EXPECT_NEAR((s.end[first_half] - Vec2(1.2, 1.2)).norm(), 0.0, tol);
  EXPECT_NEAR((s.end[second_half] - Vec2(0.0, 2.0)).norm(), 0.0, tol);
  // (2,0) -> (1.2,1.2): direction (-0.8, 1.2), left normal (-1.2, -0.8)/|.|, towards the water.
  EXPECT_NEAR((s.normal[first_half] - Vec2(-1.2, -0.8).normalized()).norm(), 0.0, tol);
  EXPECT_EQ(s.group_names[s.group[bank]], "bank");
  EXPECT_EQ(s.group_names[s.group[first_half]], "pier");
  EXPECT_EQ(s.group[first_half], s.group[second_half]);
}

TEST(BoundarySegments, UnknownGroupIsAnInputErrorNamingIt) {
  const Mesh mesh = small_mesh();
  std::vector<BoundaryCondition> bcs = conditions();
  bcs[1].group = "pier_7";
  bcs[1].line = 12;
  try {
    solid_group_indices(mesh, bcs);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'pier_7'"), std::string::npos) << what;
    EXPECT_NE(what.find("line 12"), std::string::npos) << what;
    EXPECT_NE(what.find("small.msh"), std::string::npos) << what;
    EXPECT_NE(what.find("'bank', 'inflow', 'pier'"), std::string::npos) << what;
  }
}

TEST(BoundarySegments, GridQueryFindsExactlyTheSegmentsMeetingItsCells) {
  // A circle of 64 segments of radius 2 at the origin and a long bank; cells of 1 m.
  BoundarySegments s;
  s.add_circle_hole({0.0, 0.0}, 2.0, 64, 0);
  s.add_segment({-50.0, -10.0}, {50.0, -10.0}, 1);
  s.build_grid(1.0);
  std::vector<int> found, stamp;
  int stamp_value = 0;
  // A box far from everything finds nothing; a box over the pier's right side finds the
  // segments with x > 1 (and no bank segment), each once, ascending.
  s.query({{10.0, 10.0}, {11.0, 11.0}}, found, stamp, stamp_value);
  EXPECT_TRUE(found.empty());
  s.query({{1.5, -0.2}, {2.5, 0.2}}, found, stamp, stamp_value);
  ASSERT_FALSE(found.empty());
  EXPECT_TRUE(std::is_sorted(found.begin(), found.end()));
  EXPECT_EQ(std::adjacent_find(found.begin(), found.end()), found.end());
  for (const int k : found) EXPECT_LT(k, 64);
  // Every segment whose box meets the query box must be found (the grid may add neighbours).
  for (int k = 0; k < s.size(); ++k) {
    const Aabb box{s.start[k].cwiseMin(s.end[k]), s.start[k].cwiseMax(s.end[k])};
    if (box.overlaps({{1.5, -0.2}, {2.5, 0.2}})) {
      EXPECT_TRUE(std::binary_search(found.begin(), found.end(), k)) << k;
    }
  }
}

}  // namespace
}  // namespace flotsam

namespace flotsam {
namespace {

TEST(BoundarySegments, ABandedSegmentStopsOnlyBodiesAcrossItsBandOnItsWaterSide) {
  BoundarySegments walls;
  walls.add_segment(Vec2(0, 0), Vec2(10, 0), 0);  // a plain wall: the water above it (y > 0)
  walls.add_banded_segment(Vec2(5, -5), Vec2(5, 5), 1, 2.0, 3.0);  // a deck's face, water at x < 5
  walls.add_segment(Vec2(10, 0), Vec2(10, 10), 2);                 // added after: plain again
  ASSERT_EQ(walls.band_lower.size(), 3u);
  EXPECT_TRUE(walls.stops(0, Vec2(1, 1), 5.0, 6.0));  // a plain wall stops anything
  EXPECT_TRUE(walls.stops(2, Vec2(1, 1), -1.0, 0.0));
  EXPECT_TRUE(walls.stops(1, Vec2(4, 0), 1.5, 2.5));   // top above the soffit 2
  EXPECT_TRUE(walls.stops(1, Vec2(4, 0), 2.5, 2.7));   // within the band
  EXPECT_FALSE(walls.stops(1, Vec2(4, 0), 1.0, 2.0));  // top at the soffit: passes under
  EXPECT_FALSE(walls.stops(1, Vec2(4, 0), 3.0, 3.5));  // underside at the top: floats over
  EXPECT_FALSE(walls.stops(1, Vec2(6, 0), 1.5, 2.5));  // beyond the face: not from its side
}

}  // namespace
}  // namespace flotsam
