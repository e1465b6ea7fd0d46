// Unit tests of the engine's input checks (issue 3 "Done when": bad input is a clear error) and of
// the FEM FlowField.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "flow/fem/fem_flow_field.hpp"
#include "flow/fem/shallow_water_solver.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

using ::testing::HasSubstr;

Case wet_case() {
  Case c;
  c.file = "basin.yaml";
  c.flow.initial_eta_start = c.flow.initial_eta_end = 1.0;
  return c;
}

template <class F>
std::string input_error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

TEST(FlowInput, GroupAbsentFromTheMeshIsNamed) {
  const Mesh mesh = make_rectangle_mesh({0, 0, 10, 4, 5, 2, true});
  Case c = wet_case();
  c.flow.boundaries = {{BoundaryCondition::Kind::elevation, "inlet", TimeSeries(1.0), {}}};
  const std::string msg = input_error_of([&] { ShallowWaterSolver s(mesh, c); });
  EXPECT_THAT(msg, HasSubstr("basin.yaml"));
  EXPECT_THAT(msg, HasSubstr("'inlet' is not a boundary group"));
  EXPECT_THAT(msg, HasSubstr("left, right"));
}

TEST(FlowInput, DischargeOnAWallIsRejected) {
  const Mesh mesh = make_rectangle_mesh({0, 0, 10, 4, 5, 2, true});
  Case c = wet_case();
  c.flow.boundaries = {{BoundaryCondition::Kind::wall, "left", {}, {}},
                       {BoundaryCondition::Kind::discharge, "left", TimeSeries(1.0), {}}};
  const std::string msg = input_error_of([&] { ShallowWaterSolver s(mesh, c); });
  EXPECT_THAT(msg, HasSubstr("group 'left' is given two conditions, wall and discharge"));
}

TEST(FlowInput, NegativeDepthAtStartNamesTheNode) {
  const Mesh mesh = make_rectangle_mesh({0, 0, 10, 4, 5, 2, true});
  Case c = wet_case();
  c.flow.initial_eta_start = c.flow.initial_eta_end = -0.5;
  const std::string msg = input_error_of([&] {
    ShallowWaterSolver s(mesh, c);
    s.initialize();
  });
  EXPECT_THAT(msg, HasSubstr("initial depth H = -0.5 m at node"));
  EXPECT_THAT(msg, HasSubstr("below the dry depth"));
}

TEST(FlowInput, FreeBoundaryIsForTheFiniteVolumeEngineOnly) {
  const Mesh mesh = make_rectangle_mesh({0, 0, 10, 4, 5, 2, true});
  Case c = wet_case();
  c.flow.boundaries = {{BoundaryCondition::Kind::elevation, "left", TimeSeries(1.0), {}, 13},
                       {BoundaryCondition::Kind::free, "right", {}, {}, 14}};
  EXPECT_EQ(input_error_of([&] { ShallowWaterSolver s(mesh, c); }),
            "basin.yaml:14: flow.boundaries.right: type 'free' is supported by 'engine: fv' "
            "only; the FEM engine takes elevation, discharge, velocity, wall or noslip");
  EXPECT_STREQ(boundary_kind_name(BoundaryCondition::Kind::free), "free");
}

TEST(FlowInput, RainIsForTheFiniteVolumeEngineOnly) {
  const Mesh mesh = make_rectangle_mesh({0, 0, 10, 4, 5, 2, true});
  Case c = wet_case();
  c.flow.boundaries = {{BoundaryCondition::Kind::wall, "left", {}, {}},
                       {BoundaryCondition::Kind::wall, "right", {}, {}}};
  c.flow.rain.enabled = true;
  c.flow.rain.intensity = TimeSeries(20.0);
  c.flow.rain.line = 9;
  EXPECT_EQ(input_error_of([&] { ShallowWaterSolver s(mesh, c); }),
            "basin.yaml:9: flow.rain: rain is supported by 'engine: fv' only; the FEM engine "
            "(engine: fem) has no rain or infiltration source");
}

// The FEM cannot start dry: a formula leaving vertices below the dry depth is the same error as
// a flat surface below the bed (the dam break's dry half). The message names the first dry node
// in the mesh's numbering (along its curve, mesh/curve_order.hpp) by its tag.
TEST(FlowInput, FormulaThatStartsDryNamesTheNode) {
  const Mesh mesh = make_rectangle_mesh({0, 0, 10, 4, 5, 2, true});
  Case c = wet_case();
  c.flow.initial_eta = Expression("x < 5 ? 0.005 : 0", "basin.yaml:5: flow.initial.eta");
  const std::string msg = input_error_of([&] {
    ShallowWaterSolver s(mesh, c);
    s.initialize();
  });
  EXPECT_EQ(msg,
            "basin.yaml: initial depth H = 0 m at node 18 (10, 4) of mesh rectangle 10x4 m, 5x2 "
            "cells is below the dry depth 0.001 m: the FEM engine needs the domain wet at start "
            "(eta = 0 m, z_b = 0 m)");
}

