#pragma once
// Random throws of single logs at the banks and a pier of a straight channel, stepped as the
// simulation steps them (src/bodies/body_integrator.hpp): each flow step planned by the contact
// stage (src/contact/contact_planner.hpp), the log free over the step when no wall is within its
// reach, else moved in its group's K equal contact intervals with the contact stage after each.
// Shared by no_tunnelling_through_walls.cpp (default run) and no_tunnelling_through_walls_slow.cpp
// (the full 100,000 throws).
//
//     bank y = 40  -----------------------------
//                          ( )  pier: centre (0, 20), radius 2, 64-gon
//     bank y = 0   -----------------------------
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "contact/contact_world.hpp"
#include "core/constants.hpp"

namespace flotsam::test {

struct ThrowStatistics {
  long throws = 0;
  long intervals = 0;        // contact intervals stepped, all throws
  long crossings = 0;        // intervals after which a log's centre was across a wall
  long hits = 0;             // throws that touched a wall
  double deepest = 0.0;      // largest overlap seen after any interval, relative to l [-]
  double deepest_end = 0.0;  // largest overlap left at the end of a throw, relative to l [-]
};

constexpr double channel_width = 40.0;     // [m]
inline const Vec2 pier_centre{0.0, 20.0};  // [m]
constexpr double pier_radius = 2.0;        // [m]
constexpr int pier_sides = 64;

inline BoundarySegments throw_channel() {
  BoundarySegments walls;
  walls.group_names = {"bank_right", "bank_left", "pier"};
  walls.add_segment({-100.0, 0.0}, {100.0, 0.0}, 0);
  walls.add_segment({100.0, channel_width}, {-100.0, channel_width}, 1);
  walls.add_circle_hole(pier_centre, pier_radius, pier_sides, 2);
  walls.build_grid(2.0);
  return walls;
}

// True when G is on the dry side of a bank or inside the pier polygon (its inscribed circle).
inline bool centre_across_a_wall(const Vec2& G) {
  const double inscribed = pier_radius * std::cos(pi / pier_sides);  // [m]
  return G.y() < 0.0 || G.y() > channel_width || (G - pier_centre).norm() < inscribed;
}

// One log thrown from 0.1 to 3 m in front of the right bank, the left bank or the pier,
// towards it within +-80 degrees of the normal, at a speed up to 10 m/s, spinning up to 2 rad/s,
// with e in [0, 1]; stepped for 1.5 s of flow steps of 0.02 s.
inline void throw_one_log(std::mt19937& rng, const BoundarySegments& walls, ThrowStatistics& s) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  constexpr double flow_step = 0.02;  // [s]
  constexpr int flow_steps = 75;
  BodySpec log;
  BodySet bodies;
  ContactConfig config;
  ContactWorld world(config);
  do {  // drawn again while the log starts touching a wall (a long log near the pier)
    log.length = 1.0 + 15.0 * unit(rng);  // L [m]
    log.width = 0.1 + 0.9 * unit(rng);    // l [m]
    log.angle = 2.0 * pi * unit(rng);
    const int target = static_cast<int>(3.0 * unit(rng));
    const double phi = 2.0 * pi * unit(rng);       // [rad] place on the pier
    const Vec2 n = target == 0   ? Vec2(0.0, 1.0)  // surface normal, into the water
                   : target == 1 ? Vec2(0.0, -1.0)
                                 : Vec2(std::cos(phi), std::sin(phi));
    const Vec2 surface = target == 0   ? Vec2(60.0 * (unit(rng) - 0.5), 0.0)
                         : target == 1 ? Vec2(60.0 * (unit(rng) - 0.5), channel_width)
                                       : Vec2(pier_centre + pier_radius * n);
    const Vec2 axis(std::cos(log.angle), std::sin(log.angle));
    const double reach = 0.5 * log.length * std::abs(axis.dot(n)) +
                         0.5 * log.width * std::abs(cross(axis, n));  // [m] extent along n
    log.position = surface + (reach + 0.1 + 2.9 * unit(rng)) * n;
    const double aim = (unit(rng) - 0.5) * 2.0 * 80.0 * pi / 180.0;  // [rad] off the normal
    const Vec2 towards = -(std::cos(aim) * n + std::sin(aim) * perp(n));
    log.velocity = 10.0 * unit(rng) * towards;
    log.angular_velocity = 2.0 * (2.0 * unit(rng) - 1.0);
    config.restitution = unit(rng);
    bodies = BodySet{};
    bodies.add(log);
    world.detect(bodies, walls);
  } while (!world.contacts().empty());
  world = ContactWorld(config);

  bool hit = false;
  for (int step = 0; step < flow_steps; ++step) {
    // The flow step as the simulation steps it: planned (ContactWorld::plan), then the log free
    // over the whole step or in its group's intervals, the contact stage after each (the last at
    // the step's end).
    const ContactSchedule plan = world.plan(bodies, walls, flow_step);
    const int K = plan.groups.empty() ? 1 : plan.groups.front().intervals;
    const double h = flow_step / K;  // [s] contact interval
    for (int k = 0; k < K; ++k) {
      bodies.position[0] += h * bodies.velocity[0];
      bodies.angle[0] += h * bodies.angular_velocity[0];
      // As BodyIntegrator::advance: a group's intervals but its last, then every linked body at
      // the step's end (a log needing one interval is free but linked).
      if (k + 1 < K) {
        world.step(bodies, walls, h, &plan.groups.front().bodies);
      } else if (!plan.at_end.empty()) {
        world.step(bodies, walls, h, &plan.at_end);
      }
      ++s.intervals;
      double overlap = 0.0;  // [m] at detection
      for (const ContactConstraint& c : world.contacts()) {
        for (int q = 0; q < c.point_count; ++q) {
          overlap = std::max(overlap, -c.points[static_cast<std::size_t>(q)].separation);
        }
      }
      hit = hit || !world.contacts().empty();
      s.deepest = std::max(s.deepest, overlap / log.width);  // at detection, before correction
      if (centre_across_a_wall(bodies.position[0])) ++s.crossings;
    }
  }
  ++s.throws;
  if (hit) ++s.hits;
  s.deepest_end = std::max(s.deepest_end, world.profile().largest_overlap / log.width);
}

inline ThrowStatistics throw_logs(long count, unsigned seed) {
  std::mt19937 rng(seed);
  const BoundarySegments walls = throw_channel();
  ThrowStatistics s;
  for (long t = 0; t < count; ++t) throw_one_log(rng, walls, s);
  return s;
}

// Throws `count` logs (seed `seed`) and checks the exact answer, zero crossings, with the
// contacts exercised (most throws reach their wall), no overlap reaching the log's axis (l/2),
// and at most `deepest_end` (relative to l) left at the end of a throw.
inline void expect_no_crossings(long count, unsigned seed, double deepest_end) {
  const ThrowStatistics s = throw_logs(count, seed);
  EXPECT_EQ(s.throws, count);
  EXPECT_EQ(s.crossings, 0);
  EXPECT_GT(s.hits, s.throws / 2);
  EXPECT_LT(s.deepest, 0.5);
  EXPECT_LT(s.deepest_end, deepest_end);
  testing::Test::RecordProperty("intervals", static_cast<int>(s.intervals));
  testing::Test::RecordProperty("hits", static_cast<int>(s.hits));
  testing::Test::RecordProperty("deepest_permille", static_cast<int>(1000.0 * s.deepest));
  testing::Test::RecordProperty("deepest_end_per_100000", static_cast<int>(1e5 * s.deepest_end));
}

}  // namespace flotsam::test
