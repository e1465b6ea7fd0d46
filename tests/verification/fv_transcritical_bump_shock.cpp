// ctest-label: slow
// Verifies that the finite-volume engine finds the steady transcritical flow over a bump with a
// hydraulic jump (Goutal & Maurel 1997; SWASHES 4.1.3.3, Delestre et al. 2013): 25 m
// frictionless channel, z_b = 0.2 - 0.05 (x - 10)^2 on 8 < x < 12, q = 0.18 m^2/s in, h = 0.33 m
// held downstream. The exact solution: critical flow at the bump's top fixes the energy
// upstream, so the depth upstream of the bump solves h + q^2 / (2 g h^2) = z_top + 3/2 h_c,
// h_c = (q^2 / g)^(1/3); past the top the flow is supercritical on that energy, downstream it is
// subcritical on the energy of h = 0.33 m, and the jump stands where the two conjugate depths
// h_1, h_2 carry the same momentum flux q^2 / h + g h^2 / 2: x_s = 11.6656 m. Marched to steady
// state (H changing less than 1e-8 m in 10 s) on 200 x 2 rectangles:
//   - the depth upstream of the bump (x < 7 m) is within 0.5% of the exact one;
//   - the jump, the first cell past x = 10.5 m with H above (h_1 + h_2) / 2, lies within two
//     cell widths of x_s;
//   - the outflow equals the inflow to 1e-6 relative.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support/bump_channel.hpp"

namespace flotsam {
namespace {

using Channel = test::BumpChannel;
constexpr double g = 9.81, q = 0.18, h_out = 0.33;                  // SI
constexpr double length = Channel::length, z_top = Channel::z_top;  // [m]

// The root of h + q^2 / (2 g h^2) = E - z (specific energy), by Newton from h_start: from above
// the subcritical root, from below the supercritical one.
double bernoulli_depth(double E, double z, double h_start) {
  double h = h_start;
  for (int k = 0; k < 100; ++k) {
    const double f = h + q * q / (2.0 * g * h * h) + z - E;
    const double df = 1.0 - q * q / (g * h * h * h);
    h -= f / df;
  }
  return h;
}

const double h_c = std::cbrt(q * q / g);                          // [m]
const double E_up = z_top + 1.5 * h_c;                            // [m]
const double E_down = h_out + q * q / (2.0 * g * h_out * h_out);  // [m]
double supercritical(double x) {
  return bernoulli_depth(E_up, Channel::bed(x), 1e-3);
}  // [m]
double subcritical(double x) {
  return bernoulli_depth(E_down, Channel::bed(x), 1.0);
}  // [m]
double momentum_flux(double h) {
  return q * q / h + 0.5 * g * h * h;
}  // [m^3/s^2]

// Where the conjugate depths carry the same momentum flux, by bisection on (10.5, 12) m: up to
// x_s the supercritical flow carries more (the jump is pushed downstream), past it less.
double jump_position() {
  double lo = 10.5, hi = 12.0;
  for (int k = 0; k < 60; ++k) {
    const double x = 0.5 * (lo + hi);
    (momentum_flux(supercritical(x)) > momentum_flux(subcritical(x)) ? lo : hi) = x;
  }
  return 0.5 * (lo + hi);
}

TEST(FvTranscriticalBumpShock, UpstreamDepthAndJumpMatchTheExactSolution) {
  const test::Stopwatch clock;
  const double h_up = bernoulli_depth(E_up, 0.0, 1.0), x_s = jump_position();
  const double h_mean = 0.5 * (supercritical(x_s) + subcritical(x_s));
  ASSERT_NEAR(x_s, 11.6656, 1e-4);  // SWASHES' value

  const Mesh mesh = Channel::mesh();
  const Case c = Channel::flow_case(q, h_out);
  FvEngine engine(mesh, c);
  engine.initialize();
  const FiniteVolumeSolver& solver = engine.solver();
  double change = 1.0;  // [m] largest change of H over the last 10 s
  while (change > 1e-8 && engine.time() < 2000.0)
    change = test::depth_change_over(engine, 10.0, 1.0);
  ASSERT_LE(change, 1e-8) << "no steady state by t = " << engine.time() << " s";

  const CellMesh& cells = solver.cells();
  const auto& H = solver.state().h;
  double upstream_error = 0.0, upstream_depth = 0.0, x_jump = length;  // [-], [m], [m]
  for (int i = 0; i < cells.cell_count; ++i) {
    const double x = cells.centroid[i].x();
    if (x < 7.0 && std::abs(H[i] - h_up) / h_up >= upstream_error)
      upstream_error = std::abs(H[i] - h_up) / h_up, upstream_depth = H[i];
    if (x > 10.5 && H[i] > h_mean) x_jump = std::min(x_jump, x);
  }
  const double dx = test::cell_width(cells);
  const auto& rate = engine.water_balance().group_rate;
  const double Q_in = -rate[mesh.find_group("left")], Q_out = rate[mesh.find_group("right")];
  std::printf(
      "transcritical bump, 200 x 2 rectangles, %d cells (cell width %.3f m), steady at t = %g s: "
      "upstream depth %.5f m at its worst (exact %.5f m, error %.2e), jump at %.3f m (exact %.4f "
      "m, "
      "%+.2f cells), Q_out / Q_in - 1 = %.1e, %.1f s\n",
      cells.cell_count, dx, engine.time(), upstream_depth, h_up, upstream_error, x_jump, x_s,
      (x_jump - x_s) / dx, Q_out / Q_in - 1.0, clock.seconds());
  EXPECT_LE(upstream_error, 0.005);
  EXPECT_LE(std::abs(x_jump - x_s), 2.0 * dx);
  EXPECT_LE(std::abs(Q_out / Q_in - 1.0), 1e-6);
}

}  // namespace
}  // namespace flotsam
