// Verifies that a bridge deck stops what floats (docs/model.md "Decks"): a straight flume 200 m
// long and 20 m wide, 2 m of water moving at 0.5 m/s (finite volumes, one-way), a bridge across it
// at x = 100 m without piers whose deck, 4 m wide, puts its upstream face at x = 98 m. A log of
// 0.5 m diameter and 600 kg/m^3 floats with its underside at 2 - d and its top at 2 - d + 0.5,
// d = 0.29 m its draft (Archimedes). Expected, from the vertical extents alone:
//   soffit 2.1 m, below the log's top: the log stops against the face at every angle of approach,
//     and counts as trapped at the bridge, in a jam anchored on the deck;
//   soffit 2.5 m, above its top: it passes under and ends beyond the bridge;
//   deck top 1.5 m (soffit 1.0 m), below its underside: it floats over the deck;
//   a car (a 1.5 m high box of 110 kg/m^3) meets a soffit of 2.5 m and stops.
// "Stops": over the last 10 s no point of its footprint beyond the face by more than 1 % of its
// width nor more than 0.2 m short of it (a log turning against the face rocks off it), and trapped
// at the bridge, in a jam anchored on the deck's face, at least 8 of the last 20 steps: a body at
// rest against a wall leaves its contact group every other step (the contact planner sees it still,
// docs/model.md "Contacts"), and the statistics count contacts.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "../support/bridge_across.hpp"
#include "../support/straight_channel.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"
#include "coupling/simulation.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

constexpr double face_x = 98.0;  // [m] the deck's upstream face

struct Outcome {
  double front = 0.0;                        // [m] the largest x of the body's footprint at the end
  double front_min = 1e9, front_max = -1e9;  // [m] over the last 10 s
  int trapped_at_deck = 0;  // of the last 20 steps: trapped at the bridge against the deck
  JamStatistics jams;       // at the end; its last solid is the deck's face
};

/// The flume with its footbridge and `bodies` (none, or the one body).
Case flume_with_deck(const std::vector<BodySpec>& bodies, double soffit, double top) {
  Case c = test::straight_channel_case("deck", 20.0, 2.0);  // 20 m^3/s over 20 m x 2 m: 0.5 m/s
  c.flow.engine = FlowEngineKind::fv;
  c.flow.initial_u = Expression("0.5", "the flume's current");
  c.time = {.end = 50.0, .step = 0.5, .mode = CouplingMode::one_way};
  c.output.interval = 50.0;
  c.bodies.bodies = bodies;
  c.bodies.contact.restitution = 0.0;  // it comes to rest against the face, not bouncing off
  c.bridges = {test::bridge_across("footbridge", 100.0, 20.0, test::plain_deck(soffit, top, 4.0))};
  return c;
}

Outcome run_towards_deck(const BodySpec& body, double soffit, double top) {
  const Case c = flume_with_deck({body}, soffit, top);
  Simulation s(
      c, make_rectangle_mesh({.length = 200, .width = 20, .nx = 100, .ny = 10}),
      {.output_directory = {}, .overwrite = false, .write_output = false, .progress = false});
  s.initialize();
  Outcome o;
  const BodySet& b = s.bodies();
  while (!s.done()) {
    s.step();
    o.front = b.position[0].x() + footprint_half_extent_along(b, 0, Vec2::UnitX());
    if (s.time() <= c.time.end - 10.0) continue;
    o.front_min = std::min(o.front_min, o.front);
    o.front_max = std::max(o.front_max, o.front);
    const JamStatistics jams = s.jam_statistics();
    o.trapped_at_deck += jams.jams.size() == 1 && jams.jams[0].bridge == 0 &&
                         jams.touching.back() == 1 && jams.trapped == 1;
  }
  o.jams = s.jam_statistics();
  return o;
}

BodySpec log_at(double angle_deg) {
  BodySpec log;
  log.length = 6.0;
  log.width = 0.5;
  log.height = 0.5;
  log.density = 600.0;
  log.position = Vec2(85.0, 10.0);
  log.angle = angle_deg * pi / 180.0;
  log.velocity = Vec2(0.5, 0.0);
  return log;
}

TEST(DeckStopsWhatFloats, ALogWhoseTopStandsAboveTheSoffitStopsAtEveryAngle) {
  for (const double angle : {0.0, 30.0, 60.0, 90.0}) {
    const Outcome o = run_towards_deck(log_at(angle), 2.1, 3.0);
    std::printf(
        "%g deg: front in [%.4f, %.4f] m over the last 10 s, trapped at the deck %d of "
        "20 steps\n",
        angle, o.front_min, o.front_max, o.trapped_at_deck);
    EXPECT_LE(o.front_max, face_x + 0.01 * 0.5) << angle << " deg";
    EXPECT_GE(o.front_min, face_x - 0.2) << angle << " deg: it should have reached the face";
    EXPECT_GE(o.trapped_at_deck, 8) << angle << " deg";
    EXPECT_EQ(o.jams.passed, 0);
  }
}

TEST(DeckStopsWhatFloats, ALogBelowTheSoffitPassesUnder) {
  const Outcome o = run_towards_deck(log_at(0.0), 2.5, 3.0);
  EXPECT_GT(o.front, 102.0 + 3.0);  // beyond the deck's downstream face and its own length
  EXPECT_EQ(o.jams.trapped, 0);
  EXPECT_EQ(o.jams.passed, 1);
}

TEST(DeckStopsWhatFloats, ALogAboveAnOvertoppedDeckFloatsOverIt) {
  const Outcome o = run_towards_deck(log_at(0.0), 1.0, 1.5);
  EXPECT_GT(o.front, 102.0 + 3.0);
  EXPECT_EQ(o.jams.passed, 1);
}

TEST(DeckStopsWhatFloats, ACarStopsAgainstTheFace) {
  BodySpec car;
  car.shape = Shape::box;
  car.length = 4.0;
  car.width = 1.8;
  car.height = 1.5;
  car.density = 110.0;
  car.position = Vec2(90.0, 10.0);
  car.velocity = Vec2(0.5, 0.0);
  const Outcome o = run_towards_deck(car, 2.5, 3.0);
  std::printf(
      "car: front in [%.4f, %.4f] m over the last 10 s, trapped at the deck %d of 20 "
      "steps\n",
      o.front_min, o.front_max, o.trapped_at_deck);
  EXPECT_LE(o.front_max, face_x + 0.01 * 1.8);
  EXPECT_GE(o.front_min, face_x - 0.2);
  EXPECT_GE(o.trapped_at_deck, 8);
}

TEST(DeckStopsWhatFloats, ADeckBelowTheBedIsRefusedEvenWithoutBodies) {
  Simulation s(
      flume_with_deck({}, -2.0, -1.0),
      make_rectangle_mesh({.length = 200, .width = 20, .nx = 100, .ny = 10}),
      {.output_directory = {}, .overwrite = false, .write_output = false, .progress = false});
  EXPECT_THROW(s.initialize(), InputError);
}

TEST(DeckStopsWhatFloats, ADeckBelowTheBedIsRefusedNamingTheBridge) {
  try {
    (void)run_towards_deck(log_at(0.0), -2.0, -1.0);  // the bed is at 0 m
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()),
                ::testing::HasSubstr("test: bridge 'footbridge': its deck's top (-1 m) is below "
                                     "the bed everywhere along its axis (the lowest bed there is "
                                     "0 m)"));
  }
}

}  // namespace
}  // namespace flotsam
