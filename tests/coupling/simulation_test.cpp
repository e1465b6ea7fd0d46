// Tests of the coupled run (src/coupling/simulation.cpp) on a straight frictionless channel whose
// steady flow is exactly uniform: u = Q / (W H0), eta = H0.
#include "coupling/simulation.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../support/scratch_path.hpp"
#include "../support/straight_channel.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

constexpr double length = 200.0;  // [m]
constexpr double width = 20.0;    // [m]
constexpr double H0 = 2.0;        // [m]
constexpr double Q = 40.0;        // [m^3/s]: U = Q / (W H0) = 1 m/s
constexpr double U = Q / (width * H0);

Mesh channel_mesh() {
  return make_rectangle_mesh({.length = length, .width = width, .nx = 20, .ny = 4});
}

Case channel_case(CouplingMode mode) {
  Case c = test::straight_channel_case("channel", Q, H0);
  c.flow.viscosity = 1e-6;
  c.time.mode = mode;
  c.time.step = 1.0;
  c.time.end = 60.0;
  c.bodies.physics.drag_law = DragLaw::constant;
  c.bodies.physics.drag_coefficient = 1.0;
  BodySpec log;
  log.length = 4.0;
  log.width = 0.4;
  log.position = Vec2(30.0, 10.0);
  log.angle = pi / 2;  // broadside
  c.bodies.bodies = {log};
  return c;
}

RunOptions quiet() {
  return {.output_directory = {}, .overwrite = false, .write_output = false, .progress = false};
}

TEST(Simulation, FrozenFlowCarriesALogDownstreamAtTheFlowSpeed) {
  Simulation s(channel_case(CouplingMode::frozen), channel_mesh(), quiet());
  s.run();
  // The steady flow is uniform (frictionless, discharge in, elevation out).
  for (int n = 0; n < s.flow().mesh().node_count(); ++n) {
    ASSERT_NEAR(s.flow().u()[n], U, 1e-6 * U) << "node " << n;
    ASSERT_NEAR(s.flow().v()[n], 0.0, 1e-6 * U) << "node " << n;
  }
  // A broadside log released at rest relaxes to U: du/dt = k (U - u)^2 gives U - u = U / (1 +
  // k U t); after 60 s it is within a few percent and has moved downstream.
  const BodySet& b = s.bodies();
  EXPECT_GT(b.velocity[0].x(), 0.95 * U);
  EXPECT_LT(b.velocity[0].x(), U * (1 + 1e-9));
  EXPECT_NEAR(b.velocity[0].y(), 0.0, 1e-9);
  EXPECT_GT(b.position[0].x(), 30.0 + 0.8 * U * 60.0);
  EXPECT_NEAR(b.position[0].y(), 10.0, 1e-9);
}

// time.steady_method: march skips the steady solve and marches the default characteristics
// scheme (time.spin_up_step, 20 s) until u changes by less than 1e-5 of its largest value in a
// step: the same uniform flow, to what that stopping rule leaves (measured 4.7e-6 U; limit 5e-5
// U). Newton's state is uniform to its own tolerance (measured 2.9e-9 U), so an error above
// 1e-7 U shows the flow was marched.
TEST(Simulation, FrozenFlowByMarchingIsTheUniformFlowToo) {
  Case c = channel_case(CouplingMode::frozen);
  c.time.steady_method = SteadyMethod::march;
  c.bodies.bodies.clear();
  Simulation s(c, channel_mesh(), quiet());
  s.initialize();
  double worst = 0.0;  // [m/s]
  for (int n = 0; n < s.flow().mesh().node_count(); ++n)
    worst = std::max({worst, std::abs(s.flow().u()[n] - U), std::abs(s.flow().v()[n])});
  EXPECT_LE(worst, 5e-5 * U);
  EXPECT_GT(worst, 1e-7 * U);
  EXPECT_EQ(s.flow().time(), 0.0);  // the frozen flow starts the run at t = 0
}

