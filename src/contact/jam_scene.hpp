#pragma once
// The jam scene shared by the jam test (tests/verification/log_jam_at_piers.cpp) and the contact
// benchmark (bench/contacts.cpp), so that the case the benchmark times is the case a test checks
// (spec/style.md habit 12).
//
// A straight channel along +x between two banks, a row of circular piers across it at x = 0,
// and logs lying across the channel upstream in rows, each log centred on a gap between two
// piers and longer than the gap, so that it bears on both:
//
//     bank y = W  ------------------------------------------
//                  |  |  |  |                (  )  pier j at y = 6 + 8 j, radius 2
//                  logs in rows, x < 0       (  )  (gaps of 4 m; logs 10 m long)
//     bank y = 0  ------------------------------------------
//
// A constant force along +x on each log stands in for the drag of the flow.
#include "bodies/body_set.hpp"
#include "contact/boundary_segments.hpp"
#include "io/case.hpp"

namespace flotsam {

struct JamSceneSpec {
  int log_count = 50;
  int pier_count = 2;          // >= 2
  double log_length = 10.0;    // L [m]
  double log_width = 0.5;      // l [m]
  double row_gap = 0.3;        // [m] free space between rows at the start (0: packed)
  double angle_jitter = 0.05;  // [rad] largest random turn from broadside
  int pier_sides = 64;         // segments per pier circle
  unsigned seed = 1;
};

struct JamScene {
  BodySet bodies;
  BoundarySegments walls;      // groups: 0 bank_right (y = 0), 1 bank_left (y = W), 2.. piers
  double pier_x = 0.0;         // [m] the piers' centre line
  double pier_radius = 2.0;    // [m]
  double channel_width = 0.0;  // W [m]
};

JamScene make_jam_scene(const JamSceneSpec& spec);

constexpr double jam_push = 0.2;  // [m s^-2] force per unit mass along +x (the drag's stand-in)
constexpr double jam_max_step = 0.02;  // [s] longest step of the scene

/// The contacts of the scene: a little restitution, and sweeps enough for a column of 50 logs.
ContactConfig jam_contact_config();

/// Moves the logs one step under the push, semi-implicit Euler, the step limited as the body
/// integrator limits its sub-steps (spec 3.5: no point of a body moves more than l/4); returns
/// the step [s]. The caller then applies the contact stage over that interval.
double move_jam_logs(JamScene& scene);

}  // namespace flotsam
