// Verifies where bridges stand on a mesh (src/bridges/bridge_layout.cpp): a river 40 m wide and
// 100 m long, turned 30 degrees, with two piers of radius 1 m on a line across it, meshed by
// mesh.region. In the river's own frame (x' along, y' across) the piers stand at (50, 15) and
// (50, 25); the axis from (50, -5) to (50, 45) gives, by hand, the gaps s in [5, 19], [21, 29],
// [31, 45] m (s = y' + 5). Gmsh puts the circles' nodes on the circles, so a gap's end at a pier
// is off the circle by at most the sagitta of an edge, l^2 / (8 r) <= 0.3^2 / 8 = 0.011 m.
#include "bridges/bridge_layout.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "coupling/jam_statistics.hpp"
#include "mesh/mesh_generator.hpp"

namespace flotsam {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

constexpr double turn = 30.0 * pi / 180.0;  // [rad]
constexpr double exact = 1e-9;              // [m] round-off at 100 m
constexpr double sagitta = 0.02;            // [m] a polygonal circle's crossing, with margin

/// A point of the river's frame in the mesh's frame (turned by 30 degrees about the origin).
Vec2 world(double x, double y) {
  return {std::cos(turn) * x - std::sin(turn) * y, std::sin(turn) * x + std::cos(turn) * y};
}

const Mesh& turned_river() {
  static const Mesh mesh = [] {
    MeshSource source;
    source.kind = MeshSource::Kind::region;
    RegionGeometry& r = source.region;
    r.outline = {{world(0, 0), world(100, 0), world(100, 40), world(0, 40)}, "outline"};
    r.piers = {{world(50, 15), 1.0}, {world(50, 25), 1.0}};
    r.mesh_size = 3.0;
    r.pier_mesh_size = 0.3;
    r.refine_distance = 3.0;
    return generate_mesh(source);
  }();
  return mesh;
}

/// Every group a solid, in the mesh's order.
std::vector<int> all_solid(const Mesh& mesh) {
  std::vector<int> solid(mesh.group_names.size());
  for (std::size_t g = 0; g < solid.size(); ++g) solid[g] = static_cast<int>(g);
  return solid;
}

BridgeConfig across(double y_start, double y_end) {
  return {.name = "road",
          .start = world(50, y_start),
          .end = world(50, y_end),
          .pier_groups = {},
          .deck = std::nullopt,
          .backwater_distance = 0.0,
          .origin = "case.yaml:20: bridges[0]"};
}

std::string error_of(const std::vector<BridgeConfig>& configs) {
  try {
    (void)bridges_on_mesh(configs, turned_river(), all_solid(turned_river()));
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(BridgesOnMesh, AnAxisAcrossATurnedRiverHasTheGapsBetweenBanksAndPiers) {
  const Mesh& mesh = turned_river();
  const int bank = mesh.find_group("bank"), pier_1 = mesh.find_group("pier_1"),
            pier_2 = mesh.find_group("pier_2");
  const std::vector<Bridge> bridges = bridges_on_mesh({across(-5, 45)}, mesh, all_solid(mesh));
  ASSERT_EQ(bridges.size(), 1u);
  const Bridge& b = bridges[0];
  EXPECT_EQ(b.name, "road");
  EXPECT_NEAR(b.length(), 50.0, exact);
  // Downstream is the axis turned clockwise: the river's +x'.
  EXPECT_NEAR((b.downstream - world(1, 0)).norm(), 0.0, exact);
  ASSERT_EQ(b.gaps.size(), 3u);
  EXPECT_NEAR(b.gaps[0].lower, 5.0, exact);
  EXPECT_NEAR(b.gaps[0].upper, 19.0, sagitta);
  EXPECT_NEAR(b.gaps[1].lower, 21.0, sagitta);
  EXPECT_NEAR(b.gaps[1].upper, 29.0, sagitta);
  EXPECT_NEAR(b.gaps[2].lower, 31.0, sagitta);
  EXPECT_NEAR(b.gaps[2].upper, 45.0, exact);
  EXPECT_EQ(b.gaps[0].lower_solid, bank);
  EXPECT_EQ(b.gaps[0].upper_solid, pier_1);
  EXPECT_EQ(b.gaps[1].lower_solid, pier_1);
  EXPECT_EQ(b.gaps[1].upper_solid, pier_2);
  EXPECT_EQ(b.gaps[2].upper_solid, bank);
  EXPECT_THAT(b.piers, ElementsAre(pier_1, pier_2));
  // Reach: the piers' nodes lie on their circles, the farthest from the axis at most 1 m.
  EXPECT_LE(b.reach, 1.0 + exact);
  EXPECT_GE(b.reach, 1.0 - sagitta);
  EXPECT_NEAR(b.backwater_distance, 4.0 * b.reach, exact);  // two diameters by default
  EXPECT_TRUE(b.passed(world(50 + 1.01, 20)));
  EXPECT_FALSE(b.passed(world(50 + 0.99, 20)));
  EXPECT_FALSE(b.passed(world(20, 20)));
}

TEST(BridgesOnMesh, AnAxisEndingInTheWaterEndsAtAnAbutment) {
  const std::vector<Bridge> bridges =
      bridges_on_mesh({across(10, 35)}, turned_river(), all_solid(turned_river()));
  ASSERT_EQ(bridges[0].gaps.size(), 3u);
  EXPECT_NEAR(bridges[0].gaps[0].lower, 0.0, exact);
  EXPECT_EQ(bridges[0].gaps[0].lower_solid, -1);  // an abutment, not a bank
  EXPECT_NEAR(bridges[0].gaps[2].upper, 25.0, exact);
  EXPECT_EQ(bridges[0].gaps[2].upper_solid, -1);
}

TEST(BridgesOnMesh, AnAxisOutsideTheWaterIsAnErrorNamingTheBridge) {
  BridgeConfig c = across(-5, 45);
  c.start = world(150, -5), c.end = world(150, 45);
  EXPECT_THAT(error_of({c}),
              HasSubstr("case.yaml:20: bridges[0]: the axis of bridge 'road' from "));
  EXPECT_THAT(error_of({c}), HasSubstr("crosses no water of the mesh"));
}

TEST(BridgesOnMesh, ANamedPierOffTheAxisIsAnError) {
  BridgeConfig c = across(-5, 45);
  c.start = world(45, -5), c.end = world(45, 45);  // 5 m upstream of the piers
  c.pier_groups = {"pier_2"};
  EXPECT_THAT(error_of({c}), HasSubstr("bridges[0]: bridge 'road': its pier 'pier_2' is off its "
                                       "axis"));
  c.pier_groups = {"pier_9"};
  EXPECT_THAT(error_of({c}), HasSubstr("bridge 'road': the mesh "));
  EXPECT_THAT(error_of({c}), HasSubstr("has no pier group 'pier_9' (its groups: bank, pier_1, "
                                       "pier_2)"));
}

TEST(BridgesOnMesh, TwoAxesThatCrossAreAnError) {
  BridgeConfig other = across(-5, 45);
  other.name = "rail";
  other.origin = "case.yaml:30: bridges[1]";
  other.start = world(30, 10), other.end = world(70, 30);
  EXPECT_THAT(error_of({across(-5, 45), other}),
              HasSubstr("case.yaml:30: bridges[1]: the axis of bridge 'rail' crosses that of "
                        "bridge 'road' (case.yaml:20: bridges[0])"));
}

TEST(JamStatisticsOnAnyBridge, ALogAlongATurnedAxisBlocksItsShareOfTheGap) {
  const Mesh& mesh = turned_river();
  const int pier_1 = mesh.find_group("pier_1");
  std::vector<int> solid_groups(mesh.group_names.size());
  for (std::size_t g = 0; g < solid_groups.size(); ++g) solid_groups[g] = static_cast<int>(g);
  MeshSource source;
  source.kind = MeshSource::Kind::region;
  const JamGeometry geometry = jam_geometry_for(source, mesh, solid_groups, {across(-5, 45)});
  ASSERT_EQ(geometry.bridges.size(), 1u);
  EXPECT_EQ(geometry.solids[pier_1].bridge, 0);
  EXPECT_EQ(geometry.solids[pier_1].kind, SolidKind::pier);
  // A 6 m log lying along the axis 1.5 m upstream of it, centred at y' = 17.5: it covers
  // s in [19.5, 25.5], of which [21, 25.5] lies in the middle gap [21, 29]: 4.5 / 8.
  BodySet bodies;
  bodies.add(BodySpec{.shape = Shape::log,
                      .length = 6.0,
                      .width = 0.5,
                      .height = 0.5,
                      .density = 600.0,
                      .position = world(48.5, 17.5),
                      .angle = turn + pi / 2});
  ContactReport report;
  report.body_count = 1;
  report.body_group = {{0, pier_1}};
  const JamStatistics s = compute_jam_statistics(bodies, report, geometry);
  ASSERT_EQ(s.jams.size(), 1u);
  EXPECT_EQ(s.jams[0].bridge, 0);
  ASSERT_EQ(s.jams[0].gap_blockage.size(), 3u);
  EXPECT_NEAR(s.jams[0].gap_blockage[0], 0.0, exact);
  EXPECT_NEAR(s.jams[0].gap_blockage[1], 4.5 / 8.0, sagitta / 8.0);
  EXPECT_NEAR(s.jams[0].gap_blockage[2], 0.0, exact);
  // Over the three gaps, 14 + 8 + 14 m: 4.5 / 36.
  EXPECT_NEAR(s.bridge_blockage[0], 4.5 / 36.0, 2 * sagitta / 36.0);
  EXPECT_EQ(s.trapped, 1);
  EXPECT_EQ(s.passed, 0);
}

}  // namespace
}  // namespace flotsam
