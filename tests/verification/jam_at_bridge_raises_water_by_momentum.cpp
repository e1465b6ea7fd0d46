// Verifies that a fixed jam at a bridge raises the water upstream as the momentum balance of the
// reach predicts (finite volumes, two-way, docs/model.md "Jam statistics"): a frictionless,
// inviscid straight channel 300 m x 20 m (3 m x 1.4 m rectangles, two triangles each) carrying
// 30 m^3/s at 2 m depth, a bridge across it at x = 150 m, and a raft of wood anchored against
// it (a box 10 m across the flow, 2 m along it, drawing 1.2 m: half the width closed). Over the
// reach from x1 = 120 m to x2 = 180 m (lines of cell edges) the control-volume momentum balance
// (Chow 1959, ch. 3) reads, over the last 600 s of a 1,200 s run (the wake sheds eddies, and the
// frictionless channel keeps the seiches of its start from rest),
//   mean of M(x1) - M(x2) - (P(1200 s) - P(600 s)) / 600 s = mean of F,
// M(x) = rho * integral over the section of (h u^2 + g h^2 / 2) dy, the engine's own flux through
// the section's edges (tests/support/reach_momentum.hpp: whatever the cells' numbering), P the
// reach's momentum, F the force the raft exchanges with the water (what the flow's implicit drag
// took, BodySet::water_force, exact to round-off by FvFlowField's tests). Checked: the balance
// within 2 % of F (measured -0.64 %, F = 3,070 N; the frictionless channel keeps the seiches of
// its start, so the change of P over the window counts), and the rise the run reports for the
// bridge (its backwater section 20 m upstream, against the same flow without the raft,
// `output.backwater`) within 5 % of the rise the balance predicts there (measured +1.2 %): the
// depth h1 upstream that carries the momentum
// function of the section downstream plus F,
//   B (q^2 / h1 + g h1^2 / 2) = B (q^2 / h2 + g h2^2 / 2) + F / rho,
// against the depth the same solve gives without the raft (F = 0): a 1D reading of a 2D reach,
// hence the looser tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "../support/bridge_across.hpp"
#include "../support/reach_momentum.hpp"
#include "../support/straight_channel.hpp"
#include "core/constants.hpp"
#include "coupling/simulation.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

constexpr double length = 300.0, width = 20.0, H0 = 2.0, Q = 30.0;  // [m], [m], [m], [m^3/s]
constexpr double end_time = 1200.0, averaging_time = 600.0;         // [s]
constexpr double rho = water_density_default;                       // [kg m^-3]

Case channel_with_raft() {
  Case c = test::straight_channel_case("raft", Q, H0);
  c.flow.engine = FlowEngineKind::fv;
  c.flow.viscosity = 1e-6;
  c.time = {.end = end_time, .step = 5.0, .mode = CouplingMode::two_way};
  c.output.backwater = true;
  c.bodies.physics.drag_law = DragLaw::constant;
  c.bodies.physics.drag_coefficient = 1.2;
  BodySpec raft;
  raft.shape = Shape::box;
  raft.length = 10.0;
  raft.width = 2.0;
  raft.height = 2.0;
  raft.density = 600.0;
  raft.position = Vec2(148.0, 0.5 * width);
  raft.angle = pi / 2;
  raft.anchored = true;
  c.bodies.bodies = {raft};
  c.bridges = {test::bridge_across("bridge", 150.0, width, std::nullopt, 20.0)};
  return c;
}

TEST(JamAtBridge, RaisesTheWaterUpstreamAsTheReachsMomentumBalancePredicts) {
  Simulation s(
      channel_with_raft(),
      make_rectangle_mesh({.length = length, .width = width, .nx = 100, .ny = 14}),
      {.output_directory = {}, .overwrite = false, .write_output = false, .progress = false});
  s.initialize();
  test::ReachBalance reach(s.flow(), 120.0, 180.0);
  ASSERT_NEAR(reach.upstream_width(), width, 1e-9);
  ASSERT_NEAR(reach.downstream_width(), width, 1e-9);
  double force = 0.0, rise = 0.0;  // means over the averaging time
  int n = 0;
  while (!s.done()) {
    s.step();
    if (std::abs(s.time() - (end_time - averaging_time)) < 1e-9) reach.start(s.flow());
    if (s.time() <= end_time - averaging_time + 1e-9) continue;
    reach.sample(s.flow());
    force += s.bodies().water_force[0].x();
    rise += s.backwater_rise().at(0);
    ++n;
  }
  force /= n, rise /= n;
  const double balance = reach.balance(s.flow(), averaging_time), h2 = reach.downstream_depth();
  const double q = Q / width;  // [m^2/s]
  const double predicted =
      test::depth_upstream(q, h2, force / (rho * width)) - test::depth_upstream(q, h2, 0.0);  // [m]
  std::printf(
      "momentum: reach %.1f N, exchanged %.1f N (%+.2f %%); rise 20 m upstream %.4f m, "
      "by the balance %.4f m (%+.2f %%)\n",
      balance, force, 100 * (balance / force - 1), rise, predicted, 100 * (rise / predicted - 1));
  EXPECT_GT(force, 0.0);
  EXPECT_NEAR(balance, force, 0.02 * force);
  EXPECT_NEAR(rise, predicted, 0.05 * predicted);
}

}  // namespace
}  // namespace flotsam
