// Verifies the piers' form drag (docs/model.md "Pier drag", (M-25)), finite volumes: a
// frictionless, inviscid channel 160 m x 20 m carrying 60 m^3/s at 2 m held downstream (1.5 m/s,
// Froude 0.34), three circular piers of 1.5 m across it at x = 80 m (22.5 % of the width;
// mesh.channel, 1.5 m cells refined to 0.3 m on the piers, three time levels), means over the
// last 400 s of 600 s (the frictionless channel keeps the seiches of its start). Checked:
// - momentum: the reach between x1 = 50 m and x2 = 110 m (staircases of edges;
//   tests/support/reach_momentum.hpp) gives up to what stands in it exactly what the piers take,
//   their drag (the impulse the engine counts, PierDrag) plus the pressure on their walls (the
//   scheme's flux into the piers' boundary edges): within 2 % of the drag (measured -0.02 %);
// - the drag against (M-25) at the approach flow, 3 x 1/2 rho C_d b h1 U1^2 with h1 and
//   U1 = Q / (W h1) at x1: within 15 % (the ring's mean flow stands for the approach flow;
//   measured +5.7 %);
// - the backwater h1 - h2 against the two published low-flow relations HEC-RAS offers at piers:
//   the momentum balance with the piers' drag at C_d = 1.2 (the tabulated coefficient of a
//   circular pier; Hydraulic Reference Manual, "Low flow computations") and Yarnell's (1934,
//   USDA Technical Bulletin 442) dH = 2 K (K + 10 w - 0.6)(a + 15 a^4) V^2 / 2g, K = 0.9 for
//   round-nosed piers, a the piers' share of the open width, V and w = V^2 / (2 g h2) the
//   downstream velocity and velocity head over the depth. The two differ by a factor of two
//   here; the backwater must lie between 0.9 times the first and 1.1 times the second
//   (measured 62 mm, between 34 and 72 mm).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "../support/reach_momentum.hpp"
#include "../support/straight_channel.hpp"
#include "core/constants.hpp"
#include "coupling/simulation.hpp"
#include "mesh/mesh_generator.hpp"

