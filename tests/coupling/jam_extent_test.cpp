// Verifies the vertical extent of a jam and the share of a bridge's opening it closes
// (src/coupling/jam_extent.cpp, docs/model.md "Vertical extent of a jam") on hand-built bodies in
// the paper's channel (two bridges of two piers of radius 30 m at y = 42.5 and 127.5 m, 170 m
// wide: gaps of 12.5, 25 and 12.5 m): three logs 1 m thick (lengths 6, 6 and 20 m, density
// 600 kg/m^3) against pier_1 cover 10 m of the 25 m gap. Every expected value is worked out by
// hand from (M-J1) and the definitions.
#include "coupling/jam_extent.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "../support/paper_bridges.hpp"
#include "core/constants.hpp"

namespace flotsam {
namespace {

constexpr double tolerance = 1e-12;  // [-] round-off on ratios of lengths of order 10 m
using namespace test;                // the paper's channel and its logs (support/paper_bridges.hpp)

ContactReport jam_report() {
  ContactReport r;
  r.body_count = 3;
  r.body_body = {{0, 1}, {1, 2}};
  r.body_group = {{0, pier_1}};
  return r;
}

/// The three logs after set_wetted_heights with jams as accumulations at P = 0.5: each acts over
/// `accumulation_T`.
BodySet logs_as_accumulation(const JamGeometry& g) {
  BodySet bodies = three_logs_against_pier_1();
  const JamConfig accumulation{.vertical_extent = JamExtent::accumulation, .porosity = 0.5};
  set_wetted_heights(bodies, compute_jam_statistics(bodies, jam_report(), g), g, accumulation);
  return bodies;
}
// V_s = (pi/4) 1^2 (6 + 6 + 20) m^3 = 8 pi m^3 over w_c = 10 m at P = 0.5: T = sqrt(1.6 pi) m
// (2.242 m).
const double accumulation_T = std::sqrt(8.0 * pi / (0.5 * 10.0));

/// Every gap of both bridges with the same surface and bed [m].
std::vector<std::vector<GapLevel>> flat_levels(const JamGeometry& g, double surface, double bed) {
  return gap_levels(g, [&](const Vec2&) { return GapLevel{surface, bed}; });
}

TEST(AccumulationThickness, IsTheSideOfASquareSectionHoldingTheWoodAtItsPorosity) {
  EXPECT_DOUBLE_EQ(accumulation_thickness(8.0, 4.0, 0.5), 2.0);  // sqrt(8 / (0.5 * 4))
  EXPECT_DOUBLE_EQ(accumulation_thickness(9.0, 1.0, 0.0), 3.0);
  EXPECT_EQ(accumulation_thickness(8.0, 0.0, 0.5), 0.0);  // covers no gap: no accumulation
}

TEST(JamExtent, AFloatingLayerReachesItsBodiesDraftAndClosesThatShareOfTheOpening) {
  const JamGeometry g = paper_geometry();
  BodySet bodies = three_logs_against_pier_1();
  set_wetted_heights(bodies, compute_jam_statistics(bodies, jam_report(), g), g, JamConfig{});
  EXPECT_EQ(bodies.wetted_height, bodies.draft);  // the layer model keeps every draft
  JamStatistics s = compute_jam_statistics(bodies, jam_report(), g);
  const double d = bodies.draft[0];  // [m] the three logs share it
  ASSERT_EQ(s.jams.size(), 1u);
  EXPECT_EQ(s.jams[0].thickness, d);
  measure_opening_closure(s, g, flat_levels(g, 3.0, 0.0));  // 3 m deep, no deck
  EXPECT_THAT(s.jams[0].gap_opening_closed.size(), 3u);
  EXPECT_NEAR(s.jams[0].gap_opening_closed[1], 10.0 * d / (25.0 * 3.0), tolerance);
  EXPECT_EQ(s.jams[0].gap_opening_closed[0], 0.0);
  ASSERT_EQ(s.bridge_opening_closed.size(), 2u);
  EXPECT_NEAR(s.bridge_opening_closed[0], 10.0 * d / (50.0 * 3.0), tolerance);
  EXPECT_EQ(s.bridge_opening_closed[1], 0.0);
}

TEST(JamExtent, AnAccumulationReachesM_J1sThicknessAndItsBodiesActOverIt) {
  const JamGeometry g = paper_geometry();
  const BodySet bodies = logs_as_accumulation(g);
  const double T = accumulation_T;
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(bodies.wetted_height[i], T, 1e-12 * T);
  JamStatistics s = compute_jam_statistics(bodies, jam_report(), g);
  EXPECT_NEAR(s.jams[0].thickness, T, 1e-12 * T);
  measure_opening_closure(s, g, flat_levels(g, 3.0, 0.0));
  EXPECT_NEAR(s.jams[0].gap_opening_closed[1], 10.0 * T / (25.0 * 3.0), tolerance);
  // A depth below T: the jam reaches the bed and closes its covered width entirely.
  measure_opening_closure(s, g, flat_levels(g, 2.0, 0.5));
  EXPECT_NEAR(s.jams[0].gap_opening_closed[1], 10.0 / 25.0, tolerance);
  EXPECT_NEAR(s.bridge_opening_closed[0], 10.0 / 50.0, tolerance);
}

TEST(JamExtent, UnderADeckOnlyThePartOfTheJamBelowTheSoffitClosesTheOpening) {
  JamGeometry g = paper_geometry();
  g.bridges[0].deck = DeckConfig{.soffit = 2.0, .top = 3.0, .width = 2.0};
  JamStatistics s = compute_jam_statistics(logs_as_accumulation(g), jam_report(), g);
  const double T = accumulation_T;
  // The surface at 3 m, above the soffit (pressure flow): the opening is [0, 2] m, the jam
  // [3 - T, 3] m; it closes [3 - T, 2] m of it.
  measure_opening_closure(s, g, flat_levels(g, 3.0, 0.0));
  EXPECT_NEAR(s.jams[0].gap_opening_closed[1], 10.0 * (2.0 - (3.0 - T)) / (25.0 * 2.0), tolerance);
  EXPECT_NEAR(s.bridge_opening_closed[0], 10.0 * (2.0 - (3.0 - T)) / (50.0 * 2.0), tolerance);
  // A dry gap has no opening to close.
  measure_opening_closure(s, g, flat_levels(g, 0.0, 0.0));
  EXPECT_EQ(s.jams[0].gap_opening_closed[1], 0.0);
  EXPECT_EQ(s.bridge_opening_closed[0], 0.0);
}

TEST(JamExtent, TwoJamsInOneGapCloseItOnce) {
  // One jam against the piers and one behind it, each across the whole 25 m gap and deeper than
  // the 3 m of water: the gap is closed, once; the bridge's other gaps (12.5 m each) are open.
  const JamGeometry g = paper_geometry();
  JamStatistics s;
  for (int k = 0; k < 2; ++k) {
    Jam jam;
    jam.bridge = 0;
    jam.gap_blockage = {0.0, 1.0, 0.0};
    jam.thickness = 5.0;
    s.jams.push_back(jam);
  }
  measure_opening_closure(s, g, flat_levels(g, 3.0, 0.0));
  for (const Jam& jam : s.jams) EXPECT_NEAR(jam.gap_opening_closed[1], 1.0, tolerance);
  EXPECT_NEAR(s.bridge_opening_closed[0], 25.0 / 50.0, tolerance);
}

TEST(JamExtent, BodiesOutOfEveryJamGetTheirDraftBack) {
  const JamGeometry g = paper_geometry();
  BodySet bodies = logs_as_accumulation(g);
  const JamConfig accumulation{.vertical_extent = JamExtent::accumulation, .porosity = 0.5};
  ContactReport apart;  // the jam broke up: nothing touches
  apart.body_count = 3;
  set_wetted_heights(bodies, compute_jam_statistics(bodies, apart, g), g, accumulation);
  EXPECT_EQ(bodies.wetted_height, bodies.draft);
}

}  // namespace
}  // namespace flotsam
