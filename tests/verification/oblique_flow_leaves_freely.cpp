// Verifies that water leaves through an elevation boundary with the tangential velocity it has
// (spec 1.4; docs/model.md "Boundary conditions": u . t is held at zero only where water
// enters). Uniform oblique flow u = (1, 0.3) m/s over a flat bed, depth 2 m, no friction, is an
// exact steady solution of (M-1): it enters through the left and bottom sides (velocity
// imposed), leaves through the top (velocity imposed) and through the right side, where only
// eta = 2 m is imposed. Started from that solution, 20 steps of 2 s (both time schemes with
// characteristics, with either step) must keep it: max |u - (1, 0.3)| <= 1e-9 m/s and max
// |eta - 2| <= 1e-9 m. Holding u . t = 0 at the right side too would force v = 0 there, an error of
// 0.3 m/s.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/time_schemes.hpp"
#include "flow/fem/shallow_water_solver.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

class ObliqueFlow : public testing::TestWithParam<test::StepAndTime> {};

TEST_P(ObliqueFlow, LeavesThroughAnElevationBoundaryUnchanged) {
  const double U = 1.0, V = 0.3, H = 2.0;  // [m/s], [m/s], [m]
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 100.0, 40.0, 10, 4, true});
  Case c;
  c.flow.initial_eta_start = c.flow.initial_eta_end = H;
  c.flow.viscosity = 0.01;  // [m^2/s]
  c.flow.scheme = GetParam().flow;
  c.time.scheme = GetParam().time;
  const TimeSeries u(U), v(V);
  for (const char* side : {"left", "bottom", "top"})
    c.flow.boundaries.push_back({BoundaryCondition::Kind::velocity, side, u, v, 0});
  c.flow.boundaries.push_back({BoundaryCondition::Kind::elevation, "right", TimeSeries(H), {}, 0});
  ShallowWaterSolver solver(mesh, c);
  solver.initialize();
  FlowState uniform = solver.state();
  std::fill(uniform.u.begin(), uniform.u.end(), U);
  std::fill(uniform.v.begin(), uniform.v.end(), V);
  solver.set_state(uniform);
  for (int n = 0; n < 20; ++n) solver.step(2.0);
  double du = 0.0, deta = 0.0;
  for (int i = 0; i < mesh.node_count(); ++i)
    du = std::max(du, std::hypot(solver.u()[i] - U, solver.v()[i] - V));
  for (double eta : solver.eta()) deta = std::max(deta, std::abs(eta - H));
  EXPECT_LE(du, 1e-9);
  EXPECT_LE(deta, 1e-9);
  std::printf("oblique flow: max |u - U| %.2e m/s, max |eta - H| %.2e m\n", du, deta);
}

INSTANTIATE_TEST_SUITE_P(Schemes, ObliqueFlow, test::all_steps_and_times, test::step_and_time_name);

}  // namespace
}  // namespace flotsam
