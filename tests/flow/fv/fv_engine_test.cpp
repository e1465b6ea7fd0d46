// Unit tests of the finite-volume engine behind the FlowEngine interface (flow/fv/fv_engine.hpp):
// a checkpoint continues bit for bit, and the nodal view of a lake at rest is its level.
#include <gtest/gtest.h>

#include <cmath>

#include "../../support/scratch_path.hpp"
#include "core/error.hpp"
#include "flow/fv/fv_engine.hpp"
#include "fv_test_cases.hpp"
#include "io/binary_archive.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

// A dam break over a sloping bed with Manning friction, inflow at the left, a level held at the
// right, rain and infiltration: every part of the state and of the balance moves.
Case moving_case() {
  Case c = test::closed_basin_case(0.0);
  c.flow.initial_eta = Expression("x < 4 ? 1.5 : 1", "test: flow.initial.eta");
  c.bed.kind = BedConfig::Kind::expression;
  c.bed.expression = Expression("0.02*x - 0.05*y", "test: bed.expression");
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = 0.03;
  test::condition_of(c, "left") = {BoundaryCondition::Kind::discharge, "left", TimeSeries(0.5),
                                   TimeSeries(0.0)};
  test::condition_of(c, "right") = {BoundaryCondition::Kind::elevation, "right", TimeSeries(1.0),
                                    TimeSeries(0.0)};
  c.flow.rain.enabled = true;
  c.flow.rain.intensity = TimeSeries({{0.0, 100.0}, {1.0, 500.0}});  // [mm/h]
  c.flow.rain.infiltration = 50.0;                                   // [mm/h]
  return c;
}

// With one time level and with three (local time stepping: each step chooses its levels from its
// own start, so a restart continues as the run would), the balance closing to 1e-12 with rain,
// infiltration, a discharge and a level.
class FvCheckpoint : public ::testing::TestWithParam<int> {};

TEST_P(FvCheckpoint, RoundTripContinuesBitForBit) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 10.0, 4.0, 10, 4, true});
  Case c = moving_case();
  c.flow.fv.time_levels = GetParam();
  FvEngine running(mesh, c);
  running.initialize();
  for (int n = 0; n < 3; ++n) running.step(0.2);
  const std::string path = test::scratch_path("fv_engine_checkpoint.bin").string();
  {
    ArchiveWriter w(path);
    running.save(w, "flow");
    w.close();
  }
  FvEngine restarted(mesh, c);
  restarted.initialize();
  ArchiveReader r(path);
  restarted.restore(r, "flow");
  EXPECT_EQ(restarted.time(), running.time());

  running.step(0.2);
  restarted.step(0.2);
  const ConservedState& a = running.solver().state();
  const ConservedState& b = restarted.solver().state();
  ASSERT_GT(std::abs(a.hu[0]) + std::abs(a.hu[a.hu.size() / 2]), 0.0);  // the flow moves
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.h, b.h);
  EXPECT_EQ(a.hu, b.hu);
  EXPECT_EQ(a.hv, b.hv);
  const WaterBalance &wa = running.water_balance(), &wb = restarted.water_balance();
  EXPECT_EQ(wa.initial_volume, wb.initial_volume);
  EXPECT_EQ(wa.volume, wb.volume);
  EXPECT_EQ(wa.outflow, wb.outflow);
  EXPECT_EQ(wa.source, wb.source);
  ASSERT_GT(wa.rain, 0.0);
  ASSERT_GT(wa.infiltration, 0.0);
  EXPECT_EQ(wa.rain, wb.rain);
  EXPECT_EQ(wa.infiltration, wb.infiltration);
  EXPECT_EQ(wa.group_outflow, wb.group_outflow);
  EXPECT_EQ(running.solver().sub_steps().count, restarted.solver().sub_steps().count);
  EXPECT_EQ(running.solver().sub_steps().smallest, restarted.solver().sub_steps().smallest);
  EXPECT_EQ(running.solver().sub_steps().total, restarted.solver().sub_steps().total);
  EXPECT_EQ(running.solver().sub_steps().cell_updates, restarted.solver().sub_steps().cell_updates);
  EXPECT_LE(std::abs(wa.relative_error()), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(TimeLevels, FvCheckpoint, ::testing::Values(1, 3));

TEST(FvEngine, RestoreOfAnotherMeshIsAnInputError) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 10.0, 4.0, 10, 4, true});
  const Mesh other = make_rectangle_mesh({0.0, 0.0, 10.0, 4.0, 5, 2, true});
  const Case c = test::closed_basin_case(1.0);
  FvEngine engine(mesh, c);
  engine.initialize();
  const std::string path = test::scratch_path("fv_engine_other_mesh.bin").string();
  {
    ArchiveWriter w(path);
    engine.save(w, "flow");
    w.close();
  }
  FvEngine smaller(other, c);
  smaller.initialize();
  ArchiveReader r(path);
  EXPECT_THROW(smaller.restore(r, "flow"), InputError);
}

