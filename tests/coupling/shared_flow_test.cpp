// Verifies the shared flow (coupling/shared_flow.hpp): a one-way or frozen run that replays a
// flow recorded once ends in the same state, bit for bit, as the run that computes its own flow
// (bodies with contacts and a seeded release, the flow, the water balance, the tables written),
// with either engine; runs replaying it write each flow field file once and link it, the same
// bytes as the run that computes its own flow writes; and a shared flow recorded for other times
// is refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../support/scratch_path.hpp"
#include "../support/straight_channel.hpp"
#include "core/error.hpp"
#include "coupling/shared_flow.hpp"
#include "coupling/simulation.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

namespace fs = std::filesystem;

Case shared_case(CouplingMode mode, FlowEngineKind engine) {
  Case c = test::straight_channel_case("shared", 40.0, 2.0);
  c.flow.engine = engine;
  c.flow.viscosity = 0.01;
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = 0.03;
  // The eddy viscosity is a field of the FEM's output: a replayed flow writes it too.
  if (engine == FlowEngineKind::fem) c.flow.turbulence = TurbulenceModel::mixing_length;
  c.time = {.end = 10.0, .step = 1.0, .mode = mode};
  c.time.spin_up_step = 5.0;
  c.time.steady_method = SteadyMethod::march;
  c.output.interval = 4.0;  // outputs at 0, 4, 8 and the end 10 s
  test::add_colliding_logs_and_release(c, 8.0);
  return c;
}

std::string text_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct SharedFlowCase {
  CouplingMode mode;
  FlowEngineKind engine;
  const char* name;
};

/// The flow fields of two runs replaying one shared flow: the first wrote each output's file and
/// shared it, the second linked it (one file, two names, the shared one removed since); both
/// are the bytes the run computing its own flow wrote.
void expect_flow_fields_linked(const fs::path& own, const fs::path& first, const fs::path& second) {
  const std::vector<std::string> files = {"flow_000000.vtu", "flow_000001.vtu", "flow_000002.vtu",
                                          "flow_000003.vtu"};  // outputs at 0, 4, 8, 10 s
  for (const std::string& file : files) {
    const std::string written = text_of(own / file);
    ASSERT_GT(written.size(), 1000u) << file;
    EXPECT_EQ(text_of(first / file), written) << file;
    EXPECT_EQ(text_of(second / file), written) << file;
    EXPECT_TRUE(fs::equivalent(first / file, second / file)) << file;
    EXPECT_EQ(fs::hard_link_count(second / file), 2u) << file;
    EXPECT_EQ(fs::hard_link_count(own / file), 1u) << file;
  }
  EXPECT_FALSE(fs::exists(own / "flow_000004.vtu"));
}

class SharedFlow : public testing::TestWithParam<SharedFlowCase> {};

TEST_P(SharedFlow, ReplayedFlowMovesTheBodiesAsTheComputedFlowBitForBit) {
  const SharedFlowCase p = GetParam();
  const fs::path base = test::scratch_path(std::string("flotsam_shared_flow_test_") + p.name);
  fs::remove_all(base);
  fs::create_directories(base);
  const Mesh mesh = make_rectangle_mesh({.length = 200, .width = 20, .nx = 40, .ny = 8});
  const Case run_case = shared_case(p.mode, p.engine);
  record_shared_flow(run_case, mesh, (base / "flow.bin").string(), true);

  Simulation own(run_case, mesh,
                 {.output_directory = base / "own", .write_output = true, .progress = false});
  own.run();
  Simulation replay(run_case, mesh,
                    {.output_directory = base / "replay",
                     .write_output = true,
                     .progress = false,
                     .shared_flow = base / "flow.bin"});
  replay.run();
  Simulation(run_case, mesh,
             {.output_directory = base / "second",
              .write_output = true,
              .progress = false,
              .shared_flow = base / "flow.bin"})
      .run();
  remove_shared_flow(base / "flow.bin");
  EXPECT_FALSE(fs::exists(base / "flow.bin"));
  EXPECT_FALSE(fs::exists(shared_fields_folder(base / "flow.bin")));

  ASSERT_EQ(own.bodies().size(), replay.bodies().size());
  ASSERT_GE(own.bodies().size(), 6);  // three placed, at least three released
  for (int i = 0; i < own.bodies().size(); ++i) {
    EXPECT_EQ(own.bodies().position[i].x(), replay.bodies().position[i].x()) << "body " << i;
    EXPECT_EQ(own.bodies().position[i].y(), replay.bodies().position[i].y()) << "body " << i;
    EXPECT_EQ(own.bodies().angle[i], replay.bodies().angle[i]) << "body " << i;
  }
  EXPECT_EQ(own.flow().eta(), replay.flow().eta());
  EXPECT_EQ(own.flow().water_balance().volume, replay.flow().water_balance().volume);
  EXPECT_EQ(own.time(), replay.time());
  // What the runs wrote: the body tracks and the checkpoint (a restart continues either).
  for (const char* file : {"shared_bodies.csv", "checkpoint.bin"})
    EXPECT_EQ(text_of(base / "own" / file), text_of(base / "replay" / file)) << file;
  expect_flow_fields_linked(base / "own", base / "replay", base / "second");
}

INSTANTIATE_TEST_SUITE_P(
    ModesAndEngines, SharedFlow,
    testing::Values(SharedFlowCase{CouplingMode::one_way, FlowEngineKind::fv, "one_way_fv"},
                    SharedFlowCase{CouplingMode::one_way, FlowEngineKind::fem, "one_way_fem"},
                    SharedFlowCase{CouplingMode::frozen, FlowEngineKind::fv, "frozen_fv"}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(SharedFlowFile, RecordedForOtherTimesIsRefused) {
  const fs::path base = test::scratch_path("flotsam_shared_flow_test_refused");
  fs::remove_all(base);
  fs::create_directories(base);
  const Mesh mesh = make_rectangle_mesh({.length = 200, .width = 20, .nx = 40, .ny = 8});
  Case recorded = shared_case(CouplingMode::one_way, FlowEngineKind::fv);
  record_shared_flow(recorded, mesh, (base / "flow.bin").string(), true);
  Case longer = recorded;
  longer.time.end = 12.0;
  Simulation run(longer, mesh,
                 {.output_directory = base / "run",
                  .write_output = true,
                  .progress = false,
                  .shared_flow = base / "flow.bin"});
  EXPECT_THROW(run.initialize(), RunError);
  Case two_way = recorded;
  two_way.time.mode = CouplingMode::two_way;
  EXPECT_THROW(record_shared_flow(two_way, mesh, (base / "two_way.bin").string(), true), RunError);
}

}  // namespace
}  // namespace flotsam
