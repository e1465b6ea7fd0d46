// Energy in a closed basin: a frictionless, nearly inviscid square basin (200 m, 10 m deep, walls
// all round) holds a vortex that is not in balance with the flat surface, so it radiates waves
// that reflect from the walls. Nothing brings energy in: the total energy
//     E = integral of ( H |u|^2 / 2 + g (eta - H_0)^2 / 2 ) dA     [m^5 s^-2; times rho: J]
// can only fall, through the viscosity and the schemes' damping. At a small amplitude (0.05 m/s,
// Froude number 0.005, the equations close to linear) both time schemes must lose energy at
// every step: a rise at any step would be an unstable discretisation of gravity waves, walls or
// time. (At 0.5 m/s the characteristics scheme gains ~1.5 % per 100 s with either time scheme
// on this alternating-diagonal mesh, whatever dt and h, and loses energy on Gmsh's meshes:
// docs/validation.md "Closed basin, energy".)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "../support/flow_integral.hpp"
#include "../support/time_schemes.hpp"
#include "flow/fem/shallow_water_solver.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

constexpr double L = 200.0, H0 = 10.0;  // [m] basin side, still-water depth (flat bed at 0)

double energy(const ShallowWaterSolver& solver) {  // [m^5 s^-2]
  const double g = solver.flow_case().flow.gravity;
  return test::integrate_flow(solver, [&](const Vec2&, const Vec2& u, double eta, double z_b) {
    return 0.5 * (eta - z_b) * u.squaredNorm() + 0.5 * g * (eta - H0) * (eta - H0);
  });
}

// E(400 s) / E(0) and the largest relative rise of E in one step of dt [s].
struct EnergyHistory {
  double ratio, largest_rise;  // [-]
  double balance_error;        // [-] the water balance's relative error
};

EnergyHistory run_basin(Case c, double dt, double U = 0.05) {  // U: speed scale [m/s]
  const Mesh mesh = make_rectangle_mesh({.length = L, .width = L, .nx = 20, .ny = 20});
  c.flow.initial_eta_start = c.flow.initial_eta_end = H0;  // walls all round
  ShallowWaterSolver solver(mesh, c);
  solver.initialize();
  FlowState s = solver.state();
  const Vec2 centre(0.5 * L, 0.5 * L);
  const double R = 30.0;  // [m] vortex radius
  for (int i = 0; i < mesh.node_count(); ++i) {
    const Vec2 r = mesh.nodes[i] - centre;
    const double swirl = U / R * std::exp(-r.squaredNorm() / (R * R));  // [1/s]
    s.u[i] = -swirl * r.y();
    s.v[i] = swirl * r.x();
  }
  solver.set_state(s);
  const double E0 = energy(solver);
  double E = E0, largest_rise = -1.0;  // [-] relative change of E over one step
  for (int n = 0; n < static_cast<int>(std::lround(400.0 / dt)); ++n) {
    solver.step(dt);
    const double E_new = energy(solver);
    largest_rise = std::max(largest_rise, (E_new - E) / E);
    E = E_new;
  }
  return {E / E0, largest_rise, solver.water_balance().relative_error()};
}

class ClosedBasin : public testing::TestWithParam<TimeScheme> {};

TEST_P(ClosedBasin, EnergyFallsAtEveryStep) {
  Case c;
  c.time.scheme = GetParam();
  const EnergyHistory h = run_basin(c, 2.0);  // [s] gravity-wave Courant number 2 on 10 m cells
  std::printf("closed basin, %s: E(400 s) / E(0) = %.6f, largest rise in one step %.2e\n",
              test::scheme_name(GetParam()).c_str(), h.ratio, h.largest_rise);
  EXPECT_LT(h.largest_rise, 0.0);
  EXPECT_LT(h.ratio, 1.0);
  EXPECT_LE(std::abs(h.balance_error), 1e-9);
}

// The segregated step (flow.scheme: segregated) at gravity-wave Courant numbers 2 and 5, with a
// ten times weaker vortex (0.005 m/s, Froude number 5e-4): at 0.05 m/s its energy rises by up
// to 2.5e-5 in a step (E(400 s) / E(0) = 0.9990), the characteristics' spin-up above, which its
// lumped mass damps less than the coupled step's consistent one; at 0.005 m/s what is left is
// the gravity waves, which must lose energy at every step (the seiche, seiche_period.cpp).
class ClosedBasinSegregated : public testing::TestWithParam<double> {};

TEST_P(ClosedBasinSegregated, EnergyFallsAtEveryStep) {
  Case c;
  c.flow.scheme = FlowScheme::segregated;
  const double courant = GetParam(), dt = courant * 10.0 / std::sqrt(9.81 * H0);  // [s]
  const EnergyHistory h = run_basin(c, dt, 0.005);
  std::printf("closed basin, segregated, Courant %g: E(400 s) / E(0) = %.6f, largest rise %.2e\n",
              courant, h.ratio, h.largest_rise);
  EXPECT_LT(h.largest_rise, 0.0);
  EXPECT_LT(h.ratio, 1.0);
  EXPECT_LE(std::abs(h.balance_error), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(GravityWaveCourant, ClosedBasinSegregated, testing::Values(2.0, 5.0));

// The segregated step where the viscosity dominates the step: nu = 50 m^2/s, dt = 2 s on 10 m
// elements (nu dt / h^2 = 1, and the P2 vertices' lumped mass is a nineteenth of their
// elements'), the vortex of 0.05 m/s. The transposed-gradient half T_nu of the viscous term is
// explicit; with K_nu wholly at t^{n+1} the pair is stable at any step (docs/model.md "Why K_nu
// wholly at t^{n+1}"), where theta K_nu at t^{n+1} and the rest at t^n amplified the modes with
// nu dt lambda > 2.5 and this energy grew without bound. Viscosity only takes energy out.
TEST(ClosedBasinSegregated, EnergyFallsAtEveryStepWhenTheViscosityDominates) {
  Case c;
  c.flow.scheme = FlowScheme::segregated;
  c.flow.viscosity = 50.0;  // [m^2/s]
  const EnergyHistory h = run_basin(c, 2.0);
  std::printf(
      "closed basin, segregated, nu = 50 m^2/s: E(400 s) / E(0) = %.3e, largest rise %.2e\n",
      h.ratio, h.largest_rise);
  EXPECT_LT(h.largest_rise, 0.0);
  EXPECT_LT(h.ratio, 1.0);
  EXPECT_LE(std::abs(h.balance_error), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(TimeSchemes, ClosedBasin, test::both_time_schemes, test::time_scheme_name);

}  // namespace
}  // namespace flotsam
