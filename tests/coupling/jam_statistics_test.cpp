// Verifies that the jam statistics (src/coupling/jam_statistics.cpp, spec 6.3) count, cluster
// and measure hand-built bodies and contact reports as defined, in the paper's channel
// (spec 8.2): two bridges at x = 600 and 900 m, each with piers of radius 30 m centred at
// y = 42.5 and 127.5 m, 170 m wide; every expected value below is worked out by hand from the
// definitions in docs/model.md.
#include "coupling/jam_statistics.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../support/paper_bridges.hpp"
#include "../support/scratch_path.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"
#include "coupling/jam_extent.hpp"

namespace flotsam {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

constexpr double tolerance = 1e-12;  // [-] round-off on ratios of lengths of order 100 m

using namespace test;  // the paper's channel, its groups and logs (support/paper_bridges.hpp)

ContactReport make_report(int body_count, std::vector<std::pair<int, int>> body_body,
                          std::vector<std::pair<int, int>> body_group) {
  ContactReport r;
  r.body_count = body_count;
  r.body_body = std::move(body_body);
  r.body_group = std::move(body_group);
  return r;
}

TEST(JamGeometry, PaperChannelHasTwoBridgesWithGapsAtTheBanksAndBetweenThePiers) {
  const JamGeometry g = paper_geometry();
  ASSERT_EQ(g.solids.size(), 6u);
  EXPECT_EQ(g.solids[0].name, "bank_right");
  EXPECT_EQ(g.solids[0].group, bank_right);
  EXPECT_EQ(g.solids[1].name, "bank_left");
  EXPECT_EQ(g.solids[1].group, bank_left);
  EXPECT_EQ(g.solids[2].name, "pier_1");
  EXPECT_EQ(g.solids[2].group, pier_1);
  EXPECT_EQ(g.solids[5].group, pier_4);
  ASSERT_EQ(g.bridges.size(), 2u);
  for (int b = 0; b < 2; ++b) {
    const Bridge& line = g.bridges[b];
    EXPECT_EQ(line.name, b == 0 ? "bridge_1" : "bridge_2");
    EXPECT_EQ(line.start, Vec2(b == 0 ? 600.0 : 900.0, 0.0));
    EXPECT_EQ(line.end, Vec2(b == 0 ? 600.0 : 900.0, 170.0));
    EXPECT_EQ(line.reach, 30.0);
    EXPECT_EQ(line.backwater_distance, 120.0);  // two diameters
    EXPECT_THAT(line.piers, ElementsAre(2 + 2 * b, 3 + 2 * b));
    EXPECT_EQ(g.solids[2 + 2 * b].bridge, b);
    ASSERT_EQ(line.gaps.size(), 3u);
    // 42.5 - 30 = 12.5, 42.5 + 30 = 72.5, 127.5 - 30 = 97.5, 127.5 + 30 = 157.5: all exact.
    EXPECT_EQ(line.gaps[0].lower, 0.0);
    EXPECT_EQ(line.gaps[0].upper, 12.5);
    EXPECT_EQ(line.gaps[1].lower, 72.5);
    EXPECT_EQ(line.gaps[1].upper, 97.5);
    EXPECT_EQ(line.gaps[2].lower, 157.5);
    EXPECT_EQ(line.gaps[2].upper, 170.0);
    EXPECT_EQ(line.gaps[0].lower_solid, 0);  // bank_right
    EXPECT_EQ(line.gaps[0].upper_solid, 2 + 2 * b);
    EXPECT_EQ(line.gaps[1].lower_solid, 2 + 2 * b);
    EXPECT_EQ(line.gaps[1].upper_solid, 3 + 2 * b);
    EXPECT_EQ(line.gaps[2].upper_solid, 1);  // bank_left
  }
  // Beyond both bridges: x > 900 + 30, anywhere across.
  EXPECT_FALSE(g.passed_every_bridge(Vec2(930.0, 85.0)));
  EXPECT_TRUE(g.passed_every_bridge(Vec2(std::nextafter(930.0, 1e9), 85.0)));
  EXPECT_FALSE(g.passed_every_bridge(Vec2(700.0, 85.0)));
}

TEST(JamGeometry, PiersGivenInAnyOrderGroupIntoLinesByXAndSortByY) {
  ChannelGeometry c = paper_channel();
  // pier_1 (900, 127.5), pier_2 (600, 42.5), pier_3 (610, 127.5): 10 m < 30 m off the line at
  // 600, so the same bridge at x = 605; pier_4 (900, 42.5).
  c.piers = {
      {{900.0, 127.5}, 30.0}, {{600.0, 42.5}, 30.0}, {{610.0, 127.5}, 30.0}, {{900.0, 42.5}, 20.0}};
  const JamGeometry g = jam_geometry_from_channel(c, channel_groups, "test mesh");
  ASSERT_EQ(g.bridges.size(), 2u);
  EXPECT_DOUBLE_EQ(g.bridges[0].start.x(), 605.0);
  EXPECT_THAT(g.bridges[0].piers, ElementsAre(3, 4));  // solids of pier_2, pier_3
  EXPECT_EQ(g.bridges[1].start.x(), 900.0);
  EXPECT_EQ(g.bridges[1].reach, 30.0);
  EXPECT_THAT(g.bridges[1].piers, ElementsAre(5, 2));  // pier_4 (y 42.5), pier_1 (y 127.5)
  EXPECT_EQ(g.bridges[1].gaps[0].upper, 22.5);         // 42.5 - 20
  EXPECT_EQ(g.bridges[1].gaps[1].lower, 62.5);         // 42.5 + 20
}

TEST(JamGeometry, PiersAPierRadiusApartInXStandInTwoLines) {
  ChannelGeometry c = paper_channel();
  c.piers = {{{600.0, 42.5}, 30.0}, {{630.0, 127.5}, 30.0}};
  const JamGeometry g =
      jam_geometry_from_channel(c, {"bank_right", "bank_left", "pier_1", "pier_2"}, "test mesh");
  ASSERT_EQ(g.bridges.size(), 2u);
  // A line with one pier has a gap on each side of it.
  EXPECT_EQ(g.bridges[0].gaps.size(), 2u);
  EXPECT_EQ(g.bridges[1].gaps[0].upper, 97.5);
}

TEST(JamGeometry, MissingPierGroupIsAnInputErrorNamingTheMeshAndTheGroup) {
  try {
    jam_geometry_from_channel(paper_channel(), {"inflow", "bank_right", "bank_left", "pier_1"},
                              "channel.msh");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("channel.msh: the channel's boundary group 'pier_2' is "
                                    "missing from the mesh (it has: inflow, bank_right, "
                                    "bank_left, pier_1)"));
  }
}

