// Verifies that the finite-volume engine finds the steady transcritical flow over a bump without
// a shock (Goutal & Maurel 1997; SWASHES 4.1.3.2, Delestre et al. 2013), at its defaults: 25 m
// frictionless channel, z_b = 0.2 - 0.05 (x - 10)^2 on 8 < x < 12, q = 1.53 m^2/s in, the water
// level 0.66 m held downstream while the outflow is subcritical (SWASHES' condition): the flow
// turns supercritical past the bump and leaves freely, the `elevation` condition imposing
// nothing on a supercritical outflow (fv_boundary.cpp). The exact solution: the flow is critical
// at the bump's top, which fixes the energy E = z_top + 3/2 h_c, h_c = (q^2 / g)^(1/3); upstream
// of the top the depth is the subcritical root of h + q^2 / (2 g h^2) = E - z_b, downstream the
// supercritical one. From water at rest at 0.66 m, 200 s on 200 x 2 rectangles (steady: H
// changes less than 1e-8 m over the last 10 s):
//   - the outflow supercritical (Froude > 1);
//   - the depth within 1 % of the exact one in the mean (L1 of h over the channel, relative to
//     the exact L1 norm) and at every cell, and upstream of the bump (x < 7 m);
//   - the outflow equals the inflow to 1e-6 relative.
// (A `free` end instead, from the same rest state, gives the flow no level to fall to: it stays
// subcritical over the bump at 1.133 m, a steady state as valid for a transmissive end; docs/
// validation.md.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support/bump_channel.hpp"

namespace flotsam {
namespace {

using Channel = test::BumpChannel;
constexpr double g = 9.81, q = 1.53, h_start = 0.66;                // SI
constexpr double length = Channel::length, z_top = Channel::z_top;  // [m]

const double h_c = std::cbrt(q * q / g);  // [m]
const double E = z_top + 1.5 * h_c;       // [m]

// The root of h + q^2 / (2 g h^2) = E - z_b(x) on the side of the critical depth: upstream of
// the top the subcritical one, downstream the supercritical one (bisection: the specific energy
// is monotone on each side of h_c).
double exact_depth(double x) {
  const bool upstream = x < 10.0;
  double lo = upstream ? h_c : 1e-4, hi = upstream ? 10.0 : h_c;
  for (int k = 0; k < 200; ++k) {
    const double h = 0.5 * (lo + hi);
    const double excess =
        h + q * q / (2.0 * g * h * h) + Channel::bed(x) - E;  // > 0: too much energy
    // Subcritical side: energy grows with h; supercritical side: it falls with h.
    ((excess > 0.0) == upstream ? hi : lo) = h;
  }
  return 0.5 * (lo + hi);
}

TEST(FvTranscriticalBump, DepthMatchesTheExactSolutionWithAFreeOutflow) {
  const test::Stopwatch clock;
  const Mesh mesh = Channel::mesh();
  const Case c = Channel::flow_case(q, h_start);
  FvEngine engine(mesh, c);
  engine.initialize();
  const FiniteVolumeSolver& solver = engine.solver();
  double change = 1.0;  // [m] largest change of H over the last 10 s
  while (engine.time() < 200.0) change = test::depth_change_over(engine, 10.0, 1.0);
  EXPECT_LE(change, 1e-8);  // steady

  const CellMesh& cells = solver.cells();
  const auto& H = solver.state().h;
  double error = 0.0, norm = 0.0, upstream_error = 0.0, worst = 0.0, x_worst = 0.0;
  for (int i = 0; i < cells.cell_count; ++i) {
    const double x = cells.centroid[i].x(), exact = exact_depth(x);
    const double e = std::abs(H[i] - exact);
    error += cells.area[i] * e;
    norm += cells.area[i] * exact;
    if (x < 7.0) upstream_error = std::max(upstream_error, e / exact);
    if (e / exact > worst) worst = e / exact, x_worst = x;
  }
  double outflow_froude = 0.0;  // [-] of the last cells
  for (int i = 0; i < cells.cell_count; ++i)
    if (cells.centroid[i].x() > length - 0.1)
      outflow_froude = std::max(outflow_froude, solver.state().hu[i] / H[i] / std::sqrt(g * H[i]));
  const auto& rate = engine.water_balance().group_rate;
  const double Q_in = -rate[mesh.find_group("left")], Q_out = rate[mesh.find_group("right")];
  std::printf(
      "transcritical bump without shock, %d cells, at t = %g s: L1(h) %.3f %%, upstream "
      "depth error %.3f %% (exact %.5f m), largest %.2f %% at x = %.2f m, Q_out / Q_in - 1 = "
      "%.1e, outflow Froude %.2f, change over the last 10 s %.1e m, %.1f s\n",
      cells.cell_count, engine.time(), 100 * error / norm, 100 * upstream_error, exact_depth(0.0),
      100 * worst, x_worst, Q_out / Q_in - 1.0, outflow_froude, change, clock.seconds());
  EXPECT_GT(outflow_froude, 1.0);  // supercritical: the outflow's level no longer imposed
  EXPECT_LE(error / norm, 0.01);
  EXPECT_LE(worst, 0.01);
  EXPECT_LE(upstream_error, 0.01);
  EXPECT_LE(std::abs(Q_out / Q_in - 1.0), 1e-6);
}

}  // namespace
}  // namespace flotsam