TEST(Simulation, ALogReachingTheOutflowLeavesAndIsCounted) {
  Case c = channel_case(CouplingMode::frozen);
  c.bodies.bodies[0].position = Vec2(190.0, 10.0);
  c.bodies.bodies[0].velocity = Vec2(U, 0.0);
  Simulation s(std::move(c), channel_mesh(), quiet());
  s.run();
  EXPECT_EQ(s.bodies().outflow_count, 1);
  EXPECT_EQ(s.bodies().state[0], BodyState::gone);
}

TEST(Simulation, TwoWayRunKeepsTheWaterBalance) {
  Case c = channel_case(CouplingMode::two_way);
  c.time.end = 20.0;
  Simulation s(std::move(c), channel_mesh(), quiet());
  s.run();
  EXPECT_LT(std::abs(s.flow().water_balance().relative_error()), 1e-9);
  EXPECT_GT(s.bodies().position[0].x(), 30.0);
}

/// Six cars parked in a zone of the channel at the start (a count), as a case file gives them.
Case parked_cars_case(std::vector<Vec2> zone) {
  Case c = channel_case(CouplingMode::frozen);
  c.file = "case.yaml";
  c.bodies.bodies.clear();
  Release cars;
  cars.zone = std::move(zone);
  cars.count = 6;
  cars.shape = Shape::box;
  cars.length_min = cars.length_max = 4.0;
  cars.width_min = cars.width_max = 1.7;
  cars.height = 1.5;
  cars.density_min = cars.density_max = 300.0;
  cars.source_line = 14;
  c.bodies.releases = {cars};
  return c;
}

TEST(Simulation, CarsParkedInAZoneAreReleasedInTheFirstStep) {
  Simulation s(parked_cars_case({{20, 2}, {60, 2}, {60, 18}, {20, 18}}), channel_mesh(), quiet());
  s.initialize();
  EXPECT_EQ(s.bodies().size(), 0);
  s.step();
  ASSERT_EQ(s.bodies().size(), 6);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(s.bodies().shape[i], Shape::box);
}

TEST(Simulation, AZoneOutsideTheDomainIsAnErrorNamingItsLineAndCorner) {
  Simulation s(parked_cars_case({{180, 2}, {250, 2}, {180, 18}}), channel_mesh(), quiet());
  try {
    s.initialize();
    FAIL() << "a zone reaching beyond the outflow was accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "case.yaml:14: bodies.release[0].zone: corner 2 at (250, 2) m is outside the "
                 "domain; a zone's corners must lie in the mesh");
  }
}

TEST(Simulation, WritesOneSnapshotPerIntervalAndRefusesToOverwrite) {
  const auto dir = test::scratch_path("flotsam_simulation_test");
  std::filesystem::remove_all(dir);
  Case c = channel_case(CouplingMode::frozen);
  c.time.end = 10.0;
  c.output.interval = 4.0;  // outputs at 0, 4, 8 and the end, 10
  {
    Simulation s(
        c, channel_mesh(),
        {.output_directory = dir, .overwrite = false, .write_output = true, .progress = false});
    s.run();
  }
  int vtu = 0, vtp = 0;
  for (const auto& f : std::filesystem::directory_iterator(dir)) {
    vtu += f.path().extension() == ".vtu";
    vtp += f.path().extension() == ".vtp" && f.path().stem().string().starts_with("bodies_");
  }
  EXPECT_EQ(vtu, 4);
  EXPECT_EQ(vtp, 4);
  std::ifstream csv(dir / "channel_bodies.csv");
  int lines = 0;
  std::string last;
  for (std::string line; std::getline(csv, line);) ++lines, last = line;
  EXPECT_EQ(lines, 1 + 4);                       // header + one body at four times
  EXPECT_TRUE(last.starts_with("10,")) << last;  // the run's time, though the flow is frozen
  Simulation again(
      c, channel_mesh(),
      {.output_directory = dir, .overwrite = false, .write_output = true, .progress = false});
  try {
    again.initialize();
    FAIL() << "an existing output folder was overwritten without --overwrite";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("exists and is not empty"));
  }
  std::filesystem::remove_all(dir);
}