namespace flotsam {
namespace {

constexpr double length = 160.0, width = 20.0, H0 = 2.0, Q = 60.0;  // [m], [m], [m], [m^3/s]
constexpr double pier_x = 80.0, radius = 0.75;                      // [m]
constexpr double x1 = 50.0, x2 = 110.0;                             // [m] the reach
constexpr double end_time = 600.0, averaging_time = 400.0;          // [s]
constexpr double rho = water_density_default;                       // [kg m^-3]
constexpr double drag_coefficient = 1.2;                            // C_d [-], circular piers

Case channel_with_piers() {
  Case c = test::straight_channel_case("piers", Q, H0);
  c.mesh.kind = MeshSource::Kind::channel;
  c.mesh.element_order = 1;
  c.mesh.channel = {
      .length = length,
      .width = width,
      .piers = {{{pier_x, 5.0}, radius}, {{pier_x, 10.0}, radius}, {{pier_x, 15.0}, radius}},
      .mesh_size = 1.5,
      .pier_mesh_size = 0.3,
      .refine_distance = 4.0};
  c.flow.boundaries[0].group = "inflow";
  c.flow.boundaries[1].group = "outflow";
  c.flow.boundaries[2].group = "bank_right";
  c.flow.boundaries[3].group = "bank_left";
  for (const char* pier : {"pier_1", "pier_2", "pier_3"})
    c.flow.boundaries.push_back(
        {BoundaryCondition::Kind::wall, pier, TimeSeries(0.0), TimeSeries(0.0)});
  c.flow.engine = FlowEngineKind::fv;
  c.flow.fv.pier_drag = drag_coefficient;
  c.flow.fv.time_levels = 3;  // the cells at the piers take the smallest steps
  c.flow.viscosity = 1e-6;
  c.time = {.end = end_time, .step = 5.0, .mode = CouplingMode::two_way};
  return c;
}

/// rho * the x-momentum flux out of the water through the piers' walls [N]: the pressure force
/// the resolved piers take.
double wall_force(const FiniteVolumeSolver& solver, const std::vector<int>& pier_edges) {
  std::vector<int> facing_down, facing_up;  // outward normal along +x or -x
  for (const int e : pier_edges)
    (solver.cells().normal[e].x() >= 0.0 ? facing_down : facing_up).push_back(e);
  return rho * (solver.section_flux(facing_down, Vec2(1.0, 0.0)).momentum.x() +
                solver.section_flux(facing_up, Vec2(-1.0, 0.0)).momentum.x());
}

TEST(PierDrag, RaisesTheWaterAsTheReachsMomentumAndThePublishedRelationsSay) {
  const Case c = channel_with_piers();
  Simulation s(
      c, generate_mesh(c.mesh),
      {.output_directory = {}, .overwrite = false, .write_output = false, .progress = false});
  s.initialize();
  const FiniteVolumeSolver& solver = dynamic_cast<const FvEngine&>(s.flow()).solver();
  const PierDrag& drag = solver.pier_drag();
  ASSERT_EQ(drag.piers.size(), 3u);
  std::vector<int> pier_edges;
  for (const int e : solver.cells().boundary_edges)
    if (s.flow().mesh().group_names[solver.cells().group[e]].starts_with("pier"))
      pier_edges.push_back(e);
  test::ReachBalance reach(s.flow(), x1, x2);
  const std::vector<int> upstream = test::edges_across_x(solver.cells(), x1);
  double impulse_start = 0.0, walls = 0.0, h1 = 0.0;
  int n = 0;
  while (!s.done()) {
    s.step();
    if (std::abs(s.time() - (end_time - averaging_time)) < 1e-9) {
      reach.start(s.flow());
      impulse_start = drag.total_impulse().x();
    }
    if (s.time() <= end_time - averaging_time + 1e-9) continue;
    reach.sample(s.flow());
    walls += wall_force(solver, pier_edges);
    double depth = 0.0;
    test::section_momentum(s.flow(), upstream, depth);
    h1 += depth;
    ++n;
  }
  walls /= n, h1 /= n;
  const double force = rho * (drag.total_impulse().x() - impulse_start) / averaging_time;  // [N]
  const double balance = reach.balance(s.flow(), averaging_time), h2 = reach.downstream_depth();
  const double b = drag.piers[0].width, U1 = Q / (width * h1), g = gravity;
  const double by_drag_law = 3 * 0.5 * rho * drag_coefficient * b * h1 * U1 * U1;  // (M-25)
  // HEC-RAS's momentum method: the depth upstream whose momentum function exceeds the
  // downstream one's by the piers' drag at the upstream velocity (solved by fixed point).
  const double q = Q / width;
  double h_momentum = h2;
  for (int k = 0; k < 50; ++k) {
    const double u = q / h_momentum;
    h_momentum =
        test::depth_upstream(q, h2, 3 * 0.5 * drag_coefficient * b * h_momentum * u * u / width);
  }
  const double V = q / h2, w = V * V / (2 * g * h2), a = 3 * b / (width - 3 * b), K = 0.9;
  const double yarnell = 2 * K * (K + 10 * w - 0.6) * (a + 15 * std::pow(a, 4)) * V * V / (2 * g);
  const double rise = h1 - h2;
  std::printf(
      "piers: drag %.1f N, walls %.1f N, reach %.1f N (%+.2f %% of the drag); drag by (M-25) "
      "at x1 %.1f N (%+.2f %%); backwater %.4f m, momentum with C_d 1.2 %.4f m, Yarnell %.4f m\n",
      force, walls, balance, 100 * (balance - force - walls) / force, by_drag_law,
      100 * (force / by_drag_law - 1), rise, h_momentum - h2, yarnell);
  EXPECT_NEAR(b, 2 * radius, 0.03 * 2 * radius);  // the circle's polygon, 0.3 m sides
  EXPECT_NEAR(balance, force + walls, 0.02 * force);
  EXPECT_NEAR(force, by_drag_law, 0.15 * by_drag_law);
  EXPECT_GT(rise, 0.9 * (h_momentum - h2));
  EXPECT_LT(rise, 1.1 * yarnell);
  EXPECT_LT(std::abs(s.flow().water_balance().relative_error()), 1e-12);
}

}  // namespace
}  // namespace flotsam