// Formulas set z_b per P2 node, eta per vertex and u, v per P2 node (mid-edge nodes included).
TEST(FemInitialState, FormulasGiveBedSurfaceAndVelocity) {
  const Mesh mesh = make_rectangle_mesh({0, 0, 10, 4, 5, 2, true});
  Case c = wet_case();
  c.bed.kind = BedConfig::Kind::expression;
  c.bed.expression = Expression("0.01*x - 0.02*y", "basin.yaml:3: bed.expression");
  c.flow.initial_eta = Expression("1 + 0.02*x", "basin.yaml:5: flow.initial.eta");
  c.flow.initial_u = Expression("0.5 + 0.1*y", "basin.yaml:6: flow.initial.u");
  c.flow.initial_v = Expression("-0.2*x*y", "basin.yaml:7: flow.initial.v");
  ShallowWaterSolver solver(mesh, c);
  solver.initialize();
  ASSERT_GT(mesh.node_count(), mesh.vertex_count);
  for (int j = 0; j < mesh.vertex_count; ++j)
    EXPECT_DOUBLE_EQ(solver.eta()[j], 1.0 + 0.02 * mesh.nodes[j].x()) << j;
  for (int i = 0; i < mesh.node_count(); ++i) {
    const Vec2& p = mesh.nodes[i];
    EXPECT_DOUBLE_EQ(solver.bed()[i], 0.01 * p.x() - 0.02 * p.y()) << i;
    EXPECT_DOUBLE_EQ(solver.u()[i], 0.5 + 0.1 * p.y()) << i;
    EXPECT_DOUBLE_EQ(solver.v()[i], -0.2 * p.x() * p.y()) << i;
  }
}

// Without formulas the surface is linear in x between the two values and the water at rest.
TEST(FemInitialState, WithoutFormulasTheSurfaceIsLinearInXAndAtRest) {
  const Mesh mesh = make_rectangle_mesh({0, 0, 10, 4, 5, 2, true});
  Case c = wet_case();
  c.flow.initial_eta_start = 1.2;
  c.flow.initial_eta_end = 1.0;
  ShallowWaterSolver solver(mesh, c);
  solver.initialize();
  for (int j = 0; j < mesh.vertex_count; ++j)
    EXPECT_NEAR(solver.eta()[j], 1.2 - 0.02 * mesh.nodes[j].x(), 1e-14) << j;
  for (int i = 0; i < mesh.node_count(); ++i) {
    EXPECT_EQ(solver.u()[i], 0.0);
    EXPECT_EQ(solver.v()[i], 0.0);
  }
}

// A linear velocity field u = (a + b y, 0) over a flat bed is represented exactly by P2: the
// field's samples must be exact, and du/dt the difference of the two states over dt.
TEST(FemFlowField, SamplesInterpolateInSpaceAndTime) {
  const Mesh mesh = make_rectangle_mesh({0, 0, 10, 4, 5, 2, true});
  Case c = wet_case();
  ShallowWaterSolver solver(mesh, c);
  solver.initialize();
  FlowState s;
  s.time = 0.0;
  for (int j = 0; j < mesh.vertex_count; ++j) s.eta.push_back(1.0 + 0.01 * mesh.nodes[j].x());
  for (const Vec2& p : mesh.nodes) {
    s.u.push_back(0.5 + 0.1 * p.y());
    s.v.push_back(0.0);
  }
  solver.set_state(s);
  FemFlowField field(solver);
  int hint = -1;
  const FlowSample f = field.sample(Vec2(3.3, 1.7), 0.0, hint);
  ASSERT_TRUE(f.inside);
  EXPECT_NEAR(f.eta, 1.033, 1e-12);
  EXPECT_NEAR(f.H, 1.033, 1e-12);
  EXPECT_NEAR(f.u.x(), 0.67, 1e-12);
  EXPECT_NEAR(f.grad_u(0, 1), 0.1, 1e-12);
  EXPECT_NEAR(f.grad_zb.norm(), 0.0, 1e-12);
  EXPECT_FALSE(field.sample(Vec2(-1.0, 1.0), 0.0, hint).inside);
}

}  // namespace
}  // namespace flotsam
