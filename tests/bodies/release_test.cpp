// Release (spec 5): explicit bodies are checked where they are placed, with messages naming the
// body; release lines and zones release at their rate, or a count at once, within their ranges,
// reproducibly from a seed; a zone's bodies are uniform in its polygon.
#include "bodies/release.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "bodies/analytic_flow.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"

namespace flotsam {
namespace {

/// A 100 m x 50 m channel, 2 m deep, whose bed rises above the water for x > 80 m.
AnalyticFlow channel() {
  AnalyticFlowSpec spec;
  spec.velocity = {0.5, 0.0};
  spec.eta = 2.0;
  spec.bed_level = -6.0;
  spec.bed_gradient = {0.1, 0.0};  // z_b = -6 + 0.1 x: dry beyond x = 80
  spec.domain_min = {0, 0};
  spec.domain_max = {100, 50};
  return AnalyticFlow(spec);
}

std::string error_of(const BodySpec& spec) {
  BodySet bodies;
  try {
    add_explicit_bodies(bodies, {BodySpec{.position = {20, 25}}, spec}, channel(), 0.0,
                        PlacementCheck{"case.yaml"});
  } catch (const InputError& e) {
    EXPECT_EQ(bodies.size(), 1);  // the good one before it was added
    return e.what();
  }
  return "";
}

TEST(ExplicitBodies, AcceptsAGoodBody) {
  BodySet bodies;
  const int first =
      add_explicit_bodies(bodies, {BodySpec{.position = {20, 25}}}, channel(), 0, PlacementCheck{});
  EXPECT_EQ(first, 0);
  EXPECT_EQ(bodies.size(), 1);
}

TEST(ExplicitBodies, OutsideTheDomainIsAnErrorNamingTheBody) {
  BodySpec s;
  s.position = {-5, 25};
  s.id = 4;
  EXPECT_EQ(error_of(s), "case.yaml: bodies[1] (id 4) at (-5, 25): outside the domain");
}

TEST(ExplicitBodies, ACornerOutsideIsOverlappingAWallOrPier) {
  BodySpec s;
  s.position = {20, 49.8};  // a 20 m x 1 m log along x: its upper side at 50.3
  EXPECT_NE(error_of(s).find("bodies[1] at (20, 49.8): corner (30, 50.3) is outside the domain"),
            std::string::npos)
      << error_of(s);
}

TEST(ExplicitBodies, OnADryPointRestsOnTheBed) {  // a log on a floodplain
  BodySpec s;
  s.position = {85, 25};
  s.angle = pi / 2;
  EXPECT_EQ(error_of(s), "");
}

TEST(ExplicitBodies, NonPositiveSizeOrDensityIsAnError) {
  BodySpec s;
  s.position = {20, 25};
  s.width = 0.0;
  EXPECT_EQ(error_of(s), "case.yaml: bodies[1] at (20, 25): width 0 m must be positive");
  s.width = 1.0;
  s.length = -2.0;
  EXPECT_EQ(error_of(s), "case.yaml: bodies[1] at (20, 25): length -2 m must be positive");
  s.length = 20.0;
  s.density = 0.0;
  EXPECT_EQ(error_of(s), "case.yaml: bodies[1] at (20, 25): density 0 kg/m^3 must be positive");
}

Release line() {
  Release r;
  r.line_start = {10, 10};
  r.line_end = {10, 40};
  r.start_time = 0;
  r.end_time = 600;
  r.rate = 2;  // one body every 30 s
  r.length_min = 5, r.length_max = 15;
  r.width_min = 0.5, r.width_max = 1.0;
  r.density_min = 500, r.density_max = 800;
  r.angle_min_deg = 0, r.angle_max_deg = 90;
  r.seed = 42;
  return r;
}

TEST(Releaser, ReleasesAtTheRateWithinTheRanges) {
  BodySet bodies;
  Releaser releaser({line()}, PlacementCheck{});
  const AnalyticFlow flow = channel();
  // Each body drifts off the line before the next is due (the line is left clear for it).
  std::vector<Vec2> released_at;
  auto release = [&](double t0, double t1) {
    const int n = releaser.release(bodies, flow, t0, t1);
    for (int i = bodies.size() - n; i < bodies.size(); ++i) {
      released_at.push_back(bodies.position[i]);
      bodies.position[i] = {60.0, 25.0};
      bodies.state[i] = BodyState::gone;
    }
    return n;
  };
  int total = 0;
  for (int n = 0; n < 6000; ++n) total += release(n * 0.1, (n + 1) * 0.1);
  EXPECT_EQ(total, 20);  // t = 0, 30, ..., 570 s; t = 600 is not in [0, 600)
  total += release(600.0, 600.1);
  EXPECT_EQ(total, 21);  // t = 600 = end_time is the last one
  EXPECT_EQ(releaser.released(0), 21);
  EXPECT_EQ(releaser.waits(), 0);
  for (int i = 0; i < bodies.size(); ++i) {
    EXPECT_EQ(released_at[i].x(), 10.0);
    EXPECT_GE(released_at[i].y(), 10.0);
    EXPECT_LE(released_at[i].y(), 40.0);
    EXPECT_GE(bodies.length[i], 5.0);
    EXPECT_LE(bodies.length[i], 15.0);
    EXPECT_GE(bodies.width[i], 0.5);
    EXPECT_LE(bodies.width[i], 1.0);
    EXPECT_GE(bodies.density[i], 500.0);
    EXPECT_LE(bodies.density[i], 800.0);
    EXPECT_GE(bodies.angle[i], 0.0);
    EXPECT_LE(bodies.angle[i], pi / 2);
    EXPECT_EQ(bodies.velocity[i], Vec2::Zero());  // released at rest
  }
}

// A body due at a rate is not put on a body already there (the contacts would push the two
// apart at once, through a bank if one is near): it waits, and is released at the first step
// that finds room.
TEST(Releaser, ABodyDueAtARateWaitsForRoomOnItsLine) {
  BodySet bodies;
  bodies.add(BodySpec{.length = 40, .width = 4, .position = {10, 25}, .angle = pi / 2});
  Releaser releaser({line()}, PlacementCheck{});  // due at t = 0, 30, ... on x = 10, y in [10, 40]
  const AnalyticFlow flow = channel();
  EXPECT_EQ(releaser.release(bodies, flow, 0.0, 0.1), 0);  // the log covers the whole line
  EXPECT_EQ(releaser.release(bodies, flow, 0.1, 0.2), 0);
  EXPECT_EQ(releaser.waits(), 2);
  EXPECT_EQ(releaser.released(0), 0);
  bodies.position[0] = {50, 25};  // it drifts off
  EXPECT_EQ(releaser.release(bodies, flow, 0.2, 0.3), 1);
  EXPECT_EQ(releaser.released(0), 1);
  EXPECT_EQ(bodies.position[1].x(), 10.0);
  EXPECT_EQ(releaser.release(bodies, flow, 0.3, 0.4), 0);  // the next is due at t = 30 s
}

TEST(Releaser, SameSeedSameBodiesOtherSeedOtherBodies) {
  const AnalyticFlow flow = channel();
  const auto run = [&](unsigned long seed) {
    Release r = line();
    r.seed = seed;
    BodySet bodies;
    Releaser releaser({r}, PlacementCheck{});
    releaser.release(bodies, flow, 0, 300);
    return bodies;
  };
  const BodySet a = run(42), b = run(42), c = run(43);
  ASSERT_EQ(a.size(), 10);
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.length, b.length);
  EXPECT_EQ(a.angle, b.angle);
  EXPECT_NE(a.position, c.position);
}

TEST(Releaser, BadRatesAndRangesAreErrorsNamingTheRelease) {
  Release r = line();
  r.rate = 0;
  try {
    Releaser({line(), r}, PlacementCheck{"c.yaml"});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "c.yaml: releases[1]: rate = 0 bodies/min must be positive");
  }
  r = line();
  r.width_min = 2, r.width_max = 1;
  try {
    Releaser({r}, PlacementCheck{"c.yaml"});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "c.yaml: releases[0]: width_min = 2 is larger than width_max = 1");
  }
}

