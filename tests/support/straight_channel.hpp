#pragma once
// The scenario the coupled tests share: a straight channel on a structured rectangle mesh
// (mesh/structured_mesh.hpp, groups left/right/bottom/top), a discharge Q in at the left, the
// surface held at H0 over a flat bed at the right, slip walls at the sides, still water at H0 to
// start (Q [m^3/s] constant or a hydrograph). Each test adds its friction, viscosity, time and
// bodies.
#include <initializer_list>
#include <string>

#include "io/case.hpp"

namespace flotsam::test {

inline Case straight_channel_case(const std::string& name, const TimeSeries& Q, double H0) {
  Case c;
  c.name = name;
  c.mesh.kind = MeshSource::Kind::file;  // the mesh is given in memory, not generated
  c.flow.initial_eta_start = c.flow.initial_eta_end = H0;
  c.flow.boundaries = {
      {BoundaryCondition::Kind::discharge, "left", Q, TimeSeries(0.0)},
      {BoundaryCondition::Kind::elevation, "right", TimeSeries(H0), TimeSeries(0.0)},
      {BoundaryCondition::Kind::wall, "bottom", TimeSeries(0.0), TimeSeries(0.0)},
      {BoundaryCondition::Kind::wall, "top", TimeSeries(0.0), TimeSeries(0.0)}};
  return c;
}

inline Case straight_channel_case(const std::string& name, double Q, double H0) {
  return straight_channel_case(name, TimeSeries(Q), H0);
}

/// The bodies of the restart and shared-flow tests: three logs that collide (the middle one
/// slow), and a line at x = 20 m releasing one small log every 2 s until `release_end` [s] from
/// a seeded stream.
inline void add_colliding_logs_and_release(Case& c, double release_end) {
  for (int k = 0; k < 3; ++k) {
    BodySpec log;
    log.length = 6.0;
    log.width = 0.5;
    log.position = Vec2(40.0 + 7.0 * k, 10.0);
    log.velocity = Vec2(k == 1 ? 0.0 : 2.0 - k, 0.0);
    c.bodies.bodies.push_back(log);
  }
  Release line;
  line.line_start = Vec2(20.0, 3.0);
  line.line_end = Vec2(20.0, 17.0);
  line.end_time = release_end;
  line.rate = 30.0;  // [1/min]: one body every 2 s
  line.length_min = 2.0, line.length_max = 5.0;
  line.width_min = 0.2, line.width_max = 0.4;
  line.seed = 7;
  c.bodies.releases = {line};
}

/// Logs across the flow (9.9 m x 0.6 m, 800 kg/m^3: they draw 0.448 m) with their centres at
/// every (x, y) of `xs` x `ys` [m]: two abreast fill a 20 m channel but for 0.1 m at the banks
/// and between them.
inline void add_logs_across(Case& c, std::initializer_list<double> xs,
                            std::initializer_list<double> ys) {
  for (const double x : xs)
    for (const double y : ys) {
      BodySpec log;
      log.length = 9.9;
      log.width = log.height = 0.6;
      log.density = 800.0;
      log.position = Vec2(x, y);
      log.angle = 1.5707963267948966;  // pi / 2: across the flow
      c.bodies.bodies.push_back(log);
    }
}

}  // namespace flotsam::test
