// Verifies that a jam at a bridge modelled as an accumulation (bodies.jams.vertical_extent:
// accumulation, docs/model.md "Vertical extent of a jam") reaches the thickness (M-J1), that its
// bodies act on the water over it, and that the water feels it with the momentum exchanged
// exactly (finite volumes, two-way). The channel of jam_at_bridge_raises_water_by_momentum.cpp
// (300 m x 20 m, frictionless, 30 m^3/s at 2 m depth) with a deck across it at x = 150 m (soffit
// 2.1 m, 0.1 m above the water; 2 m wide) and four free logs 9.9 m long and 0.6 m thick
// (800 kg/m^3: they draw 0.448 m and stand 0.15 m above the water), released across the flow
// upstream: they drift against the deck's face and stay there, in jams at the bridge.
// Checked, for the mean over the last 600 s of 1,200 s (steps of 5 s):
// - every body of a jam at the bridge acts over (M-J1)'s T for its jam's wood and covered width
//   (P = 0.5; 1.063 m), more than twice its draft (0.448 m); with `layer`, over its draft;
// - the reach's momentum balance (Chow 1959, ch. 3) between x = 120 and 180 m, as
//   jam_at_bridge_raises_water_by_momentum.cpp checks it (the engine's fluxes through the
//   sections, less the change of the reach's momentum over the window), equals the force the
//   logs exchange with the water (what the flow's implicit drag took, BodySet::water_force)
//   within 2 % (measured +0.01 %: the water under the deck flows free, the deck takes no force),
//   and the rise 20 m upstream is within 5 % of the rise the balance predicts by a 1D reading
//   (measured +0.34 %);
// - the accumulation exchanges more than 1.8 times the force of the same logs as a layer
//   (measured 2.21; 2.36 is the ratio of the heights at equal velocity, and the water slows
//   under the thicker jam), and each more than 0.8 of the drag (M-6) the jammed bodies would take
//   at rest in the flow at the end (measured 0.87 and 0.90; the reference is one sample at each
//   body's centre at the end, the exchange a 600 s mean over its footprint's cells). A body held
//   against the deck stays against it (docs/model.md "Pose update from the interval's start").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "../support/bridge_across.hpp"
#include "../support/reach_momentum.hpp"
#include "../support/straight_channel.hpp"
#include "core/constants.hpp"
#include "coupling/jam_extent.hpp"
#include "coupling/simulation.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

constexpr double length = 300.0, width = 20.0, H0 = 2.0, Q = 30.0;  // [m], [m], [m], [m^3/s]
constexpr double end_time = 1200.0, averaging_time = 600.0;         // [s]
constexpr double rho = water_density_default;                       // [kg m^-3]
constexpr double porosity = 0.5;                                    // [-]

Case channel_with_logs(JamExtent extent) {
  Case c = test::straight_channel_case("accumulation", Q, H0);
  c.flow.engine = FlowEngineKind::fv;
  c.flow.viscosity = 1e-6;
  c.flow.initial_u = Expression("0.75", "test: flow.initial.u");  // Q / (W H0): steady from t = 0
  c.time = {.end = end_time, .step = 5.0, .mode = CouplingMode::two_way};
  c.output.backwater = true;
  c.bodies.physics.drag_law = DragLaw::constant;
  c.bodies.physics.drag_coefficient = 1.2;
  c.bodies.contact.restitution = 0.0;  // wood on wood and on concrete
  c.bodies.jams = {.vertical_extent = extent, .porosity = porosity};
  test::add_logs_across(c, {144.0, 146.0}, {5.0, 15.0});
  c.bridges = {test::bridge_across("bridge", 150.0, width, test::plain_deck(2.1, 2.9, 2.0), 20.0)};
  return c;
}

struct Means {
  double balance = 0.0, force = 0.0, rise = 0.0, h2 = 0.0;  // [N], [N], [m], [m]
  double thickness_error = 0.0;  // largest |d_w - T| over the bodies of jams at the bridge [m]
  double thickness = 0.0;        // smallest T of those jams [m]
  int jammed = 0;                // bodies in jams at the bridge at the end
  double draft = 0.0;            // [m] of the logs (all alike)
  double held_drag = 0.0;  // [N] (M-6) on the bodies at the end were they at rest, for the record
};