TEST(Releaser, ALineOnDryGroundPlacesBodiesThatRestOnTheBed) {  // logs on a floodplain
  Release r = line();
  r.line_start = {85, 10};
  r.line_end = {85, 40};
  r.angle_min_deg = r.angle_max_deg = 90;
  BodySet bodies;
  Releaser releaser({r}, PlacementCheck{"c.yaml"});
  releaser.release(bodies, channel(), 0, 0.1);
  ASSERT_EQ(bodies.size(), 1);  // the first body of the line, at t = 0
  EXPECT_EQ(bodies.position[0].x(), 85.0);
  EXPECT_GE(bodies.position[0].y(), 10.0);
  EXPECT_LE(bodies.position[0].y(), 40.0);
}

/// An L-shaped zone of three 10 m squares: [10, 30] x [10, 20] and [10, 20] x [20, 30].
Release zone() {
  Release r = line();
  r.zone = {{10, 10}, {30, 10}, {30, 20}, {20, 20}, {20, 30}, {10, 30}};
  return r;
}

bool in_l_shape(const Vec2& p) {
  return p.x() >= 10 && p.y() >= 10 &&
         ((p.x() <= 30 && p.y() <= 20) || (p.x() <= 20 && p.y() <= 30));
}

std::string releaser_error(const Release& r, int source_line = 0) {
  Release with_line = r;
  with_line.source_line = source_line;
  try {
    Releaser releaser({line(), with_line}, PlacementCheck{"c.yaml"});
    releaser.check_inside(channel(), 0.0);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Releaser, AZoneReleasesAtTheRateInsideItsPolygon) {
  BodySet bodies;
  Releaser releaser({zone()}, PlacementCheck{});
  EXPECT_EQ(releaser.release(bodies, channel(), 0, 600.1), 21);  // as the line: t = 0, 30, ..., 600
  for (int i = 0; i < bodies.size(); ++i)
    EXPECT_TRUE(in_l_shape(bodies.position[i])) << bodies.position[i].transpose();
}

TEST(Releaser, AZoneIsUniformInItsPolygon) {
  // 30,000 small bodies, one per second: each square of the L holds a third of them, within
  // 4 standard deviations of a binomial count, sqrt(N p (1 - p)) = 82.
  Release r = zone();
  r.rate = 60;
  r.end_time = 29999;
  r.length_min = r.length_max = 0.02;
  r.width_min = r.width_max = 0.01;
  // Each body drifts off before the next (a fresh set each second): the draw alone is measured.
  Releaser releaser({r}, PlacementCheck{});
  const AnalyticFlow flow = channel();
  int squares[3] = {0, 0, 0};  // [10,20]x[10,20], [20,30]x[10,20], [10,20]x[20,30]
  for (int second = 0; second < 30000; ++second) {
    BodySet bodies;
    ASSERT_EQ(releaser.release(bodies, flow, second, second + 1), 1);
    const Vec2 p = bodies.position[0];
    ASSERT_TRUE(in_l_shape(p));
    ++squares[p.y() > 20 ? 2 : p.x() > 20 ? 1 : 0];
  }
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(squares[k], 10000, 4 * 82) << "square " << k;
  std::printf("bodies per square: %d, %d, %d\n", squares[0], squares[1], squares[2]);
}

TEST(Releaser, ACountIsReleasedAtOnceAtTheStartWithoutOverlaps) {
  Release r = zone();
  r.count = 12;  // 82 m^2 of cars in 300 m^2
  r.rate = 0;    // unused with a count
  r.shape = Shape::box;
  r.length_min = r.length_max = 4.0;
  r.width_min = r.width_max = 1.7;
  r.height = 1.5;
  r.angle_min_deg = r.angle_max_deg = 0;  // parked along x
  BodySet bodies;
  Releaser releaser({r}, PlacementCheck{});
  EXPECT_EQ(releaser.release(bodies, channel(), 0, 0.1), 12);
  EXPECT_EQ(releaser.release(bodies, channel(), 0.1, 1000), 0);
  EXPECT_EQ(releaser.released(0), 12);
  for (int i = 0; i < bodies.size(); ++i) {
    EXPECT_TRUE(in_l_shape(bodies.position[i]));
    EXPECT_EQ(bodies.shape[i], Shape::box);
    EXPECT_EQ(bodies.height[i], 1.5);
    for (int j = 0; j < i; ++j) {  // axis-aligned cars overlap when both extents overlap
      const Vec2 gap = (bodies.position[i] - bodies.position[j]).cwiseAbs();
      EXPECT_FALSE(gap.x() < 4.0 && gap.y() < 1.7) << "cars " << j << " and " << i;
    }
  }
  // Released at `start`, not at t = 0.
  r.start_time = 50;
  BodySet later;
  Releaser late({r}, PlacementCheck{});
  EXPECT_EQ(late.release(later, channel(), 0, 50), 0);
  EXPECT_EQ(late.release(later, channel(), 50, 50.1), 12);
}

TEST(Releaser, AZoneTooSmallForItsCountIsAnErrorNamingTheBody) {
  Release r = zone();
  r.count = 200;  // 200 logs 5-15 m long in 300 m^2
  BodySet bodies;
  Releaser releaser({r}, PlacementCheck{"c.yaml"});
  try {
    releaser.release(bodies, channel(), 0, 0.1);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("c.yaml: releases[0] body "), std::string::npos) << what;
    EXPECT_NE(what.find("100 tries"), std::string::npos) << what;
    EXPECT_NE(what.find(": overlaps body "), std::string::npos) << what;
  }
}