TEST(JamGeometry, OtherMeshesGetTheirSolidGroupsAndNoBridges) {
  Mesh mesh;
  mesh.group_names = {"inflow", "bank_outer", "pier_a", "island"};
  const JamGeometry g = jam_geometry_from_groups(mesh, {1, 2, 3});
  ASSERT_EQ(g.solids.size(), 3u);
  EXPECT_EQ(g.solids[0].kind, SolidKind::bank);
  EXPECT_EQ(g.solids[1].kind, SolidKind::pier);
  EXPECT_EQ(g.solids[2].kind, SolidKind::wall);
  EXPECT_EQ(g.solids[2].group, 3);
  EXPECT_TRUE(g.bridges.empty());
}

TEST(CoveredLength, UnionOfOverlappingIntervalsClippedToTheRange) {
  // [0.5, 5.5] meets (-1, 0.5) not at all, [0, 2] u [1, 3] = [0.5, 3] and [5, 6] in [5, 5.5].
  EXPECT_NEAR(covered_length({{0, 2}, {1, 3}, {5, 6}, {-1, 0.5}}, 0.5, 5.5), 3.0, tolerance);
  EXPECT_EQ(covered_length({}, 0.0, 1.0), 0.0);
  EXPECT_NEAR(covered_length({{2, 4}, {0, 10}}, 1.0, 9.0), 8.0, tolerance);  // nested
}

