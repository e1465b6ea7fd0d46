#pragma once
// The scenario the coupled tests share: a straight channel on a structured rectangle mesh
// (mesh/structured_mesh.hpp, groups left/right/bottom/top), a discharge Q in at the left, the
// surface held at H0 over a flat bed at the right, slip walls at the sides, still water at H0 to
// start (Q [m^3/s] constant or a hydrograph). Each test adds its friction, viscosity, time and
// bodies.
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

}  // namespace flotsam::test
