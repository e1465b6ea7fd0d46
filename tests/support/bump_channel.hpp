#pragma once
// The channel of the transcritical bump cases (Goutal & Maurel 1997; SWASHES 4.1.3, Delestre et
// al. 2013) for the finite-volume engine: 25 m x 0.25 m, frictionless, the bump
// z_b = 0.2 - 0.05 (x - 10)^2 on 8 < x < 12 m, q [m^2/s] in on the left, the level h_out [m]
// held on the right while the outflow is subcritical, water at rest at h_out to start; 200 x 2
// rectangles (800 cells, 0.125 m wide).
#include "fv_cases.hpp"

namespace flotsam::test {

struct BumpChannel {
  static constexpr double length = 25.0, width = 0.25, z_top = 0.2;  // [m]
  static double bed(double x) {                                      // [m]
    return x > 8.0 && x < 12.0 ? 0.2 - 0.05 * (x - 10.0) * (x - 10.0) : 0.0;
  }
  static Mesh mesh() { return make_rectangle_mesh({0.0, 0.0, length, width, 200, 2, true}); }
  static Case flow_case(double q, double h_out) {
    Case c = fv_case({"bottom", "top"});
    c.bed.kind = BedConfig::Kind::expression;
    c.bed.expression = Expression("x > 8 && x < 12 ? 0.2 - 0.05 * (x - 10)^2 : 0", "bump");
    c.flow.initial_eta_start = c.flow.initial_eta_end = h_out;
    c.flow.boundaries.push_back(
        {BoundaryCondition::Kind::discharge, "left", TimeSeries(q * width), TimeSeries(0.0)});
    c.flow.boundaries.push_back(
        {BoundaryCondition::Kind::elevation, "right", TimeSeries(h_out), TimeSeries(0.0)});
    return c;
  }
};

}  // namespace flotsam::test