Means run(JamExtent extent) {
  Simulation s(
      channel_with_logs(extent),
      make_rectangle_mesh({.length = length, .width = width, .nx = 100, .ny = 14}),
      {.output_directory = {}, .overwrite = false, .write_output = false, .progress = false});
  s.initialize();
  test::ReachBalance reach(s.flow(), 120.0, 180.0);
  EXPECT_NEAR(reach.upstream_width(), width, 1e-9);
  EXPECT_NEAR(reach.downstream_width(), width, 1e-9);
  Means m;
  int n = 0;
  while (!s.done()) {
    s.step();
    if (std::abs(s.time() - (end_time - averaging_time)) < 1e-9) reach.start(s.flow());
    if (s.time() <= end_time - averaging_time + 1e-9) continue;
    reach.sample(s.flow());
    for (int i = 0; i < s.bodies().size(); ++i) m.force += s.bodies().water_force[i].x();
    m.rise += s.backwater_rise().at(0);
    ++n;
  }
  m.force /= n, m.rise /= n;
  m.balance = reach.balance(s.flow(), averaging_time);
  m.h2 = reach.downstream_depth();
  const BodySet& bodies = s.bodies();
  m.draft = bodies.draft[0];
  const JamStatistics jams = s.jam_statistics();
  m.thickness = std::numeric_limits<double>::infinity();
  for (const Jam& jam : jams.jams) {
    if (jam.bridge != 0) continue;
    double wood = 0.0;  // V_s [m^3]
    for (const int i : jam.bodies) wood += bodies.submerged_volume(i, bodies.height[i]);
    const double T = accumulation_thickness(wood, jam.gap_blockage.at(0) * width, porosity);
    m.thickness = std::min(m.thickness, T);
    for (const int i : jam.bodies) {
      const double expected = extent == JamExtent::accumulation ? T : bodies.draft[i];
      m.thickness_error = std::max(m.thickness_error, std::abs(bodies.wetted_height[i] - expected));
      ++m.jammed;
      int hint = -1;
      const FlowSample f = s.flow().field().sample(bodies.position[i], s.time(), hint);
      m.held_drag += 0.5 * rho * 1.2 * std::min(bodies.wetted_height[i], f.H) * bodies.length[i] *
                     std::abs(f.u.x()) * f.u.x();
    }
  }
  return m;
}

TEST(JamAccumulation, ActsOverItsThicknessAndTheWaterFeelsItWithMomentumExchangedExactly) {
  const Means acc = run(JamExtent::accumulation);
  const Means layer = run(JamExtent::layer);
  const double q = Q / width;  // [m^2/s]
  const double predicted = test::depth_upstream(q, acc.h2, acc.force / (rho * width)) -
                           test::depth_upstream(q, acc.h2, 0.0);
  const double draft = acc.draft;  // [m] of the logs (spec 2)
  std::printf(
      "accumulation: %d bodies jammed, T >= %.3f m (draft %.3f m); momentum: reach %.1f N, "
      "exchanged %.1f N (%+.2f %%); rise %.4f m, by the balance %.4f m (%+.2f %%); "
      "layer: exchanged %.1f N, ratio %.3f; exchanged over held drag: %.3f (accumulation), "
      "%.3f (layer)\n",
      acc.jammed, acc.thickness, draft, acc.balance, acc.force, 100 * (acc.balance / acc.force - 1),
      acc.rise, predicted, 100 * (acc.rise / predicted - 1), layer.force, acc.force / layer.force,
      acc.force / acc.held_drag, layer.force / layer.held_drag);
  EXPECT_EQ(acc.jammed, 4);
  EXPECT_EQ(layer.jammed, 4);
  EXPECT_LT(acc.thickness_error, 1e-12);
  EXPECT_LT(layer.thickness_error, 1e-12);
  EXPECT_GT(acc.thickness, 2.0 * draft);
  EXPECT_NEAR(acc.balance, acc.force, 0.02 * acc.force);
  EXPECT_NEAR(acc.rise, predicted, 0.05 * predicted);
  EXPECT_GT(acc.force, 1.8 * layer.force);
  EXPECT_GT(acc.force, 0.8 * acc.held_drag);
  EXPECT_GT(layer.force, 0.8 * layer.held_drag);
}

}  // namespace
}  // namespace flotsam