TEST(FootprintHalfExtent, RotatedRectangleProjectsOnBothAxes) {
  BodySet bodies;
  add_log(bodies, 0.0, 0.0, pi / 6.0, 20.0);
  // (L/2)|cos| + (l/2)|sin| = 10 sqrt(3)/2 + 0.25, (L/2)|sin| + (l/2)|cos| = 5 + sqrt(3)/4.
  EXPECT_NEAR(footprint_half_extent_along(bodies, 0, Vec2::UnitX()), 5.0 * std::sqrt(3.0) + 0.25,
              tolerance);
  EXPECT_NEAR(footprint_half_extent_along(bodies, 0, Vec2::UnitY()), 5.0 + std::sqrt(3.0) / 4.0,
              tolerance);
}

// Three logs against the upstream face of pier_1: two across the flow spanning y in
// [72.5, 78.5] and [76.5, 82.5], one along the flow spanning [81.5, 82.5]; together 10 m of the
// 25 m gap between the piers.
TEST(JamStatistics, ThreeLogsAgainstAPierBlockTenOfTheTwentyFiveMetreGap) {
  const BodySet bodies = three_logs_against_pier_1();
  const auto report = make_report(3, {{0, 1}, {1, 2}}, {{0, pier_1}});
  const JamStatistics s = compute_jam_statistics(bodies, report, paper_geometry());
  ASSERT_EQ(s.jams.size(), 1u);
  const Jam& jam = s.jams[0];
  EXPECT_EQ(jam.body_count(), 3);
  EXPECT_THAT(jam.bodies, ElementsAre(0, 1, 2));
  EXPECT_THAT(jam.anchors, ElementsAre(pier_1));
  EXPECT_EQ(jam.bridge, 0);
  ASSERT_EQ(jam.gap_blockage.size(), 3u);
  EXPECT_EQ(jam.gap_blockage[0], 0.0);
  EXPECT_NEAR(jam.gap_blockage[1], 0.4, tolerance);  // 10 m / 25 m
  EXPECT_EQ(jam.gap_blockage[2], 0.0);
  ASSERT_EQ(s.bridge_blockage.size(), 2u);
  EXPECT_NEAR(s.bridge_blockage[0], 0.2, tolerance);  // 10 m / (12.5 + 25 + 12.5) m
  EXPECT_EQ(s.bridge_blockage[1], 0.0);
  EXPECT_THAT(s.touching, ElementsAre(0, 0, 1, 0, 0, 0));
  EXPECT_THAT(s.anchored, ElementsAre(0, 0, 3, 0, 0, 0));
  EXPECT_EQ(s.trapped, 3);
  EXPECT_EQ(s.largest_jam(), 3);
}

TEST(JamStatistics, ThreeLogsBridgingTheGapBetweenTwoPiersAreOneJamBlockingItWhole) {
  BodySet bodies;
  add_log(bodies, 570.0, 80.0, pi / 2.0, 30.0);   // y [65, 95], on pier_1
  add_log(bodies, 569.0, 100.0, pi / 2.0, 10.0);  // y [95, 105], on pier_2
  add_log(bodies, 568.5, 85.0, 0.0, 20.0);        // y [84.5, 85.5]
  const auto report = make_report(3, {{0, 1}, {0, 2}}, {{0, pier_1}, {1, pier_2}});
  const JamStatistics s = compute_jam_statistics(bodies, report, paper_geometry());
  ASSERT_EQ(s.jams.size(), 1u);
  EXPECT_EQ(s.jams[0].body_count(), 3);
  EXPECT_THAT(s.jams[0].anchors, ElementsAre(pier_1, pier_2));
  EXPECT_NEAR(s.jams[0].gap_blockage[1], 1.0, tolerance);
  EXPECT_NEAR(s.bridge_blockage[0], 0.5, tolerance);  // 25 m / 50 m
  EXPECT_THAT(s.touching, ElementsAre(0, 0, 1, 1, 0, 0));
  EXPECT_THAT(s.anchored, ElementsAre(0, 0, 3, 3, 0, 0));
}