TEST(FvEngine, NodalStateOfALakeAtRestIsItsLevel) {
  // An island: vertices among wet cells show the lake's level, vertices with only dry cells
  // around show the bed, and no node moves.
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 10.0, 4.0, 10, 4, true});
  Case c = test::closed_basin_case(1.0);
  c.bed.kind = BedConfig::Kind::expression;
  c.bed.expression = Expression("1.5 - 0.2*((x-5)^2 + (y-2)^2)", "test: bed.expression");
  FvEngine engine(mesh, c);
  engine.initialize();
  engine.step(0.5);
  const FiniteVolumeSolver& s = engine.solver();
  const CellMesh& cells = s.cells();
  std::vector<int> wet(mesh.node_count(), 0);
  for (int i = 0; i < cells.cell_count; ++i)
    if (s.state().h[i] > s.dry_depth())
      for (int k : cells.corners[i]) wet[k] = 1;
  const FlowState& nodal = engine.nodal_state();
  ASSERT_EQ(static_cast<int>(nodal.eta.size()), mesh.vertex_count);
  const std::vector<std::uint8_t> flags = engine.wet_nodes();  // what pictures draw as water
  ASSERT_EQ(static_cast<int>(flags.size()), mesh.node_count());
  for (int k = 0; k < mesh.vertex_count; ++k) EXPECT_EQ(flags[k], wet[k]) << "vertex " << k;
  int wet_vertices = 0, dry_vertices = 0;
  for (int k = 0; k < mesh.vertex_count; ++k) {
    const Vec2& x = mesh.nodes[k];
    const double z = 1.5 - 0.2 * ((x.x() - 5) * (x.x() - 5) + (x.y() - 2) * (x.y() - 2));
    if (wet[k]) {
      ++wet_vertices;
      EXPECT_NEAR(nodal.eta[k], 1.0, 1e-13) << "vertex " << k;
    } else {
      ++dry_vertices;
      EXPECT_NEAR(nodal.eta[k], z, 1e-13) << "vertex " << k;
    }
  }
  EXPECT_GT(wet_vertices, 0);
  EXPECT_GT(dry_vertices, 0);
  for (int k = 0; k < mesh.node_count(); ++k) {
    EXPECT_LE(std::abs(nodal.u[k]), 1e-12) << "node " << k;
    EXPECT_LE(std::abs(nodal.v[k]), 1e-12) << "node " << k;
  }
  EXPECT_EQ(nodal.time, 0.5);
}

// Frozen mode (FlowEngine::settle): a frictionless channel fed Q at the left, the level held at
// H0 at the right, marched from still water until the velocity settles; its steady state is the
// uniform flow U = Q / (W H0) (the discharge ghost and the interior fluxes then agree exactly),
// and that state becomes t = 0 with the balance restarted.
TEST(FvEngine, SettleMarchesToTheUniformFlow) {
  const double W = 4.0, H0 = 1.0, Q = 2.0, U = Q / (W * H0);  // [m], [m], [m^3/s], [m/s]
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 20.0, W, 10, 2, true});
  Case c = test::closed_basin_case(H0);
  test::condition_of(c, "left") = {BoundaryCondition::Kind::discharge, "left", TimeSeries(Q),
                                   TimeSeries(0.0)};
  test::condition_of(c, "right") = {BoundaryCondition::Kind::elevation, "right", TimeSeries(H0),
                                    TimeSeries(0.0)};
  c.time.spin_up_step = 5.0;
  c.time.spin_up_end = 3000.0;
  FvEngine engine(mesh, c);
  engine.initialize();
  engine.settle(c.time);
  EXPECT_EQ(engine.time(), 0.0);
  EXPECT_EQ(engine.water_balance().outflow, 0.0);
  EXPECT_EQ(engine.water_balance().initial_volume, engine.volume());
  const ConservedState& s = engine.solver().state();
  for (std::size_t i = 0; i < s.h.size(); ++i) {
    ASSERT_NEAR(s.h[i], H0, 1e-3 * H0) << "cell " << i;
    ASSERT_NEAR(s.hu[i] / s.h[i], U, 1e-3 * U) << "cell " << i;
    ASSERT_NEAR(s.hv[i] / s.h[i], 0.0, 1e-3 * U) << "cell " << i;
  }
  // Marching too briefly is a RunError that says so.
  c.time.spin_up_end = 5.0;
  FvEngine brief(mesh, c);
  brief.initialize();
  try {
    brief.settle(c.time);
    FAIL() << "a march of one step settled";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("time.spin_up_end"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace flotsam

namespace flotsam {
namespace {

// A dry, still basin under rain for one step shorter than any Courant step of its film: no
// sub-step was Courant-limited, and the summary says so rather than "smallest 0 s"; once the
// water moves, it gives the smallest and mean Courant steps.
TEST(FvEngine, SummaryOfRainOnADryBasinStatesThatNoCourantLimitApplied) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 10.0, 4.0, 10, 4, true});
  Case c = test::closed_basin_case(-1.0);  // the surface below the bed: dry
  c.flow.rain.enabled = true;
  c.flow.rain.intensity = TimeSeries(36.0);  // [mm/h]
  FvEngine dry(mesh, c);
  dry.initialize();
  dry.step(1.0);
  EXPECT_EQ(dry.solver().sub_steps().count, 1);
  EXPECT_NE(dry.summary().find("no Courant limit (the water was dry and still)"), std::string::npos)
      << dry.summary();
  EXPECT_EQ(dry.summary().find("smallest 0 s"), std::string::npos) << dry.summary();
  const Case moving_flow = moving_case();  // the engine keeps a reference to its case
  FvEngine moving(mesh, moving_flow);
  moving.initialize();
  moving.step(0.2);
  EXPECT_NE(moving.summary().find("Courant step smallest "), std::string::npos) << moving.summary();
}

}  // namespace
}  // namespace flotsam