// Runs `c` on the channel mesh for its whole time, writing into `dir`; returns the summary.
std::string run_writing(const Case& c, const std::filesystem::path& dir) {
  Simulation s(
      c, channel_mesh(),
      {.output_directory = dir, .overwrite = true, .write_output = true, .progress = false});
  s.run();
  return s.summary();
}

// The balance table a run wrote in `dir`: its header and its last row.
struct BalanceTable {
  std::string header;
  std::vector<double> last;
};
BalanceTable balance_table(const std::filesystem::path& dir) {
  std::ifstream csv(dir / "channel_balance.csv");
  BalanceTable table;
  std::string line, last;
  std::getline(csv, table.header);
  while (std::getline(csv, line)) last = line;
  std::stringstream fields(last);
  for (std::string field; std::getline(fields, field, ',');) table.last.push_back(std::stod(field));
  return table;
}

// The channel closed by walls all round, without bodies, on the finite-volume engine, 10 s with
// an output every 5 s.
Case closed_fv_channel() {
  Case c = channel_case(CouplingMode::one_way);
  c.bodies.bodies.clear();
  c.flow.engine = FlowEngineKind::fv;
  for (BoundaryCondition& b : c.flow.boundaries)
    b = {BoundaryCondition::Kind::wall, b.group, {}, {}};
  c.time.end = 10.0;
  c.output.interval = 5.0;
  return c;
}

// The balance table carries the volume out through each open group: in the unsteady channel
// (discharge Q in at the left, elevation held at the right) the left's column is -Q t exactly
// (the discharge is imposed), and the groups' columns add up to the total outflow.
TEST(Simulation, BalanceTableHasTheOutflowOfEachOpenGroup) {
  const auto dir = test::fresh_test_folder("flotsam_simulation_test");
  Case c = channel_case(CouplingMode::one_way);
  c.bodies.bodies.clear();
  c.time.end = 10.0;
  c.output.interval = 5.0;
  const std::string summary = run_writing(c, dir);
  const BalanceTable table = balance_table(dir);
  EXPECT_EQ(table.header,
            "t [s],volume [m^3],outflow [m^3],balance error [m^3],relative error [-],"
            "outflow left [m^3],outflow right [m^3]");
  // The summary's self-check: each open group's discharge in the last step (the left's is -Q,
  // imposed) and their sum; the FEM's relative change of u in the last step, in (0, 1) while
  // the channel still fills.
  double left = 0.0, right = 0.0, sum = 0.0, change = -1.0;
  const auto line = summary.find("discharges out   in the last step:");
  ASSERT_NE(line, std::string::npos) << summary;
  ASSERT_EQ(std::sscanf(summary.c_str() + line,
                        "discharges out   in the last step: left %lf, right %lf, in all %lf", &left,
                        &right, &sum),
            3)
      << summary;
  EXPECT_NEAR(left, -Q, 1e-4 * Q);  // printed to 4 digits
  EXPECT_NEAR(sum, left + right, 2e-4 * Q);
  const auto fem = summary.find("the last step changed u by ");
  ASSERT_NE(fem, std::string::npos) << summary;
  ASSERT_EQ(std::sscanf(summary.c_str() + fem, "the last step changed u by %lf", &change), 1);
  EXPECT_GT(change, 0.0);
  EXPECT_LT(change, 1.0);
  const std::vector<double>& row = table.last;
  ASSERT_EQ(row.size(), 7u);
  EXPECT_EQ(row[0], 10.0);
  EXPECT_NEAR(row[5], -Q * 10.0, 1e-6 * Q * 10.0);        // CSV precision: 9 digits
  EXPECT_NEAR(row[5] + row[6], row[2], 1e-6 * Q * 10.0);  // the total
  std::filesystem::remove_all(dir);
}

