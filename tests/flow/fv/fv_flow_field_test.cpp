// Unit tests of what the bodies see of the finite-volume flow (flow/fv/fv_flow_field.hpp):
// samples of the cells' linear reconstruction, their interpolation in time, and the body
// reactions shared among the wet cells of a footprint so that the water receives exactly -F_x.
#include <gtest/gtest.h>

#include <cmath>

#include "flow/fv/fv_engine.hpp"
#include "fv_test_cases.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

// Parallel diagonals: the reconstruction of linear data is exact on inner cells
// (reconstruction_test.cpp).
Mesh parallelogram_mesh() {
  return make_rectangle_mesh({0.0, 0.0, 10.0, 4.0, 10, 4, false});
}

// eta from 1 m at x = 0 to 1.5 m at x = 10 m over the plane bed z = -0.5 + 0.05 x - 0.02 y.
double eta_at(const Vec2& x) {
  return 1.0 + 0.05 * x.x();
}
double bed_at(const Vec2& x) {
  return -0.5 + 0.05 * x.x() - 0.02 * x.y();
}

TEST(FvFlowField, SampleOfALinearFieldIsExact) {
  const Mesh mesh = parallelogram_mesh();
  Case c = test::closed_basin_case(0.0);
  c.flow.initial_eta_start = 1.0, c.flow.initial_eta_end = 1.5;
  c.bed.kind = BedConfig::Kind::expression;
  c.bed.expression = Expression("-0.5 + 0.05*x - 0.02*y", "test: bed.expression");
  FvEngine engine(mesh, c);
  engine.initialize();
  const CellMesh& cells = engine.solver().cells();
  int hint = -1, sampled = 0;
  for (double x = 1.13; x < 9.0; x += 0.61)
    for (double y = 1.07; y < 3.0; y += 0.37) {
      const Vec2 p(x, y);
      ASSERT_TRUE(test::is_inner_cell(cells, test::cell_holding(mesh, cells, p)));
      const FlowSample f = engine.field().sample(p, 0.0, hint);
      ASSERT_TRUE(f.inside);
      EXPECT_NEAR(f.eta, eta_at(p), 1e-12) << "at (" << x << ", " << y << ")";
      EXPECT_NEAR(f.H, eta_at(p) - bed_at(p), 1e-12) << "at (" << x << ", " << y << ")";
      EXPECT_NEAR((f.grad_zb - Vec2(0.05, -0.02)).norm(), 0.0, 1e-12);
      EXPECT_EQ(f.u, Vec2::Zero());
      EXPECT_EQ(f.du_dt, Vec2::Zero());
      ++sampled;
    }
  EXPECT_GT(sampled, 20);
  const FlowSample outside = engine.field().sample(Vec2(12.0, 2.0), 0.0, hint);
  EXPECT_FALSE(outside.inside);
  EXPECT_EQ(mesh.group_names.at(outside.boundary_group), "right");
}

TEST(FvFlowField, LakeAtRestHasNoAcceleration) {
  const Mesh mesh = parallelogram_mesh();
  Case c = test::closed_basin_case(1.0);
  c.bed.kind = BedConfig::Kind::expression;
  c.bed.expression = Expression("-0.5 + 0.05*x - 0.02*y", "test: bed.expression");
  FvEngine engine(mesh, c);
  engine.initialize();
  engine.step(0.5);
  ASSERT_EQ(engine.field().time_begin(), 0.0);
  ASSERT_EQ(engine.field().time_end(), 0.5);
  int hint = -1;
  for (const Vec2& p : {Vec2(2.3, 1.1), Vec2(5.05, 2.9), Vec2(8.7, 0.4)}) {
    const FlowSample f = engine.field().sample(p, 0.25, hint);
    EXPECT_NEAR(f.eta, 1.0, 1e-13);
    EXPECT_NEAR(f.H, 1.0 - bed_at(p), 1e-12);
    EXPECT_LE(f.u.norm(), 1e-13);
    EXPECT_LE(f.du_dt.norm(), 1e-12);
  }
}

TEST(FvFlowField, SamplesInterpolateLinearlyInTimeOverTheStep) {
  // A dam break: the flow at mid-step is the mean of its ends, du/dt their difference over dt.
  const Mesh mesh = parallelogram_mesh();
  Case c = test::closed_basin_case(0.0);
  c.flow.initial_eta = Expression("x < 5 ? 2 : 1", "test: flow.initial.eta");
  FvEngine engine(mesh, c);
  engine.initialize();
  engine.step(0.2);
  engine.step(0.3);
  const FlowField& field = engine.field();
  ASSERT_DOUBLE_EQ(field.time_begin(), 0.2);
  ASSERT_DOUBLE_EQ(field.time_end(), 0.5);
  int hint = -1;
  const Vec2 p(5.3, 2.1);
  const FlowSample a = field.sample(p, 0.2, hint), b = field.sample(p, 0.5, hint);
  const FlowSample m = field.sample(p, 0.35, hint);
  ASSERT_GT((b.u - a.u).norm(), 1e-3);  // the flow accelerates here
  EXPECT_NEAR((m.u - 0.5 * (a.u + b.u)).norm(), 0.0, 1e-14);
  EXPECT_NEAR(m.H, 0.5 * (a.H + b.H), 1e-14);
  EXPECT_NEAR((m.du_dt - (b.u - a.u) / 0.3).norm(), 0.0, 1e-12);
  EXPECT_NEAR((a.du_dt - m.du_dt).norm(), 0.0, 1e-12);
}

