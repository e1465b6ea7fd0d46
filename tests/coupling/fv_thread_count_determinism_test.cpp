// Verifies that a two-way run on the finite-volume engine does not depend on the number of
// OpenMP threads (issue 15: "the same seed gives the same run with 1 and 2 threads, bit for
// bit"): every cell and edge is computed by one thread from the same inputs, the Courant step is
// a minimum (order-free) and the balance's sums are serial. A flood wave onto a dry bed with
// logs released from a line (seeded) runs on 1 and 2 threads; the water and the logs end
// bit-identical (tolerance 0).
#include <gtest/gtest.h>
#include <omp.h>

#include "core/thread_governor.hpp"
#include "coupling/simulation.hpp"
#include "flow/fv/fv_engine.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

Case flood_case() {
  Case c;
  c.name = "fv_threads";
  c.mesh.kind = MeshSource::Kind::file;  // the mesh is given in memory
  c.flow.engine = FlowEngineKind::fv;
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = 0.03;                         // [s m^-1/3]
  c.flow.initial_eta = Expression("x < 60 ? 2 : 0", "test");  // [m] a reservoir, dry beyond
  c.flow.boundaries = {
      {BoundaryCondition::Kind::discharge, "left", TimeSeries(20.0), TimeSeries(0.0)},
      {BoundaryCondition::Kind::free, "right", TimeSeries(0.0), TimeSeries(0.0)},
      {BoundaryCondition::Kind::wall, "bottom", TimeSeries(0.0), TimeSeries(0.0)},
      {BoundaryCondition::Kind::wall, "top", TimeSeries(0.0), TimeSeries(0.0)}};
  c.time.mode = CouplingMode::two_way;
  c.time.step = 1.0;
  c.time.end = 12.0;
  Release line;
  line.line_start = Vec2(10.0, 5.0);
  line.line_end = Vec2(10.0, 35.0);
  line.end_time = 6.0;
  line.rate = 60.0;  // [1/min]
  line.length_min = 3.0, line.length_max = 6.0;
  line.width_min = line.width_max = 0.3;
  line.seed = 7;
  c.bodies.releases = {line};
  return c;
}

struct RunResult {
  ConservedState water;
  double front = 0.0;  // [m] x of the furthest wet cell
  std::vector<Vec2> positions;
  std::vector<double> angles;
};

RunResult run_on_threads(int threads) {
  const Mesh mesh = make_rectangle_mesh({.length = 200, .width = 40, .nx = 40, .ny = 8});
  Simulation s(
      flood_case(), mesh,
      {.output_directory = {}, .overwrite = false, .write_output = false, .progress = false});
  {
    const ThreadCountScope scope(threads);
    s.run();
  }
  const FiniteVolumeSolver& flow = dynamic_cast<const FvEngine&>(s.flow()).solver();
  double front = 0.0;
  for (int i = 0; i < flow.cells().cell_count; ++i)
    if (flow.state().h[i] > 1e-3) front = std::max(front, flow.cells().centroid[i].x());
  return {flow.state(), front, s.bodies().position, s.bodies().angle};
}

TEST(FvThreadCountDeterminism, OneAndTwoThreadsGiveBitIdenticalRuns) {
  const RunResult one = run_on_threads(1), two = run_on_threads(2);
  ASSERT_GE(one.positions.size(), 3u);  // logs were released
  ASSERT_GT(one.front, 80.0);           // the wave ran onto the dry bed beyond x = 60 m
  EXPECT_EQ(one.water.h, two.water.h);
  EXPECT_EQ(one.water.hu, two.water.hu);
  EXPECT_EQ(one.water.hv, two.water.hv);
  ASSERT_EQ(one.positions.size(), two.positions.size());
  for (std::size_t i = 0; i < one.positions.size(); ++i) {
    EXPECT_EQ(one.positions[i], two.positions[i]) << "body " << i;
    EXPECT_EQ(one.angles[i], two.angles[i]) << "body " << i;
  }
}

// What `flotsam run` does on a shared machine (core/thread_governor.hpp): the thread count
// changes between steps. Every step on a count of its own (1, 2, 1, ...) gives the run of one
// count, bit for bit.
TEST(FvThreadCountDeterminism, ThreadCountChangingEveryStepGivesTheSameRun) {
  const RunResult two = run_on_threads(2);
  const ThreadCountScope restore(1);
  const Mesh mesh = make_rectangle_mesh({.length = 200, .width = 40, .nx = 40, .ny = 8});
  Simulation s(
      flood_case(), mesh,
      {.output_directory = {}, .overwrite = false, .write_output = false, .progress = false});
  s.initialize();
  for (int k = 0; !s.done(); ++k) {
    omp_set_num_threads(k % 2 == 0 ? 1 : 2);
    s.step();
  }
  const FiniteVolumeSolver& flow = dynamic_cast<const FvEngine&>(s.flow()).solver();
  ASSERT_GE(s.step_count(), 12);
  EXPECT_EQ(flow.state().h, two.water.h);
  EXPECT_EQ(flow.state().hu, two.water.hu);
  EXPECT_EQ(flow.state().hv, two.water.hv);
  ASSERT_EQ(s.bodies().position.size(), two.positions.size());
  for (std::size_t i = 0; i < two.positions.size(); ++i) {
    EXPECT_EQ(s.bodies().position[i], two.positions[i]) << "body " << i;
    EXPECT_EQ(s.bodies().angle[i], two.angles[i]) << "body " << i;
  }
}

}  // namespace
}  // namespace flotsam
