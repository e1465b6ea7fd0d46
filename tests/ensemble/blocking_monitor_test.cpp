// Blocking (docs/model.md "Blocking") on a hand-made channel: one pier of radius 8 m at y = 30 m
// in a 60 m channel leaves the gaps [0, 22] and [38, 60] m; a 20 m log across the flow at
// y = 11 m covers [1, 21] m, 20/22 of the first gap.
#include "ensemble/blocking_monitor.hpp"

#include "coupling/jam_extent.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace flotsam {
namespace {

struct OneLogAtOnePier : ::testing::Test {
  JamGeometry geometry;
  BodySet bodies;
  void SetUp() override {
    ChannelGeometry channel;
    channel.length = 240;
    channel.width = 60;
    channel.piers = {{{150, 30}, 8}};
    geometry = jam_geometry_from_channel(
        channel, {"inflow", "outflow", "bank_right", "bank_left", "pier_1"}, "test");
    BodySpec log;
    log.length = 20;
    log.width = 1;
    log.position = {140, 11};
    log.angle = std::numbers::pi / 2;  // across the flow
    bodies.add(log);
  }
  /// The statistics with the log in a jam at the bridge, or in none.
  JamStatistics statistics(bool jammed) const {
    JamStatistics s;
    s.bridge_blockage = {jammed ? 20.0 / 44.0 : 0.0};
    s.released = 1;
    if (jammed) s.jams.push_back({{0}, {2}, 0, {}, 0.0, {}});
    (jammed ? s.trapped : s.floating) = 1;
    return s;
  }
};

TEST_F(OneLogAtOnePier, GapCoverIsTheLogsSpanOverTheGapWidth) {
  ASSERT_EQ(geometry.bridges.size(), 1u);
  const std::vector<double> cover = gap_cover(statistics(true), bodies, geometry, 0);
  ASSERT_EQ(cover.size(), 2u);
  EXPECT_NEAR(cover[0], 20.0 / 22.0, 1e-12);  // footprint span y = 11 +- (10 |sin| + 0.5 |cos|)
  EXPECT_NEAR(cover[1], 0.0, 1e-15);
}

TEST_F(OneLogAtOnePier, HeldForTheDurationBlocksFromItsStart) {
  BlockingMonitor monitor(geometry, {0.5, 2.0, 1.0});
  monitor.note_new_bodies(bodies);
  monitor.sample(0.0, statistics(false), bodies, {});
  monitor.sample(1.0, statistics(true), bodies, {});
  monitor.sample(2.0, statistics(true), bodies, {});
  MemberResult early;
  monitor.finish(statistics(true), bodies, early);
  EXPECT_FALSE(early.bridges[0].blocked);  // held 1 s < 2 s so far
  monitor.sample(3.0, statistics(true), bodies, std::vector<double>{0.04});
  MemberResult r;
  monitor.finish(statistics(true), bodies, r);
  EXPECT_TRUE(r.gaps[0][0].blocked);
  EXPECT_EQ(r.gaps[0][0].blocking_time, 1.0);
  EXPECT_FALSE(r.gaps[0][1].blocked);
  EXPECT_TRUE(r.bridges[0].blocked);
  EXPECT_EQ(r.bridges[0].blocking_time, 1.0);
  EXPECT_EQ(r.bridges[0].blocking_bodies, 1);
  EXPECT_EQ(r.bridges[0].largest_jam, 1);
  EXPECT_EQ(r.bridges[0].max_rise, 0.04);
  EXPECT_NEAR(r.bridges[0].max_blockage, 20.0 / 44.0, 1e-15);
  EXPECT_EQ(r.trapped, 1);
  ASSERT_EQ(r.bodies.size(), 1u);
  EXPECT_EQ(r.bodies[0].fate, BodyFate::trapped);
}

TEST_F(OneLogAtOnePier, ABreakRestartsTheClock) {
  BlockingMonitor monitor(geometry, {0.5, 2.0, 1.0});
  const bool covered[] = {true, true, false, true, true, true};
  for (int t = 0; t < 6; ++t) monitor.sample(t, statistics(covered[t]), bodies, {});
  MemberResult r;
  monitor.finish(statistics(true), bodies, r);
  EXPECT_TRUE(r.gaps[0][0].blocked);
  EXPECT_EQ(r.gaps[0][0].blocking_time, 3.0);      // not 0: the run 0-1 s lasted only 1 s
  EXPECT_TRUE(std::isnan(r.bridges[0].max_rise));  // no reference flow
}

TEST_F(OneLogAtOnePier, BelowTheFractionNeverBlocks) {
  BlockingMonitor monitor(geometry, {0.95, 0.0, 1.0});  // 20/22 = 0.91 < 0.95
  for (int t = 0; t < 5; ++t) monitor.sample(t, statistics(true), bodies, {});
  MemberResult r;
  monitor.finish(statistics(true), bodies, r);
  EXPECT_FALSE(r.bridges[0].blocked);
  EXPECT_NEAR(r.gaps[0][0].max_cover, 20.0 / 22.0, 1e-12);
}

// The jam closes its gap's opening over its thickness T from the surface down (model.md
// "Blocking"): with 2 m of water at both gaps and T = 0.5 m, gap 1 loses 20 m x 0.5 m of its
// 22 m x 2 m, the bridge 10/88 of its two openings; the member keeps each largest share.
TEST_F(OneLogAtOnePier, KeepsTheLargestClosedShareOfTheOpenings) {
  const auto closure = [&](double thickness) {
    JamStatistics s = statistics(true);
    s.jams[0].gap_blockage = {20.0 / 22.0, 0.0};
    s.jams[0].thickness = thickness;  // [m]
    measure_opening_closure(s, geometry, {{{2.0, 0.0}, {2.0, 0.0}}});
    return s;
  };
  BlockingMonitor monitor(geometry, {0.5, 2.0, 1.0});
  monitor.sample(0.0, closure(0.25), bodies, {});
  monitor.sample(1.0, closure(0.5), bodies, {});
  monitor.sample(2.0, closure(0.1), bodies, {});
  MemberResult r;
  monitor.finish(closure(0.1), bodies, r);
  EXPECT_NEAR(r.gaps[0][0].max_opening_closed, 20.0 * 0.5 / (22.0 * 2.0), 1e-15);
  EXPECT_EQ(r.gaps[0][1].max_opening_closed, 0.0);
  EXPECT_NEAR(r.bridges[0].max_opening_closed, 20.0 * 0.5 / 88.0, 1e-15);
  const MemberResult back = parse_member(serialize_member(r));
  EXPECT_EQ(back.gaps[0][0].max_opening_closed, r.gaps[0][0].max_opening_closed);
  EXPECT_EQ(back.bridges[0].max_opening_closed, r.bridges[0].max_opening_closed);
}

// Two jams one behind the other in gap 1, each reaching the bed (T = 3 m in 2 m of water) across
// 20 m of its 22 m: each closes 10/11 of it, together the gap at most once.
TEST_F(OneLogAtOnePier, TwoJamsInOneGapCloseItAtMostOnce) {
  JamStatistics s = statistics(true);
  s.jams[0].gap_blockage = {20.0 / 22.0, 0.0};
  s.jams[0].thickness = 3.0;  // [m]
  s.jams.push_back(s.jams[0]);
  measure_opening_closure(s, geometry, {{{2.0, 0.0}, {2.0, 0.0}}});
  BlockingMonitor monitor(geometry, {0.5, 2.0, 1.0});
  monitor.sample(0.0, s, bodies, {});
  MemberResult r;
  monitor.finish(s, bodies, r);
  EXPECT_EQ(r.gaps[0][0].max_opening_closed, 1.0);
  EXPECT_NEAR(r.bridges[0].max_opening_closed, 0.5, 1e-15);  // gap 1 of two 22 m gaps
}

}  // namespace
}  // namespace flotsam