TEST(Releaser, ZoneSameSeedSameBodies) {
  const auto run = [](unsigned long seed) {
    Release r = zone();
    r.seed = seed;
    BodySet bodies;
    Releaser releaser({r}, PlacementCheck{});
    releaser.release(bodies, channel(), 0, 300);
    return bodies.position;
  };
  EXPECT_EQ(run(7), run(7));
  EXPECT_NE(run(7), run(8));
}

TEST(Releaser, BadZonesAreErrorsNamingTheReleaseAndTheDefect) {
  Release r = zone();
  r.zone = {{10, 10}, {20, 10}};
  EXPECT_EQ(releaser_error(r),
            "c.yaml: releases[1].zone: a polygon needs at least 3 points; got 2");
  r.zone = {{10, 10}, {20, 20}, {20, 10}, {10, 20}};  // a bow tie
  EXPECT_EQ(releaser_error(r),
            "c.yaml: releases[1].zone: the polygon intersects itself: side 1 (points 1 to 2) "
            "meets side 3 (points 3 to 4)");
  r.zone = {{10, 10}, {20, 20}, {15, 15}};
  EXPECT_EQ(releaser_error(r),
            "c.yaml: releases[1].zone: the polygon has zero area (its points lie on one line)");
  r.zone = {{10, 10}, {20, 10}, {20, 20}, {20, 10}};
  EXPECT_EQ(releaser_error(r), "c.yaml: releases[1].zone: points 2 and 4 coincide at (20, 10) m");
  r = zone();
  r.count = -1;
  EXPECT_EQ(releaser_error(r), "c.yaml: releases[1]: count = -1 bodies must be positive");
}

