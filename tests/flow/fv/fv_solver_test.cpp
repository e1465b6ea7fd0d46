// Unit tests of the finite-volume solver (flow/fv/fv_solver.hpp): a lake at rest stays at rest
// (well balanced, with a bed and a shoreline), volume is conserved in a closed basin and the
// water balance closes, and the implicit friction follows its formula (M-14) and never reverses
// the flow.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../../support/reach_momentum.hpp"
#include "core/error.hpp"
#include "flow/fv/fv_solver.hpp"
#include "fv_test_cases.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

Mesh basin_mesh() {
  return make_rectangle_mesh({0.0, 0.0, 10.0, 4.0, 10, 4, true});
}

// Largest |h - h0| and |hu|, |hv| over the cells.
struct Deviation {
  double depth = 0.0, discharge = 0.0;
};
Deviation deviation_from_rest(const FiniteVolumeSolver& s, double eta) {
  Deviation d;
  const ConservedState& U = s.state();
  for (int i = 0; i < s.cells().cell_count; ++i) {
    const double h0 = std::max(0.0, eta - s.bed()[i]);
    d.depth = std::max(d.depth, std::abs(U.h[i] - h0));
    d.discharge = std::max({d.discharge, std::abs(U.hu[i]), std::abs(U.hv[i])});
  }
  return d;
}

TEST(FvSolver, LakeAtRestOnAFlatBedStaysExactlyStill) {
  const Mesh mesh = basin_mesh();
  const Case c = test::closed_basin_case(1.0);
  FiniteVolumeSolver s(mesh, c);
  s.initialize();
  for (int n = 0; n < 5; ++n) s.advance(0.5);
  EXPECT_GT(s.sub_steps().count, 5);
  const Deviation d = deviation_from_rest(s, 1.0);
  EXPECT_LE(d.discharge, 1e-13);
  EXPECT_LE(d.depth, 1e-13);
  EXPECT_DOUBLE_EQ(s.time(), 2.5);
}

// A uniform state's fluxes through a line of cell edges are the exact physical ones (HLLC between
// equal states, no gradient): Q = h u W, the x-momentum flux (h u^2 + g h^2 / 2) W, the y one h u v
// W.
TEST(FvSolver, SectionFluxOfAUniformFlowIsTheExactFlux) {
  const Mesh mesh = basin_mesh();  // 10 m x 4 m
  const Case c = test::closed_basin_case(1.5);
  FiniteVolumeSolver s(mesh, c);
  s.initialize();
  const double h = 1.5, u = 0.8, v = 0.3, W = 4.0, g = c.flow.gravity;
  ConservedState U = s.state();
  std::fill(U.h.begin(), U.h.end(), h);
  std::fill(U.hu.begin(), U.hu.end(), h * u);
  std::fill(U.hv.begin(), U.hv.end(), h * v);
  s.set_state(U);
  const std::vector<int> edges = test::edges_across_x(s.cells(), 5.0);
  ASSERT_NEAR(test::section_width(s.cells(), edges), W, 1e-12);
  const SectionFlux f = s.section_flux(edges, Vec2(1.0, 0.0));
  EXPECT_NEAR(f.discharge, h * u * W, 1e-12);
  EXPECT_NEAR(f.momentum.x(), (h * u * u + 0.5 * g * h * h) * W, 1e-11);
  EXPECT_NEAR(f.momentum.y(), h * u * v * W, 1e-12);
  const SectionFlux back = s.section_flux(edges, Vec2(-1.0, 0.0));  // counted the other way
  EXPECT_NEAR(back.discharge, -f.discharge, 1e-12);
  EXPECT_NEAR(back.momentum.x(), -f.momentum.x(), 1e-11);
}

