// Release (spec 5): explicit bodies are checked where they are placed, with messages naming the
// body; release lines release at their rate, within their ranges, reproducibly from a seed.
#include "bodies/release.hpp"

#include <gtest/gtest.h>

#include <cmath>

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
  int total = 0;
  for (int n = 0; n < 6000; ++n) total += releaser.release(bodies, flow, n * 0.1, (n + 1) * 0.1);
  EXPECT_EQ(total, 20);  // t = 0, 30, ..., 570 s; t = 600 is not in [0, 600)
  total += releaser.release(bodies, flow, 600.0, 600.1);
  EXPECT_EQ(total, 21);  // t = 600 = end_time is the last one
  EXPECT_EQ(releaser.released(0), 21);
  for (int i = 0; i < bodies.size(); ++i) {
    EXPECT_EQ(bodies.position[i].x(), 10.0);
    EXPECT_GE(bodies.position[i].y(), 10.0);
    EXPECT_LE(bodies.position[i].y(), 40.0);
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

}  // namespace
}  // namespace flotsam