// Sum of the forces the solver will apply [N].
Vec2 total_force(const FvEngine& engine) {
  Vec2 sum = Vec2::Zero();
  for (const Vec2& f : engine.solver().cell_forces()) sum += f;
  return sum;
}

TEST(FvFlowField, BodyReactionIsSharedAmongTheWetCellsOfItsFootprint) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 10.0, 4.0, 10, 4, true});
  const Case c = test::closed_basin_case(1.0);
  FvEngine engine(mesh, c);
  engine.initialize();
  const Vec2 F(120.0, -45.0);  // [N]
  const BodyReaction r{Vec2(5.2, 2.1), Vec2(1.5, 0.6), 0.3, F};
  engine.field().set_body_reactions({r});
  const Vec2 sum = total_force(engine);
  EXPECT_NEAR((sum - F).norm(), 0.0, 1e-12 * F.norm());
  // Only cells whose centroid lies in the rotated rectangle receive a share, in proportion to
  // their area.
  const CellMesh& cells = engine.solver().cells();
  const Vec2 axis(std::cos(r.angle), std::sin(r.angle));
  int loaded = 0;
  std::vector<Vec2> pressure;
  for (int i = 0; i < cells.cell_count; ++i) {
    const Vec2& f = engine.solver().cell_forces()[i];
    const Vec2 d = cells.centroid[i] - r.centre;
    const bool in = std::abs(d.dot(axis)) <= r.half_extents.x() &&
                    std::abs(cross(axis, d)) <= r.half_extents.y();
    if (!in) {
      EXPECT_EQ(f, Vec2::Zero()) << "cell " << i;
      continue;
    }
    ++loaded;
    pressure.push_back(f / cells.area[i]);  // [N/m^2]
  }
  EXPECT_GT(loaded, 3);
  for (const Vec2& p : pressure) EXPECT_NEAR((p - pressure.front()).norm(), 0.0, 1e-12 * p.norm());
}

TEST(FvFlowField, SmallBodyLoadsTheCellHoldingItsCentre) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 10.0, 4.0, 10, 4, true});
  const Case c = test::closed_basin_case(1.0);
  FvEngine engine(mesh, c);
  engine.initialize();
  const Vec2 F(3.0, 4.0), centre(3.31, 1.27);
  engine.field().set_body_reactions({{centre, Vec2(0.01, 0.01), 0.0, F}});
  const int i = test::cell_holding(mesh, engine.solver().cells(), centre);
  EXPECT_EQ(engine.solver().cell_forces()[i], F);
  EXPECT_NEAR((total_force(engine) - F).norm(), 0.0, 1e-12 * F.norm());
}

TEST(FvFlowField, BodyOverDryBedGivesTheWaterNothing) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 10.0, 4.0, 10, 4, true});
  Case c = test::closed_basin_case(1.0);
  c.bed.kind = BedConfig::Kind::expression;
  c.bed.expression = Expression("x > 6 ? 2 : 0", "test: bed.expression");  // dry beyond 6 m
  FvEngine engine(mesh, c);
  engine.initialize();
  engine.field().set_body_reactions({{Vec2(8.2, 2.0), Vec2(1.0, 0.5), 0.4, Vec2(50.0, 20.0)},
                                     {Vec2(20.0, 2.0), Vec2(1.0, 0.5), 0.0, Vec2(50.0, 0.0)}});
  EXPECT_EQ(total_force(engine), Vec2::Zero());
}

TEST(FvFlowField, WaterReceivesTheBodyReactionAsMomentum) {
  // Over one sub-step of a lake at rest in a closed basin, the walls and the fluxes exchange no
  // net momentum (flat surface, flat bed): rho sum_i A_i (hu)_i = F dt.
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 10.0, 4.0, 10, 4, true});
  const Case c = test::closed_basin_case(1.0);
  FvEngine engine(mesh, c);
  engine.initialize();
  const Vec2 F(120.0, -45.0);  // [N]
  engine.field().set_body_reactions({{Vec2(5.2, 2.1), Vec2(1.5, 0.6), 0.3, F}});
  const double dt = 0.5 * engine.solver().courant_step();
  engine.step(dt);
  ASSERT_EQ(engine.solver().sub_steps().count, 1);
  const CellMesh& cells = engine.solver().cells();
  const ConservedState& U = engine.solver().state();
  Vec2 momentum = Vec2::Zero();  // [kg m/s]
  for (int i = 0; i < cells.cell_count; ++i)
    momentum += c.flow.water_density * cells.area[i] * Vec2(U.hu[i], U.hv[i]);
  EXPECT_NEAR((momentum - F * dt).norm(), 0.0, 1e-9 * F.norm() * dt);
}