TEST(JamStatistics, TwoSeparateClustersAtTwoBridgesAreTwoJams) {
  BodySet bodies;
  add_log(bodies, 575.0, 75.0, pi / 2.0, 4.0);   // y [73, 77], on pier_1
  add_log(bodies, 575.0, 79.0, pi / 2.0, 4.0);   // y [77, 81]
  add_log(bodies, 875.0, 160.0, pi / 2.0, 5.0);  // y [157.5, 162.5], on pier_4
  add_log(bodies, 875.0, 165.0, pi / 2.0, 5.0);  // y [162.5, 167.5]
  add_log(bodies, 864.0, 166.0, 0.0, 20.0);      // y [165.5, 166.5]
  const auto report = make_report(5, {{0, 1}, {2, 3}, {3, 4}}, {{0, pier_1}, {2, pier_4}});
  const JamStatistics s = compute_jam_statistics(bodies, report, paper_geometry());
  ASSERT_EQ(s.jams.size(), 2u);
  EXPECT_THAT(s.jams[0].bodies, ElementsAre(0, 1));
  EXPECT_EQ(s.jams[0].bridge, 0);
  EXPECT_NEAR(s.jams[0].gap_blockage[1], 8.0 / 25.0, tolerance);
  EXPECT_THAT(s.jams[1].bodies, ElementsAre(2, 3, 4));
  EXPECT_THAT(s.jams[1].anchors, ElementsAre(pier_4));
  EXPECT_EQ(s.jams[1].bridge, 1);
  EXPECT_NEAR(s.jams[1].gap_blockage[2], 10.0 / 12.5, tolerance);
  EXPECT_NEAR(s.bridge_blockage[0], 8.0 / 50.0, tolerance);
  EXPECT_NEAR(s.bridge_blockage[1], 10.0 / 50.0, tolerance);
  EXPECT_EQ(s.largest_jam(), 3);
  EXPECT_EQ(s.trapped, 5);
}

TEST(JamStatistics, AFloatingClusterTouchingNothingIsNotAJam) {
  BodySet bodies;
  add_log(bodies, 300.0, 80.0, 0.0, 20.0);
  add_log(bodies, 300.0, 81.0, 0.0, 20.0);
  const auto report = make_report(2, {{0, 1}}, {});
  const JamStatistics s = compute_jam_statistics(bodies, report, paper_geometry());
  EXPECT_TRUE(s.jams.empty());
  EXPECT_EQ(s.trapped, 0);
  EXPECT_EQ(s.floating, 2);
  EXPECT_EQ(s.largest_jam(), 0);
  EXPECT_THAT(s.bridge_blockage, ElementsAre(0.0, 0.0));
}

TEST(JamStatistics, AClusterAnchoredOnABankAndAPierIsOneJam) {
  BodySet bodies;
  add_log(bodies, 570.0, 6.25, pi / 2.0, 12.5);  // y [0, 12.5]: bank_right to pier_1
  add_log(bodies, 560.0, 3.0, 0.0, 20.0);        // along the bank, behind it
  const auto report = make_report(2, {{0, 1}}, {{0, bank_right}, {0, pier_1}, {1, bank_right}});
  const JamStatistics s = compute_jam_statistics(bodies, report, paper_geometry());
  ASSERT_EQ(s.jams.size(), 1u);
  EXPECT_THAT(s.jams[0].anchors, ElementsAre(bank_right, pier_1));
  EXPECT_EQ(s.jams[0].bridge, 0);
  EXPECT_NEAR(s.jams[0].gap_blockage[0], 1.0, tolerance);
  EXPECT_NEAR(s.bridge_blockage[0], 0.25, tolerance);  // 12.5 m / 50 m
  EXPECT_THAT(s.touching, ElementsAre(2, 0, 1, 0, 0, 0));
  EXPECT_THAT(s.anchored, ElementsAre(2, 0, 2, 0, 0, 0));
}

