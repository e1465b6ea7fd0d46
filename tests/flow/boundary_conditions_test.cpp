// Unit tests of the engine's input checks (issue 3 "Done when": bad input is a clear error) and of
// the FEM FlowField.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "flow/fem_flow_field.hpp"
#include "flow/shallow_water_solver.hpp"
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