// A body moving at v over a lake at rest drags the water along, point-implicitly (body_drag.hpp):
// over one sub-step the stages see water at rest (no flux), and every cell under the body has
// the same a = K / (rho A_b) (its share w_i = A_i / A_b), so the water under it, of mass
// M = rho h A_b, takes exactly K v dt / (1 + K dt / M): never more than M v, however stiff.
// What the field reports for the body is what the water took, to round-off.
TEST(FvFlowField, BodyDragIsImplicitAndReportsWhatTheWaterTook) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 10.0, 4.0, 10, 4, true});
  const Case c = test::closed_basin_case(1.0);
  const double rho = c.flow.water_density;
  for (const double K : {40.0, 4.0e6}) {  // [kg/s]: K dt / M about 1e-4 and 10
    FvEngine engine(mesh, c);
    engine.initialize();
    BodyReaction r{Vec2(5.2, 2.1), Vec2(1.5, 0.6), 0.3, Vec2::Zero()};
    r.drag_rate = K;
    r.velocity = Vec2(0.8, -0.3);  // [m/s]
    engine.field().set_body_reactions({r});
    const CellMesh& cells = engine.solver().cells();
    double area = 0.0;  // [m^2] of the cells under the body
    for (int i = 0; i < cells.cell_count; ++i)
      if (engine.solver().body_drag().rate[i] > 0.0) area += cells.area[i];
    const double dt = 0.5 * engine.solver().courant_step();
    engine.step(dt);
    ASSERT_EQ(engine.solver().sub_steps().count, 1);
    const ConservedState& U = engine.solver().state();
    Vec2 momentum = Vec2::Zero();  // [kg m/s]
    double fastest = 0.0;          // [m/s] along v
    for (int i = 0; i < cells.cell_count; ++i) {
      momentum += rho * cells.area[i] * Vec2(U.hu[i], U.hv[i]);
      fastest = std::max(fastest, Vec2(U.hu[i], U.hv[i]).dot(r.velocity) / U.h[i]);
    }
    const double M = rho * 1.0 * area;  // [kg]
    const Vec2 expected = K * r.velocity * dt / (1.0 + K * dt / M);
    EXPECT_NEAR((momentum - expected).norm(), 0.0, 1e-12 * expected.norm()) << "K " << K;
    EXPECT_LE(fastest, r.velocity.squaredNorm());  // never past the body's velocity
    const std::vector<Vec2> exchanged = engine.field().exchanged_forces();
    ASSERT_EQ(exchanged.size(), 1u);
    EXPECT_NEAR((exchanged[0] * dt + momentum).norm(), 0.0, 1e-12 * momentum.norm()) << "K " << K;
  }
}

// The same exchange over several sub-steps, with one time level and with three (the drag after
// friction in each cell's own step, local_time_steps.cpp): before the waves the body raises
// reach the walls, only the drag changes the water's momentum (the fluxes of a flat basin
// cancel), so the water's momentum is minus what the field reports times the time, to
// round-off.
TEST(FvFlowField, BodyDragOverSubStepsAndTimeLevelsReportsWhatTheWaterTook) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 20.0, 8.0, 20, 8, true});
  for (const int levels : {1, 3}) {
    Case c = test::closed_basin_case(1.0);
    c.flow.fv.time_levels = levels;
    FvEngine engine(mesh, c);
    engine.initialize();
    BodyReaction r{Vec2(10.2, 4.1), Vec2(1.5, 0.6), 0.3, Vec2::Zero()};
    r.drag_rate = 4.0e3;           // [kg/s]
    r.velocity = Vec2(0.8, -0.3);  // [m/s]
    engine.field().set_body_reactions({r});
    const double span = 2.0 * engine.solver().courant_step();  // [s]
    engine.step(span);
    ASSERT_GE(engine.solver().sub_steps().count, 2) << levels << " levels";
    const CellMesh& cells = engine.solver().cells();
    const ConservedState& U = engine.solver().state();
    Vec2 momentum = Vec2::Zero();  // [kg m/s]
    for (int i = 0; i < cells.cell_count; ++i)
      momentum += c.flow.water_density * cells.area[i] * Vec2(U.hu[i], U.hv[i]);
    const Vec2 exchanged = engine.field().exchanged_forces().at(0);
    EXPECT_GT(momentum.dot(r.velocity), 0.5 * r.drag_rate * span * r.velocity.squaredNorm());
    EXPECT_NEAR((exchanged * span + momentum).norm(), 0.0, 1e-12 * momentum.norm())
        << levels << " levels";
  }
}

}  // namespace
}  // namespace flotsam