TEST(JamStatistics, ALogOnABankFarFromTheBridgesIsAJamAtNoBridge) {
  BodySet bodies;
  add_log(bodies, 300.0, 169.5, 0.0, 20.0);  // along bank_left, x [290, 310]
  add_log(bodies, 595.0, 2.0, 0.0, 10.0);    // along bank_right, x [590, 600]: bridge_1's band
  const auto report = make_report(2, {}, {{0, bank_left}, {1, bank_right}});
  const JamStatistics s = compute_jam_statistics(bodies, report, paper_geometry());
  ASSERT_EQ(s.jams.size(), 2u);
  EXPECT_EQ(s.jams[0].bridge, -1);
  EXPECT_TRUE(s.jams[0].gap_blockage.empty());
  EXPECT_EQ(s.jams[1].bridge, 0);
  EXPECT_NEAR(s.jams[1].gap_blockage[0], 1.0 / 12.5, tolerance);  // y [1.5, 2.5]
  EXPECT_NEAR(s.bridge_blockage[0], 1.0 / 50.0, tolerance);
}

TEST(JamStatistics, EveryBodyIsTrappedDepositedFloatingOrGoneAndPassedCountsThoseDownstream) {
  BodySet bodies = three_logs_against_pier_1();  // 0, 1, 2: a jam at pier_1
  bodies.state[1] = BodyState::grounded;         // grounded in the jam: trapped
  add_log(bodies, 300.0, 80.0, 0.0, 20.0);       // 3: grounded elsewhere: deposited
  bodies.state[3] = BodyState::grounded;
  add_log(bodies, 950.0, 80.0, 0.0, 20.0);   // 4: floating beyond 900 + 30: passed
  add_log(bodies, 1501.0, 80.0, 0.0, 20.0);  // 5: gone through the outflow: passed, left
  bodies.state[5] = BodyState::gone;
  bodies.outflow_count = 1;
  add_log(bodies, 100.0, 80.0, 0.0, 20.0);  // 6: floating upstream
  // A stale contact of the gone body counts for nothing.
  const auto report = make_report(7, {{0, 1}, {1, 2}, {4, 5}}, {{0, pier_1}, {5, bank_left}});
  const JamStatistics s = compute_jam_statistics(bodies, report, paper_geometry());
  EXPECT_EQ(s.released, 7);
  EXPECT_EQ(s.passed, 2);
  EXPECT_EQ(s.left, 1);
  EXPECT_EQ(s.trapped, 3);
  EXPECT_EQ(s.deposited, 1);
  EXPECT_EQ(s.floating, 2);
  EXPECT_EQ(s.trapped + s.deposited + s.floating + s.left, s.released);
  EXPECT_EQ(s.jams.size(), 1u);
  EXPECT_THAT(s.touching, ElementsAre(0, 0, 1, 0, 0, 0));
}

TEST(JamStatistics, BodiesReleasedAfterTheContactSolveTouchNothing) {
  BodySet bodies = three_logs_against_pier_1();
  add_log(bodies, 100.0, 80.0, 0.0, 20.0);
  const auto report = make_report(3, {{0, 1}, {1, 2}}, {{0, pier_1}});
  const JamStatistics s = compute_jam_statistics(bodies, report, paper_geometry());
  EXPECT_EQ(s.released, 4);
  EXPECT_EQ(s.trapped, 3);
  EXPECT_EQ(s.floating, 1);
}

