// Verifies that the finite-volume engine breaks a dam onto a dry bed as Ritter's exact solution
// says (Ritter 1892; SWASHES 4.1.2, Delestre et al. 2013): h0 = 1 m behind a dam at x0 = 10 m of
// a frictionless 20 m channel, dry in front, at t = 1 s (the waves still inside), on three nested
// meshes:
//   - the L1 errors of H and Hu fall at an observed order above 0.5 (about 1 is expected, the
//     solution having kinks at both ends of the rarefaction; 0.5 is a conservative bound);
//   - the wet front, the furthest cell with H > h_f, lies within two cell widths of where the
//     exact solution has h = h_f, x0 + (2 c0 - 3 sqrt(g h_f)) t, c0 = sqrt(g h0), for
//     h_f = 1e-2 m (the exact front x0 + 2 c0 t itself has h = 0, which no threshold sees).
//     At h_f = 1e-3 m, the engine's dry depth, below which cells are first order by design
//     (reconstruction.hpp), the front lags 4 to 6 cells (0.83, 0.60, 0.20 m on the three
//     meshes; a plain 1D first-order HLL scheme lags 0.7 m at any cell width from 0.2 to
//     0.025 m): there the test asks only that the lag shrinks as the cells do;
//   - the water balance closes to 1e-12 relative and no depth goes negative.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support/fv_cases.hpp"

namespace flotsam {
namespace {

using test::DamBreakChannel;

constexpr double g = 9.81, h0 = 1.0, t_end = 1.0;  // [m s^-2], [m], [s]
const double c0 = std::sqrt(g * h0);               // [m/s]

// Ritter's solution at x [m], time t [s]: depth [m] and unit discharge [m^2/s].
struct Ritter {
  double h, hu;
};
Ritter ritter(double x, double t) {
  const double xi = (x - DamBreakChannel::x_dam) / t;  // [m/s]
  if (xi <= -c0) return {h0, 0.0};
  if (xi >= 2.0 * c0) return {0.0, 0.0};
  const double h = (2.0 * c0 - xi) * (2.0 * c0 - xi) / (9.0 * g);
  return {h, h * 2.0 / 3.0 * (xi + c0)};
}

// Where Ritter's depth falls to h_f [m] at t_end.
double exact_front(double h_f) {
  return DamBreakChannel::x_dam + (2.0 * c0 - 3.0 * std::sqrt(g * h_f)) * t_end;
}

struct Measured {
  double error_h, error_hu;  // [m], [m^2/s] L1 per unit area
  double front_1e2;          // [m] furthest cell with H > 1e-2 m
  double front_1e3;          // [m] furthest cell with H > 1e-3 m
  double balance;            // [-] relative water balance error
  double cell_width;         // [m]
  int cells;
  double seconds;
};

Measured break_dam(int refinement) {
  const test::Stopwatch clock;
  const Mesh mesh = test::dam_break_mesh(refinement);
  const Case c = test::dam_break_case(h0, 0.0);
  FvEngine engine(mesh, c);
  engine.initialize();
  test::run_to(engine, t_end, 0.05);
  const CellMesh& cells = engine.solver().cells();
  const ConservedState& U = engine.solver().state();
  Measured m{};
  m.error_h = test::l1_error(cells, U.h, [](const Vec2& p) { return ritter(p.x(), t_end).h; });
  m.error_hu = test::l1_error(cells, U.hu, [](const Vec2& p) { return ritter(p.x(), t_end).hu; });
  m.front_1e2 = m.front_1e3 = -1.0;
  for (int i = 0; i < cells.cell_count; ++i) {
    if (U.h[i] > 1e-2) m.front_1e2 = std::max(m.front_1e2, cells.centroid[i].x());
    if (U.h[i] > 1e-3) m.front_1e3 = std::max(m.front_1e3, cells.centroid[i].x());
  }
  m.balance = engine.water_balance().relative_error();
  m.cell_width = test::cell_width(cells);
  m.cells = cells.cell_count;
  m.seconds = clock.seconds();
  return m;
}

TEST(FvDamBreakDryBed, FollowsRitterOnThreeNestedMeshes) {
  Measured m[3];
  for (int k = 0; k < 3; ++k) {
    m[k] = break_dam(k);
    const double dx = m[k].cell_width;
    std::printf(
        "Ritter, %d x %d rectangles, %d cells (cell width %.3f m): L1(H) %.3e m, L1(Hu) %.3e "
        "m^2/s, "
        "balance %.1e, %.2f s\n"
        "  front at H > 1e-2 m: %.3f m (exact %.3f m, %+.2f cells); at H > 1e-3 m: %.3f m "
        "(exact %.3f m, %+.2f cells)\n",
        DamBreakChannel::nx(k), DamBreakChannel::ny(k), m[k].cells, dx, m[k].error_h, m[k].error_hu,
        m[k].balance, m[k].seconds, m[k].front_1e2, exact_front(1e-2),
        (m[k].front_1e2 - exact_front(1e-2)) / dx, m[k].front_1e3, exact_front(1e-3),
        (m[k].front_1e3 - exact_front(1e-3)) / dx);
    EXPECT_LE(std::abs(m[k].front_1e2 - exact_front(1e-2)), 2.0 * dx) << "mesh " << k;
    EXPECT_LE(std::abs(m[k].balance), 1e-12) << "mesh " << k;
  }
  for (int k = 1; k < 3; ++k) {
    const double order_h = test::observed_order(m[k - 1].error_h, m[k].error_h);
    const double order_hu = test::observed_order(m[k - 1].error_hu, m[k].error_hu);
    std::printf("Ritter, meshes %d -> %d: observed order %.2f in H, %.2f in Hu\n", k - 1, k,
                order_h, order_hu);
    EXPECT_GT(order_h, 0.5);
    EXPECT_GT(order_hu, 0.5);
    EXPECT_LT(std::abs(m[k].front_1e3 - exact_front(1e-3)),
              std::abs(m[k - 1].front_1e3 - exact_front(1e-3)));
  }
}

}  // namespace
}  // namespace flotsam