TEST(FvSolver, LakeAtRestOverASubmergedBumpyBedStaysStill) {
  // The hydrostatic reconstruction balances the bed slope to round-off (Audusse et al. 2004).
  const Mesh mesh = basin_mesh();
  Case c = test::closed_basin_case(1.0);
  c.bed.kind = BedConfig::Kind::expression;
  c.bed.expression = Expression("0.3*sin(x)*cos(2*y) + 0.02*x", "test: bed.expression");
  FiniteVolumeSolver s(mesh, c);
  s.initialize();
  for (int n = 0; n < 5; ++n) s.advance(0.5);
  const Deviation d = deviation_from_rest(s, 1.0);
  EXPECT_LE(d.discharge, 1e-12);
  EXPECT_LE(d.depth, 1e-12);
}

TEST(FvSolver, LakeAtRestWithAnIslandStaysStill) {
  // A mound rising 0.5 m above the surface: a wet/dry shoreline that must not drive a flow.
  const Mesh mesh = basin_mesh();
  Case c = test::closed_basin_case(1.0);
  c.bed.kind = BedConfig::Kind::expression;
  c.bed.expression = Expression("1.5 - 0.2*((x-5)^2 + (y-2)^2)", "test: bed.expression");
  FiniteVolumeSolver s(mesh, c);
  s.initialize();
  ASSERT_LT(s.wet_fraction(), 0.95);
  ASSERT_GT(s.wet_fraction(), 0.3);
  for (int n = 0; n < 5; ++n) s.advance(0.5);
  const Deviation d = deviation_from_rest(s, 1.0);
  EXPECT_LE(d.discharge, 1e-12);
  EXPECT_LE(d.depth, 1e-12);
}

TEST(FvSolver, DamBreakInAClosedBasinConservesVolume) {
  const Mesh mesh = basin_mesh();
  for (const char* eta : {"x < 5 ? 2 : 1", "x < 5 ? 1 : 0"}) {  // onto wet, onto dry bed
    Case c = test::closed_basin_case(0.0);
    c.flow.initial_eta = Expression(eta, "test: flow.initial.eta");
    FiniteVolumeSolver s(mesh, c);
    s.initialize();
    const double V0 = s.volume();
    for (int n = 0; n < 4; ++n) s.advance(0.25);
    EXPECT_GT(s.sub_steps().count, 4);
    EXPECT_GT(deviation_from_rest(s, 0.0).discharge, 0.1) << eta << ": the dam broke";
    EXPECT_LT(std::abs(s.water_balance().relative_error()), 1e-12) << eta;
    // Walls only: nothing leaves, nothing is added (but round-off clamps onto a dry bed).
    EXPECT_EQ(s.water_balance().outflow, 0.0) << eta;
    EXPECT_NEAR(s.volume(), V0 + s.water_balance().source, 1e-12 * V0) << eta;
    EXPECT_LT(std::abs(s.water_balance().source), 1e-12 * V0) << eta;
  }
}

// The balance counts each Runge-Kutta stage's boundary outflow with the weight Heun's step gives
// it (U^{n+1} = U^n + dt/2 (L(U^n) + L(U1))): with water in and out it closes to round-off.
TEST(FvSolver, WaterBalanceClosesWithAnInflowAndAnOutflow) {
  const Mesh mesh = basin_mesh();
  Case c = test::closed_basin_case(1.0);
  test::condition_of(c, "left") = {BoundaryCondition::Kind::discharge, "left", TimeSeries(2.0),
                                   TimeSeries(0.0)};
  test::condition_of(c, "right") = {BoundaryCondition::Kind::elevation, "right", TimeSeries(0.9),
                                    TimeSeries(0.0)};
  FiniteVolumeSolver s(mesh, c);
  s.initialize();
  for (int n = 0; n < 4; ++n) s.advance(0.5);
  ASSERT_GT(std::abs(s.water_balance().outflow), 0.1);  // water crossed the boundaries
  EXPECT_LT(std::abs(s.water_balance().relative_error()), 1e-12);
}