TEST(Releaser, AZoneOutsideTheDomainIsAnErrorNamingItsCorner) {
  Release r = zone();
  r.zone = {{90, 10}, {120, 10}, {120, 20}};  // the channel ends at x = 100
  EXPECT_EQ(releaser_error(r),
            "c.yaml: releases[1].zone: corner 2 at (120, 10) m is outside the domain; a zone's "
            "corners must lie in the mesh");
  EXPECT_EQ(releaser_error(r, 14),
            "c.yaml:14: bodies.release[1].zone: corner 2 at (120, 10) m is outside the domain; a "
            "zone's corners must lie in the mesh");
}

TEST(Releaser, ALineOutsideTheDomainOrOfNoLengthIsAnErrorBeforeTheRun) {
  Release r = line();
  r.line_start = {50, 40};
  r.line_end = {50, 60};  // the channel ends at y = 50
  EXPECT_THAT(releaser_error(r, 9),
              ::testing::HasSubstr("c.yaml:9: bodies.release[1].line: the point (50.000, 50.159) "
                                   "m of the line from (50, 40) to (50, 60) m is outside the "
                                   "domain"));
  r.line_end = r.line_start;
  EXPECT_EQ(releaser_error(r, 9),
            "c.yaml:9: bodies.release[1].line: both ends are (50, 40) m; a release line needs a "
            "length");
}

}  // namespace
}  // namespace flotsam
