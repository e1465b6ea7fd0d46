// Verifies that the finite-volume engine breaks a dam onto a wet bed as Stoker's exact solution
// says (tests/support/stoker.hpp): h_l = 1 m behind a dam at x0 = 10 m of a frictionless 20 m
// channel, h_r = 0.1 m in front, at t = 1 s (the waves still inside), on three nested meshes.
// Checked:
//   - the L1 errors of H and Hu fall at an observed order above 0.5 (about 1 is expected with a
//     shock; 0.5 is a conservative bound);
//   - the shock, the furthest cell with H above the mean of h_m and h_r, lies within two cell
//     widths of x0 + s t;
//   - the water balance closes to 1e-12 relative and no depth goes negative.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support/fv_cases.hpp"
#include "../support/stoker.hpp"

namespace flotsam {
namespace {

using test::DamBreakChannel;

constexpr double g = 9.81, h_l = 1.0, h_r = 0.1, t_end = 1.0;  // [m s^-2], [m], [m], [s]

const test::Stoker stoker(g, h_l, h_r);

// Stoker's solution at x [m], time t [s].
test::Stoker::State exact(double x, double t) {
  return stoker.at((x - DamBreakChannel::x_dam) / t);
}

struct Measured {
  double error_h, error_hu;  // [m], [m^2/s] L1 per unit area
  double shock;              // [m]
  double hv_max;             // [m^2/s] largest transverse discharge (exact: 0)
  double balance;            // [-] relative water balance error
  double cell_width;         // [m]
  int cells;
  double seconds;
};

Measured break_dam(int refinement) {
  const test::Stopwatch clock;
  const Mesh mesh = test::dam_break_mesh(refinement);
  const Case c = test::dam_break_case(h_l, h_r);
  FvEngine engine(mesh, c);
  engine.initialize();
  test::run_to(engine, t_end, 0.05);
  const CellMesh& cells = engine.solver().cells();
  const ConservedState& U = engine.solver().state();
  Measured m{};
  m.error_h = test::l1_error(cells, U.h, [](const Vec2& p) { return exact(p.x(), t_end).h; });
  m.error_hu = test::l1_error(cells, U.hu, [](const Vec2& p) { return exact(p.x(), t_end).hu; });
  m.shock = -1.0;
  const double h_mean = 0.5 * (stoker.h_m + h_r);
  for (int i = 0; i < cells.cell_count; ++i)
    if (U.h[i] > h_mean) m.shock = std::max(m.shock, cells.centroid[i].x());
  for (double hv : U.hv) m.hv_max = std::max(m.hv_max, std::abs(hv));
  m.balance = engine.water_balance().relative_error();
  m.cell_width = test::cell_width(cells);
  m.cells = cells.cell_count;
  m.seconds = clock.seconds();
  return m;
}

TEST(FvDamBreakWetBed, FollowsStokerOnThreeNestedMeshes) {
  const double exact_shock = DamBreakChannel::x_dam + stoker.s * t_end;
  std::printf("Stoker: h_m = %.6f m, u_m = %.6f m/s, shock speed %.6f m/s\n", stoker.h_m,
              stoker.u_m, stoker.s);
  Measured m[3];
  for (int k = 0; k < 3; ++k) {
    m[k] = break_dam(k);
    const double dx = m[k].cell_width;
    std::printf(
        "Stoker, %d x %d rectangles, %d cells (cell width %.3f m): L1(H) %.3e m, L1(Hu) %.3e "
        "m^2/s, shock "
        "%.3f m (exact %.3f m, %+.2f cells), max|Hv| %.1e m^2/s, balance %.1e, %.2f s\n",
        DamBreakChannel::nx(k), DamBreakChannel::ny(k), m[k].cells, dx, m[k].error_h, m[k].error_hu,
        m[k].shock, exact_shock, (m[k].shock - exact_shock) / dx, m[k].hv_max, m[k].balance,
        m[k].seconds);
    EXPECT_LE(std::abs(m[k].shock - exact_shock), 2.0 * dx) << "mesh " << k;
    EXPECT_LE(std::abs(m[k].balance), 1e-12) << "mesh " << k;
  }
  for (int k = 1; k < 3; ++k) {
    const double order_h = test::observed_order(m[k - 1].error_h, m[k].error_h);
    const double order_hu = test::observed_order(m[k - 1].error_hu, m[k].error_hu);
    std::printf("Stoker, meshes %d -> %d: observed order %.2f in H, %.2f in Hu\n", k - 1, k,
                order_h, order_hu);
    EXPECT_GT(order_h, 0.5);
    EXPECT_GT(order_hu, 0.5);
  }
}

}  // namespace
}  // namespace flotsam