// A case with rain (finite-volume engine) has the rain and infiltration columns: on a closed flat
// basin the rain column is i t A exactly (to the CSV's 9 digits), the infiltration f t A, and the
// volume gained their difference; the summary names both.
TEST(Simulation, BalanceTableHasTheRainAndTheInfiltration) {
  const auto dir = test::fresh_test_folder("flotsam_simulation_test");
  Case c = closed_fv_channel();
  c.flow.rain.enabled = true;
  c.flow.rain.intensity = TimeSeries(360.0);  // [mm/h] = 1e-4 m/s
  c.flow.rain.infiltration = 36.0;            // [mm/h] = 1e-5 m/s
  const std::string summary = run_writing(c, dir);
  const BalanceTable table = balance_table(dir);
  EXPECT_EQ(table.header,
            "t [s],volume [m^3],outflow [m^3],rain [m^3],infiltration [m^3],balance error [m^3],"
            "relative error [-]");
  const std::vector<double>& row = table.last;
  ASSERT_EQ(row.size(), 7u);
  const double area = length * width, rain = 1e-4 * 10.0 * area, lost = 1e-5 * 10.0 * area;
  EXPECT_EQ(row[0], 10.0);
  EXPECT_NEAR(row[3], rain, 1e-8 * rain);
  EXPECT_NEAR(row[4], lost, 1e-8 * rain);
  EXPECT_NEAR(row[1], H0 * area + rain - lost, 1e-8 * H0 * area);
  EXPECT_LE(std::abs(row[6]), 1e-12);
  EXPECT_THAT(summary, ::testing::HasSubstr("rain 4 m^3, infiltrated 0.4 m^3"));
  std::filesystem::remove_all(dir);
}

// A case with sources (finite-volume engine) has their column: in a closed channel a point
// source of 2 m^3/s has let in 20 m^3 after 10 s, all of it in the volume; the summary names it.
TEST(Simulation, BalanceTableHasTheSources) {
  const auto dir = test::fresh_test_folder("flotsam_simulation_test");
  Case c = closed_fv_channel();
  FlowSource culvert;
  culvert.point = Vec2(0.3 * length, 0.5 * width);
  culvert.discharge = TimeSeries(2.0);  // [m^3/s]
  culvert.origin = "test: flow.sources[0]";
  c.flow.sources = {culvert};
  const std::string summary = run_writing(c, dir);
  const BalanceTable table = balance_table(dir);
  EXPECT_EQ(
      table.header,
      "t [s],volume [m^3],outflow [m^3],sources [m^3],balance error [m^3],relative error [-]");
  const std::vector<double>& row = table.last;
  ASSERT_EQ(row.size(), 6u);
  EXPECT_EQ(row[0], 10.0);
  EXPECT_NEAR(row[3], 20.0, 1e-8 * 20.0);
  EXPECT_NEAR(row[1], H0 * length * width + 20.0, 1e-8 * H0 * length * width);
  EXPECT_LE(std::abs(row[5]), 1e-12);
  EXPECT_THAT(summary, ::testing::HasSubstr("sources 20 m^3"));
  std::filesystem::remove_all(dir);
}

