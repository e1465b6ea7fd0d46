// Verifies that wind over a closed basin sets the water surface up with the slope
// d eta/dx = tau_w / (rho g H), tau_w = rho_air C_w |W| W (spec 1.1; steady balance of (M-1a)
// with u = 0), within 2% (issue 3 item 5), reached by time stepping at a gravity-wave Courant
// number of about 70 (both steps, flow.scheme); the volume is conserved to 1e-9.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/flow_schemes.hpp"
#include "core/constants.hpp"
#include "flow/fem/shallow_water_solver.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

class WindSetup : public testing::TestWithParam<FlowScheme> {};

TEST_P(WindSetup, SurfaceSlopeBalancesWindStress) {
  const double L = 1000.0, H0 = 5.0, W = 10.0;  // [m], [m], [m/s]
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, L, 100.0, 20, 2, true});
  Case c;
  c.flow.initial_eta_start = c.flow.initial_eta_end = H0;
  c.flow.scheme = GetParam();
  c.flow.wind = Vec2(W, 0.0);
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = 0.03;
  // Time stepping to the steady state (a closed basin's steady problem fixes its mean level only
  // through the time term): backward Euler at a Courant number of about 70 damps the seiches.
  c.time.theta = 1.0;
  ShallowWaterSolver solver(mesh, c);
  solver.initialize();
  for (int n = 0; n < 40; ++n) solver.step(500.0);
  // Slope of the least-squares line through eta(x), against tau_w/(rho g H) at the mean depth.
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const int n = mesh.vertex_count;
  for (int j = 0; j < n; ++j) {
    const double x = mesh.nodes[j].x(), e = solver.eta()[j];
    sx += x, sy += e, sxx += x * x, sxy += x * e;
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double expected = air_density * wind_drag_coefficient * W * W / (1000.0 * 9.81 * H0);
  EXPECT_NEAR(slope / expected, 1.0, 0.02);
  EXPECT_LE(std::abs(solver.water_balance().relative_error()), 1e-9);
  std::printf("wind: slope %.6e expected %.6e (ratio %.5f)\n", slope, expected, slope / expected);
}

INSTANTIATE_TEST_SUITE_P(FlowSchemes, WindSetup, test::both_flow_schemes, test::flow_scheme_name);

}  // namespace
}  // namespace flotsam