// The same with a single inflow: what entered is V(t) - V(0), to round-off.
TEST(FvSolver, InflowCountedInTheBalanceIsTheVolumeGained) {
  const Mesh mesh = basin_mesh();
  Case c = test::closed_basin_case(1.0);
  test::condition_of(c, "left") = {BoundaryCondition::Kind::discharge, "left", TimeSeries(2.0),
                                   TimeSeries(0.0)};
  FiniteVolumeSolver s(mesh, c);
  s.initialize();
  const double V0 = s.volume();
  s.advance(1.0);
  const double gained = s.volume() - V0;
  ASSERT_GT(gained, 0.5);
  EXPECT_NEAR(-s.water_balance().outflow, gained, 1e-12 * V0);
}

// ---- friction (M-14) ------------------------------------------------------------------------

struct FrictionRun {
  double u0, u1, dt;  // [m/s] at the centre before and after one sub-step dt [s]
  double smallest_u;  // [m/s] the smallest velocity over the wet cells after it
};

// A shallow flat basin 40 m x 40 m in uniform flow u0 along x: the centre sees no gradient
// during a step shorter than one Courant step, only friction.
FrictionRun run_uniform_flow(FrictionLaw law, double coefficient, double h, double u0) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 40.0, 40.0, 20, 20, true});
  Case c = test::closed_basin_case(h);
  c.flow.initial_u = Expression(std::to_string(u0), "test: flow.initial.u");
  c.flow.friction = law;
  c.flow.friction_coefficient = coefficient;
  FiniteVolumeSolver s(mesh, c);
  s.initialize();
  const int centre = test::cell_holding(mesh, s.cells(), Vec2(20.3, 20.2));
  FrictionRun run;
  run.u0 = s.state().hu[centre] / s.state().h[centre];
  run.dt = 0.9 * s.courant_step();
  s.advance(run.dt);
  EXPECT_EQ(s.sub_steps().count, 1);
  run.u1 = s.state().hu[centre] / s.state().h[centre];
  run.smallest_u = u0;
  for (int i = 0; i < s.cells().cell_count; ++i)
    if (s.state().h[i] > s.dry_depth())
      run.smallest_u = std::min(run.smallest_u, s.state().hu[i] / s.state().h[i]);
  return run;
}

// (M-14): u1 = u0 2 / (1 + sqrt(1 + 4 dt gamma)), gamma = c_f |u0| / h, the backward Euler
// step u1 (1 + dt c_f |u1| / h) = u0.
double backward_euler(double u0, double dt, double gamma) {
  return u0 * 2.0 / (1.0 + std::sqrt(1.0 + 4.0 * dt * gamma));
}

TEST(FvSolver, ManningFrictionIsImplicitInTheVelocity) {
  // gamma = g n^2 |u0| / h^(4/3)
  const double g = 9.81, n = 0.05, h = 0.1, u0 = 1.0;
  const FrictionRun r = run_uniform_flow(FrictionLaw::manning, n, h, u0);
  EXPECT_EQ(r.u0, u0);
  const double expected = backward_euler(u0, r.dt, g * n * n * u0 / std::pow(h, 4.0 / 3.0));
  EXPECT_NEAR(expected * (1.0 + r.dt * g * n * n * expected / std::pow(h, 4.0 / 3.0)), u0,
              1e-14);               // it is the backward Euler step
  ASSERT_LT(expected, 0.995 * u0);  // friction is felt
  EXPECT_NEAR(r.u1, expected, 1e-10 * expected);
}

TEST(FvSolver, ChezyFrictionIsImplicitInTheVelocity) {
  // gamma = g |u0| / (C^2 h)
  const double g = 9.81, C = 10.0, h = 0.2, u0 = 1.5;
  const FrictionRun r = run_uniform_flow(FrictionLaw::chezy, C, h, u0);
  const double expected = backward_euler(u0, r.dt, g * u0 / (C * C * h));
  ASSERT_LT(expected, 0.99 * u0);
  EXPECT_NEAR(r.u1, expected, 1e-10 * expected);
}