// Gauges (output.probes) on a run of the finite-volume engine: a row at t = 0 and at every
// coupling step, and the last row is what the engine's field gives at the probe at the end (to
// the CSV's 9 digits).
TEST(Simulation, ProbesWriteARowPerStepWithTheEnginesValues) {
  const auto dir = test::fresh_test_folder("flotsam_simulation_test");
  Case c = channel_case(CouplingMode::one_way);
  c.bodies.bodies.clear();
  c.flow.engine = FlowEngineKind::fv;
  c.time.end = 5.0;
  c.output.probes = {{"mid", Vec2(100.0, 10.0), 0}, {"inlet", Vec2(5.0, 3.0), 0}};
  Simulation s(
      c, channel_mesh(),
      {.output_directory = dir, .overwrite = true, .write_output = true, .progress = false});
  s.run();
  std::ifstream csv(dir / "channel_probes.csv");
  std::string header, line, last;
  std::getline(csv, header);
  EXPECT_EQ(header,
            "t [s],mid_eta [m],mid_H [m],mid_u [m/s],mid_v [m/s],inlet_eta [m],inlet_H [m],"
            "inlet_u [m/s],inlet_v [m/s]");
  int rows = 0;
  while (std::getline(csv, line)) ++rows, last = line;
  EXPECT_EQ(rows, 6);  // t = 0, 1, ..., 5
  std::vector<double> row;
  std::stringstream fields(last);
  for (std::string field; std::getline(fields, field, ',');) row.push_back(std::stod(field));
  ASSERT_EQ(row.size(), 9u);
  EXPECT_EQ(row[0], 5.0);
  const FlowEngine& flow = s.flow();
  for (int k = 0; k < 2; ++k) {
    int hint = -1;
    const FlowSample at = flow.field().sample(c.output.probes[k].position, 5.0, hint);
    EXPECT_NEAR(row[1 + 4 * k], at.eta, 1e-8 * std::abs(at.eta)) << c.output.probes[k].name;
    EXPECT_NEAR(row[2 + 4 * k], at.H, 1e-8 * at.H) << c.output.probes[k].name;
    EXPECT_NEAR(row[3 + 4 * k], at.u.x(), 1e-8 + 1e-8 * std::abs(at.u.x()));
  }
  EXPECT_GT(row[7], 0.5);  // the inflow has reached the inlet's gauge
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace flotsam

namespace flotsam {
namespace {

// A gauge outside the domain is refused before the run writes anything: no boundary.vtp, no
// header-only tables, no run.bin are left behind (the folder stays empty).
TEST(Simulation, AGaugeOutsideTheDomainIsRefusedBeforeAnyOutput) {
  const auto dir = test::fresh_test_folder("flotsam_simulation_test");
  Case c = channel_case(CouplingMode::frozen);
  c.output.probes = {{.name = "in_a_pier", .position = Vec2(-5.0, 1.0), .line = 31}};
  Simulation s(
      c, channel_mesh(),
      {.output_directory = dir, .overwrite = true, .write_output = true, .progress = false});
  try {
    s.initialize();
    FAIL() << "a gauge outside the domain was accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("probe 'in_a_pier' at (-5, 1) m is outside"));
  }
  EXPECT_TRUE(!std::filesystem::exists(dir) || std::filesystem::is_empty(dir));
  std::filesystem::remove_all(dir);
}

// Envelope rasters too fine to fit in memory (1e-5 m pixels over the 200 m x 20 m channel: 4e13
// pixels) are refused before the run writes anything, naming the key and the size, instead of
// stopping with std::bad_alloc after the first outputs.
TEST(Simulation, EnvelopeRastersLargerThanMemoryAreRefusedBeforeAnyOutput) {
  const auto dir = test::fresh_test_folder("flotsam_simulation_test");
  Case c = channel_case(CouplingMode::one_way);
  c.bodies.bodies.clear();
  c.flow.engine = FlowEngineKind::fv;
  c.file = "river.yaml";
  c.output.raster_resolution = 1e-5;  // [m]
  Simulation s(
      c, channel_mesh(),
      {.output_directory = dir, .overwrite = true, .write_output = true, .progress = false});
  try {
    s.initialize();
    FAIL() << "rasters of 4e13 pixels were accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::StartsWith("river.yaml: output.rasters.resolution: 1e-05 m "
                                                "over the mesh (200 m x 20 m) gives 4e+13 pixels"));
  }
  EXPECT_TRUE(!std::filesystem::exists(dir) || std::filesystem::is_empty(dir));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace flotsam
