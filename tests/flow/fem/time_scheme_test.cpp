// The BDF2 time scheme's history (flow_time_stepping.cpp, ShallowWaterSolver::time_step) on a
// channel fed by a discharge ramp with the level held downstream (Manning, characteristics):
//  - a restart from a state and the state a step before it (what a checkpoint stores) goes on
//    bit for bit like the run that was never stopped (exact comparison);
//  - the first step, which has no history (u^{n-1} = u^n), is backward Euler with 2/3 of the
//    step: BDF2's first step of dt equals the theta-scheme's at theta = 1 over 2 dt / 3 (Eulerian
//    form, constant boundary values), to round-off (1e-12 m/s, 1e-12 m).
#include <gtest/gtest.h>

#include <cmath>

#include "../../support/straight_channel.hpp"
#include "flow/fem/shallow_water_solver.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

Case channel(const TimeSeries& discharge) {
  Case c = test::straight_channel_case("bdf2", discharge, 2.0);  // [m] over a flat bed
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = 0.03;  // [s m^-1/3]
  return c;
}

TEST(Bdf2, RestartFromAStateAndTheOneBeforeGoesOnBitForBit) {
  // Both steps: the segregated one also carries guesses from step to step (the surface's rate,
  // the predictor's increment), which a checkpoint must reset as a restart starts without them.
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 200.0, 40.0, 20, 6, true});
  for (FlowScheme scheme : {FlowScheme::coupled, FlowScheme::segregated}) {
    Case c = channel(TimeSeries({{0.0, 0.0}, {40.0, 30.0}}));
    c.time.scheme = TimeScheme::bdf2;
    c.flow.scheme = scheme;
    ShallowWaterSolver run(mesh, c);
    run.initialize();
    for (int n = 0; n < 3; ++n) run.step(5.0);
    const FlowState at = run.state(), before = run.previous_state();
    run.start_fresh_factorisation();  // as at a checkpoint
    for (int n = 0; n < 3; ++n) run.step(5.0);

    ShallowWaterSolver restarted(mesh, c);
    restarted.initialize();
    restarted.set_state(at, &before);
    for (int n = 0; n < 3; ++n) restarted.step(5.0);
    ASSERT_GT(std::abs(run.u()[0]), 0.0);  // the flow has moved
    EXPECT_EQ(restarted.eta(), run.eta()) << static_cast<int>(scheme);
    EXPECT_EQ(restarted.u(), run.u()) << static_cast<int>(scheme);
    EXPECT_EQ(restarted.v(), run.v()) << static_cast<int>(scheme);
  }
}

TEST(Bdf2, FirstStepIsBackwardEulerOverTwoThirdsOfTheStep) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 200.0, 40.0, 20, 6, true});
  Case bdf2 = channel(TimeSeries(30.0));
  bdf2.time.scheme = TimeScheme::bdf2;
  Case euler = bdf2;
  euler.time.scheme = TimeScheme::theta;
  euler.time.theta = 1.0;
  const double dt = 6.0;  // [s]
  FlowSolverOptions eulerian;
  eulerian.advection = Advection::supg;
  eulerian.max_iterations = 20;
  ShallowWaterSolver a(mesh, bdf2, eulerian), b(mesh, euler, eulerian);
  a.initialize();
  b.initialize();
  a.step(dt);
  b.step(2.0 * dt / 3.0);
  ASSERT_GT(std::abs(a.u()[0]), 0.1);  // the inflow has started
  for (int i = 0; i < mesh.node_count(); ++i) {
    EXPECT_NEAR(a.u()[i], b.u()[i], 1e-12) << "node " << i;
    EXPECT_NEAR(a.v()[i], b.v()[i], 1e-12) << "node " << i;
  }
  for (int j = 0; j < mesh.vertex_count; ++j) EXPECT_NEAR(a.eta()[j], b.eta()[j], 1e-12);
}

}  // namespace
}  // namespace flotsam