TEST(JamStatistics, WithoutBridgesPassedCountsTheGoneBodies) {
  Mesh mesh;
  mesh.group_names = {"inflow", "outflow", "bank_inner", "bank_outer"};
  const JamGeometry g = jam_geometry_from_groups(mesh, {2, 3});
  BodySet bodies;
  add_log(bodies, 1.0, 1.0, 0.0, 0.2);
  add_log(bodies, 2.0, 1.0, 0.0, 0.2);
  add_log(bodies, 9.0, 1.0, 0.0, 0.2);
  bodies.state[2] = BodyState::gone;
  bodies.outflow_count = 1;
  const JamStatistics s = compute_jam_statistics(bodies, make_report(3, {}, {{0, 3}}), g);
  EXPECT_EQ(s.passed, 1);
  EXPECT_EQ(s.left, 1);
  EXPECT_EQ(s.jams.size(), 1u);
  EXPECT_EQ(s.jams[0].bridge, -1);
  EXPECT_TRUE(s.bridge_blockage.empty());
  EXPECT_THAT(s.touching, ElementsAre(0, 1));
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(JamStatisticsWriter, HeaderAndRowWithBackwater) {
  const JamGeometry g = paper_geometry();
  const auto report = make_report(3, {{0, 1}, {1, 2}}, {{0, pier_1}});
  JamStatistics s = compute_jam_statistics(three_logs_against_pier_1(), report, g);
  // The water 0.25 m deep, less than the logs' draft: the jam closes its covered width.
  measure_opening_closure(s, g, gap_levels(g, [](const Vec2&) { return GapLevel{0.25, 0.0}; }));
  const auto path = test::scratch_path("flotsam_jam_writer_test_jams.csv");
  {
    JamStatisticsWriter writer(path.string(), g, true);
    const std::vector<double> rise = {0.0125, -0.002};  // [m]
    writer.write(12.5, s, rise);
    EXPECT_THROW(writer.write(13.0, s, {}), std::invalid_argument);
  }
  EXPECT_EQ(read_text(path),
            "time [s],released,passed,left,trapped,deposited,floating,jams,largest jam,"
            "blockage bridge_1 [-],blockage bridge_2 [-],"
            "opening closed bridge_1 [-],opening closed bridge_2 [-],"
            "backwater rise bridge_1 [m],backwater rise bridge_2 [m],"
            "touching bank_right,touching bank_left,touching pier_1,touching pier_2,"
            "touching pier_3,touching pier_4,"
            "anchored bank_right,anchored bank_left,anchored pier_1,anchored pier_2,"
            "anchored pier_3,anchored pier_4\n"
            "12.5,3,0,0,3,0,0,1,3,0.2,0,0.2,0,0.0125,-0.002,0,0,1,0,0,0,0,0,3,0,0,0\n");
  std::filesystem::remove(path);
}

TEST(JamStatisticsWriter, WithoutAReferenceFlowTheBackwaterColumnsAreLeftOut) {
  const JamGeometry g = paper_geometry();
  const auto columns = JamStatisticsWriter::columns(g, false);
  EXPECT_EQ(columns.size(), 9u + 2u + 2u + 6u + 6u);
  EXPECT_EQ(columns[10], "blockage bridge_2 [-]");
  EXPECT_EQ(columns[12], "opening closed bridge_2 [-]");
  EXPECT_EQ(columns[13], "touching bank_right");
}

TEST(JamSummary, AlignedTableOfBridgesJamsAndGroups) {
  const JamGeometry g = paper_geometry();
  const auto report = make_report(3, {{0, 1}, {1, 2}}, {{0, pier_1}});
  JamStatistics s = compute_jam_statistics(three_logs_against_pier_1(), report, g);
  // The water 0.25 m deep, less than the logs' draft: the jam closes its covered width.
  measure_opening_closure(s, g, gap_levels(g, [](const Vec2&) { return GapLevel{0.25, 0.0}; }));
  const std::vector<double> rise = {0.0125, 0.0};
  const std::string text = format_jam_summary(s, g, rise);
  EXPECT_THAT(text, HasSubstr("bodies: 3 released, 0 passed, 0 left, 3 trapped, 0 deposited, "
                              "0 floating\n"));
  EXPECT_THAT(
      text,
      HasSubstr("  bridge       axis centre (x, y) [m]  gaps  blockage opening closed  backwater "
                "rise [m]\n"
                "  bridge_1              (600.0, 85.0)     3     0.200          0.200              "
                "0.0125\n"
                "  bridge_2              (900.0, 85.0)     3     0.000          0.000              "
                "0.0000\n"));
  EXPECT_THAT(text, HasSubstr("  1 jam, largest 3 bodies\n"));
  // The jam's thickness: the logs' draft, 0.579 m for 1 m logs at 600 kg/m^3 (spec 2).
  EXPECT_THAT(text, HasSubstr("  1         3         0.579  pier_1                   bridge_1   "
                              "0.000 0.400 0.000\n"));
  EXPECT_THAT(text, HasSubstr("  pier_1              1        3\n"));
}

}  // namespace
}  // namespace flotsam
