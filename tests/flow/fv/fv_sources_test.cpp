// Unit tests of the finite-volume engine's wind and Coriolis sources (M-10, spec 1.1): from a
// uniform state the fluxes of an inner cell cancel, so one sub-step of (M-13) is exactly the
// Runge-Kutta step of the source alone there:
//   wind:     hu = dt tau/rho, tau/rho = (rho_air / rho) C_w |W| W;
//   Coriolis: hv = -f dt hu_0, hu = hu_0 (1 - (f dt)^2 / 2), f = 2 Omega sin(phi)
// (Heun's step of the rotation d(hu, hv)/dt = f (hv, -hu)). Cells within three cells of a wall
// feel the walls within the two stages and are left out. Tolerance 1e-9 relative: the pressure
// fluxes (g h^2 / 2 ~ 20 m^3/s^2) cancel around a cell to about 1e-16 m^2/s, against changes of
// 1e-4 m^2/s.
#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "flow/fv/fv_solver.hpp"
#include "fv_test_cases.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

constexpr double side = 100.0;  // [m] the square basin
constexpr int cells_across = 10;

Mesh basin() {
  return make_rectangle_mesh({0.0, 0.0, side, side, cells_across, cells_across, true});
}

bool far_from_walls(const Vec2& p) {
  const double margin = 3.5 * side / cells_across;  // [m]
  return p.x() > margin && p.x() < side - margin && p.y() > margin && p.y() < side - margin;
}

TEST(FvSources, WindPushesTheWaterByItsStressOverOneSubStep) {
  Case c = test::closed_basin_case(2.0);
  c.flow.wind = Vec2(12.0, -5.0);  // [m/s]
  const Mesh mesh = basin();       // the solver keeps a reference to it
  FiniteVolumeSolver s(mesh, c);
  s.initialize();
  const double dt = 0.5 * s.courant_step();  // [s] one sub-step
  s.advance(dt);
  ASSERT_EQ(s.sub_steps().count, 1);
  const Vec2 stress = air_density / c.flow.water_density * wind_drag_coefficient *
                      c.flow.wind.norm() * c.flow.wind;  // [m^2/s^2]
  int checked = 0;
  for (int i = 0; i < s.cells().cell_count; ++i) {
    if (!far_from_walls(s.cells().centroid[i])) continue;
    EXPECT_NEAR(s.state().hu[i], dt * stress.x(), 1e-9 * dt * stress.norm()) << "cell " << i;
    EXPECT_NEAR(s.state().hv[i], dt * stress.y(), 1e-9 * dt * stress.norm()) << "cell " << i;
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

TEST(FvSources, CoriolisTurnsTheFlowAsHeunsStepOfTheRotation) {
  const double u0 = 0.8, h = 3.0, latitude = 45.0;  // [m/s], [m], [deg]
  Case c = test::closed_basin_case(h);
  c.flow.initial_u = Expression("0.8", "test: flow.initial.u");
  c.flow.coriolis = true;
  c.flow.latitude_deg = latitude;
  const Mesh mesh = basin();  // the solver keeps a reference to it
  FiniteVolumeSolver s(mesh, c);
  s.initialize();
  const double dt = 0.5 * s.courant_step();
  s.advance(dt);
  ASSERT_EQ(s.sub_steps().count, 1);
  const double f = 2.0 * earth_rotation_rate * std::sin(latitude * pi / 180.0);  // [1/s]
  const double hu0 = h * u0;
  int checked = 0;
  for (int i = 0; i < s.cells().cell_count; ++i) {
    if (!far_from_walls(s.cells().centroid[i])) continue;
    EXPECT_NEAR(s.state().hv[i], -f * dt * hu0, 1e-9 * f * dt * hu0) << "cell " << i;
    EXPECT_NEAR(s.state().hu[i], hu0 * (1.0 - 0.5 * f * f * dt * dt), 1e-12 * hu0);
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

}  // namespace
}  // namespace flotsam
