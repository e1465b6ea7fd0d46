// Verifies that the water volume balances to round-off under a time-varying inflow (spec 6.2,
// issue 3 item 5: "mass balance below 1e-9 relative"): a 500 m channel fed by a hydrograph
// (discharge table rising from 0 to 40 m^3/s and falling back to 10 m^3/s) with the level held
// downstream; after 60 steps at a gravity-wave Courant number of about 4,
// |V(t) - V(0) + outflow - lag| / V(0) <= 1e-9 (lag: BDF2's, water_balance.hpp; zero for the
// theta-scheme); and the volume that entered is dt Q(t^{n+1}) per step (a discharge boundary
// carries Q(t^{n+1}) at t^{n+1} with either time scheme: boundary_flux_weight) within
// 1e-6 relative (the inflow velocities are set from the depth of the last Newton iterate, so the
// imposed flux is exact to the Newton tolerance 1e-6). Both time schemes, with either step.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/straight_channel.hpp"
#include "../support/time_schemes.hpp"
#include "flow/fem/shallow_water_solver.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

class HydrographMassBalance : public testing::TestWithParam<test::StepAndTime> {};

TEST_P(HydrographMassBalance, VolumeBalancesToRoundOff) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 500.0, 40.0, 25, 4, true});
  const TimeSeries Q({{0.0, 0.0}, {200.0, 40.0}, {400.0, 10.0}});  // [s], [m^3/s]
  Case c = test::straight_channel_case("hydrograph", Q, 2.0);      // [m] over a flat bed
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = 0.03;  // [s m^-1/3]
  c.flow.scheme = GetParam().flow;
  c.time.scheme = GetParam().time;
  ShallowWaterSolver solver(mesh, c);
  solver.initialize();
  const double dt = 10.0;  // [s] Courant sqrt(g H) dt / h = 4.4 * 10 / 10 ~ 4.4
  double inflow = 0.0;     // [m^3] sum of dt Q(t^{n+1})
  for (int n = 0; n < 60; ++n) {
    solver.step(dt);
    inflow += dt * Q(solver.time());
  }
  const WaterBalance& balance = solver.water_balance();
  EXPECT_LE(std::abs(balance.relative_error()), 1e-9);
  const double entered = -balance.group_outflow[mesh.find_group("left")];  // [m^3]
  EXPECT_NEAR(entered / inflow, 1.0, 1e-6);
  std::printf("hydrograph: balance %.2e, inflow %.6e m^3 (imposed %.6e m^3), lag %.3g m^3\n",
              balance.relative_error(), entered, inflow, balance.lag);
}

INSTANTIATE_TEST_SUITE_P(Schemes, HydrographMassBalance, test::all_steps_and_times,
                         test::step_and_time_name);

}  // namespace
}  // namespace flotsam