TEST(FvSolver, HugeFrictionSlowsTheFlowButNeverReversesIt) {
  const double g = 9.81, n = 100.0, h = 0.1, u0 = 1.0;  // n: absurdly rough
  const FrictionRun r = run_uniform_flow(FrictionLaw::manning, n, h, u0);
  const double expected = backward_euler(u0, r.dt, g * n * n * u0 / std::pow(h, 4.0 / 3.0));
  EXPECT_GT(r.u1, 0.0);
  EXPECT_LT(r.u1, 1e-2 * u0);
  EXPECT_NEAR(r.u1, expected, 1e-10 * expected);
  EXPECT_GE(r.smallest_u, 0.0);  // nowhere, not even at the walls, does the flow turn round
}

// Friction balancing the slope is a fixed point of the sub-step, however long: from Manning's
// uniform flow u_n = h^(2/3) sqrt(S) / n on a slope, the stages add the drive dt g h S and
// friction takes exactly as much (1 / (1 + dt gamma) with gamma at |u*|, after the drive, would
// leave about half of u_n here). Checked in the centre of a basin 40 m x 40 m of 4 m squares,
// whose walls are too far to be felt in one sub-step.
TEST(FvSolver, FrictionBalancingTheSlopeIsAFixedPointWhateverTheStep) {
  const double n = 0.03, h = 0.007, S = 0.01;                    // [s m^-1/3], [m], [-]
  const double u_n = std::pow(h, 2.0 / 3.0) * std::sqrt(S) / n;  // [m/s] 0.122
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 40.0, 40.0, 10, 10, true});
  Case c = test::closed_basin_case(0.0);
  c.bed.kind = BedConfig::Kind::slope;
  c.bed.slope = Vec2(S, 0.0);
  c.flow.initial_eta = Expression("0.007 - 0.01*x", "test: flow.initial.eta");
  char u_text[32];
  std::snprintf(u_text, sizeof u_text, "%.17g", u_n);
  c.flow.initial_u = Expression(u_text, "test: flow.initial.u");
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = n;
  FiniteVolumeSolver s(mesh, c);
  s.initialize();
  const int centre = test::cell_holding(mesh, s.cells(), Vec2(20.3, 20.2));
  const double u0 = s.state().hu[centre] / s.state().h[centre];
  ASSERT_NEAR(u0, u_n, 1e-15);
  const double dt = 0.9 * s.courant_step();
  s.advance(dt);
  ASSERT_EQ(s.sub_steps().count, 1);
  const double g = 9.81, gamma = g * n * n * u_n / std::pow(h, 4.0 / 3.0);  // [1/s]
  ASSERT_GT(dt * gamma, 1.0);  // friction is stiff at this step
  EXPECT_NEAR(s.state().hu[centre] / s.state().h[centre], u0, 1e-12 * u0);
}

// ---- input ----------------------------------------------------------------------------------

TEST(FvSolver, NegativeDepthSetAsStateIsAnInputError) {
  const Mesh mesh = basin_mesh();
  const Case c = test::closed_basin_case(1.0);
  FiniteVolumeSolver s(mesh, c);
  s.initialize();
  ConservedState bad = s.state();
  bad.h[7] = -0.1;
  EXPECT_THROW(s.set_state(bad), InputError);
}

// A condition on a group the mesh lacks (a case built in code with a misspelt group) is an
// InputError, not a wall.
TEST(FvSolver, ConditionOnAGroupTheMeshLacksIsAnInputError) {
  const Mesh mesh = basin_mesh();
  Case c = test::closed_basin_case(1.0);
  c.flow.boundaries.push_back(
      {BoundaryCondition::Kind::discharge, "inlet", TimeSeries(1.0), TimeSeries(0.0)});
  EXPECT_THROW(FiniteVolumeSolver(mesh, c), InputError);
}

}  // namespace
}  // namespace flotsam
