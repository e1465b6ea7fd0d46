// Verifies that case files are read into the exact values they give (the two examples, the
// defaults), and that every kind of bad input is an InputError naming the file, the line, the
// key path and what was expected.
#include "io/case_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../support/case_error.hpp"
#include "../support/scratch_path.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"
#include "geo/vector_layer.hpp"
#include "mesh/mesh_generator.hpp"
#include "mesh/point_locator.hpp"

namespace flotsam {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

const std::string examples = std::string(FLOTSAM_SOURCE_DIR) + "/examples/";

// A minimal valid case; tests edit one line of it, so the line numbers below stay true.
const std::string base_case = R"(mesh:
  channel: {length: 100, width: 20}
flow:
  friction: {law: manning, coefficient: 0.03}
  initial: {eta: 1.0}
  boundaries:
    inflow: {type: elevation, value: 1.0}
    outflow: {type: elevation, value: 0.9}
    bank_right: {type: wall}
    bank_left: {type: wall}
time: {end: 10, step: 0.5}
)";

// base_case with `from` replaced by `to` (`from` must occur).
std::string edited(const std::string& from, const std::string& to) {
  return test::replaced(base_case, from, to);
}

// base_case with `extra` appended (it starts on line 12).
std::string appended(const std::string& extra) {
  return base_case + extra;
}

using test::error_of;  // tests/support/case_error.hpp

double degrees(double deg) {
  return deg * pi / 180.0;
}

const std::vector<std::string> channel_groups = {"inflow", "outflow", "bank_right", "bank_left",
                                                 "pier_1", "pier_2",  "pier_3",     "pier_4"};

// ---- the examples -------------------------------------------------------------------------

TEST(CaseFile, BridgePiersExampleHoldsThePapersChannel) {
  const Case c = read_case(examples + "bridge_piers.yaml");
  EXPECT_EQ(c.name, "bridge_piers");
  ASSERT_EQ(c.mesh.kind, MeshSource::Kind::channel);
  EXPECT_EQ(c.mesh.channel.length, 1500.0);
  EXPECT_EQ(c.mesh.channel.width, 170.0);
  ASSERT_EQ(c.mesh.channel.piers.size(), 4u);
  EXPECT_EQ(c.mesh.channel.piers[2].centre, Vec2(900.0, 42.5));  // pier 3
  EXPECT_EQ(c.mesh.channel.piers[1].centre, Vec2(600.0, 127.5));
  for (const Pier& p : c.mesh.channel.piers) EXPECT_EQ(p.radius, 30.0);
  EXPECT_EQ(c.bed.kind, BedConfig::Kind::flat);
  EXPECT_EQ(c.bed.level, 0.0);

  EXPECT_EQ(c.flow.water_density, 1000.0);
  EXPECT_EQ(c.flow.friction, FrictionLaw::manning);
  EXPECT_EQ(c.flow.friction_coefficient, 0.03);
  EXPECT_NEAR(c.flow.viscosity, 0.5 * 60.0 / 1000.0, 1e-15);  // nu = U D / Re
  EXPECT_EQ(c.flow.initial_eta_start, 10.0);
  EXPECT_EQ(c.flow.initial_eta_end, 9.80);
  ASSERT_EQ(c.flow.boundaries.size(), 8u);
  EXPECT_EQ(c.flow.boundaries[0].group, "inflow");
  EXPECT_EQ(c.flow.boundaries[0].kind, BoundaryCondition::Kind::elevation);
  EXPECT_EQ(c.flow.boundaries[0].value(0.0), 10.0);
  EXPECT_EQ(c.flow.boundaries[1].group, "outflow");
  EXPECT_EQ(c.flow.boundaries[1].value(1e3), 9.80);
  for (std::size_t i = 2; i < 8; ++i)
    EXPECT_EQ(c.flow.boundaries[i].kind, BoundaryCondition::Kind::wall) << i;
  EXPECT_NO_THROW(check_case_against_mesh(c, channel_groups));

  EXPECT_EQ(c.time.end, 1800.0);
  EXPECT_EQ(c.time.step, 1.0);
  EXPECT_EQ(c.time.mode, CouplingMode::two_way);
  EXPECT_EQ(c.bodies.contact.restitution, 1.0);
  ASSERT_EQ(c.bodies.bodies.size(), 7u);
  for (const BodySpec& b : c.bodies.bodies) {
    EXPECT_EQ(b.shape, Shape::log);
    EXPECT_EQ(b.length, 20.0);
    EXPECT_EQ(b.width, 1.0);
    EXPECT_EQ(b.height, 1.0);  // a log's height is its diameter
    EXPECT_EQ(b.velocity, Vec2::Zero());
    EXPECT_EQ(b.angular_velocity, 0.0);
    EXPECT_GE(b.position.x(), 300.0);
    EXPECT_LE(b.position.x(), 500.0);
  }
  EXPECT_EQ(c.bodies.bodies[0].position, Vec2(320.0, 30.0));
  EXPECT_DOUBLE_EQ(c.bodies.bodies[0].angle, degrees(15.0));
  EXPECT_DOUBLE_EQ(c.bodies.bodies[5].angle, degrees(135.0));
  EXPECT_EQ(c.output.directory, "out");
  EXPECT_EQ(c.output.interval, 60.0);
}

TEST(CaseFile, Bend180ExampleHoldsRozovskiisFlume) {
  const Case c = read_case(examples + "bend180.yaml");
  EXPECT_EQ(c.name, "bend180");
  ASSERT_EQ(c.mesh.kind, MeshSource::Kind::bend);
  EXPECT_EQ(c.mesh.bend.centre, Vec2::Zero());
  EXPECT_EQ(c.mesh.bend.width, 0.8);
  EXPECT_EQ(c.mesh.bend.inner_radius, 0.4);
  EXPECT_EQ(c.mesh.bend.inlet_length, 3.0);
  EXPECT_EQ(c.mesh.bend.outlet_length, 3.0);
  EXPECT_EQ(c.flow.friction, FrictionLaw::manning);
  EXPECT_EQ(c.flow.friction_coefficient, 0.012);
  EXPECT_EQ(c.flow.turbulence, TurbulenceModel::mixing_length);
  EXPECT_EQ(c.flow.viscosity, 1e-6);
  EXPECT_EQ(c.flow.initial_eta_start, 0.058);
  EXPECT_EQ(c.flow.initial_eta_end, 0.058);
  ASSERT_EQ(c.flow.boundaries.size(), 4u);
  EXPECT_EQ(c.flow.boundaries[0].kind, BoundaryCondition::Kind::discharge);
  EXPECT_EQ(c.flow.boundaries[0].value(10.0), 0.0123);
  EXPECT_EQ(c.flow.boundaries[1].kind, BoundaryCondition::Kind::elevation);
  EXPECT_EQ(c.flow.boundaries[1].value(10.0), 0.058);
  EXPECT_NO_THROW(check_case_against_mesh(c, {"inflow", "outflow", "bank_inner", "bank_outer"}));
  EXPECT_EQ(c.time.end, 120.0);
  EXPECT_EQ(c.time.mode, CouplingMode::one_way);
  ASSERT_EQ(c.bodies.bodies.size(), 4u);
  for (const BodySpec& b : c.bodies.bodies) {
    EXPECT_EQ(b.length, 0.2);
    EXPECT_EQ(b.width, 0.02);
    // Inside the inlet reach x in [0, 3], y in [0.4, 1.2] with the whole log.
    EXPECT_GT(b.position.x() - 0.1, 0.0);
    EXPECT_LT(b.position.x() + 0.1, 3.0);
    EXPECT_GT(b.position.y() - 0.1, 0.4);
    EXPECT_LT(b.position.y() + 0.1, 1.2);
  }
}

TEST(CaseFile, BridgeFloodExampleReleasesFiveHundredLogs) {
  const Case c = read_case(examples + "bridge_flood.yaml");
  EXPECT_EQ(c.name, "bridge_flood");
  ASSERT_EQ(c.mesh.channel.piers.size(), 4u);
  EXPECT_TRUE(c.bodies.bodies.empty());
  ASSERT_EQ(c.bodies.releases.size(), 1u);
  const Release& r = c.bodies.releases[0];
  // Release times start + k 60/rate <= end: 50 per minute over 10 minutes.
  EXPECT_EQ(std::floor((r.end_time - r.start_time) * r.rate / 60.0) + 1, 500.0);
  EXPECT_EQ(r.length_min, 5.0);
  EXPECT_EQ(r.length_max, 25.0);
  EXPECT_EQ(r.line_start, Vec2(100, 15));
  EXPECT_EQ(r.line_end, Vec2(100, 155));
  EXPECT_EQ(c.bodies.contact.restitution, 0.3);
}

TEST(CaseFile, DocumentationExampleParses) {
  std::ifstream in(std::string(FLOTSAM_SOURCE_DIR) + "/docs/case-format.md");
  std::ostringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const auto section = doc.find("## Complete example");
  ASSERT_NE(section, std::string::npos);
  const auto begin = doc.find("```yaml\n", section) + 8;
  const auto end = doc.find("\n```", begin);
  const Case c = parse_case(doc.substr(begin, end - begin + 1), "case-format.yaml");
  EXPECT_EQ(c.name, "reach_with_bridge");
  EXPECT_NEAR(c.flow.viscosity, 1.0 * 10.0 / 1000.0, 1e-15);
  EXPECT_EQ(c.bed.slope, Vec2(0.0005, 0.0));
  EXPECT_DOUBLE_EQ(c.flow.boundaries[0].value(300.0), 325.0);  // halfway up the flood wave
  EXPECT_EQ(c.flow.boundaries[3].kind, BoundaryCondition::Kind::noslip);
  EXPECT_EQ(c.bodies.bodies.size(), 2u);
  EXPECT_EQ(c.bodies.releases.size(), 1u);
  EXPECT_EQ(c.bodies.contact.restitution, 0.3);
  EXPECT_EQ(c.bodies.contact.restitution_threshold, 0.01);
  EXPECT_EQ(c.bodies.contact.position_iterations, 10);
  EXPECT_EQ(c.bodies.contact.allowed_overlap, 0.005);
  EXPECT_EQ(c.time.scheme, TimeScheme::theta);
  EXPECT_EQ(c.time.theta, 0.6);
  EXPECT_EQ(c.time.origin.text(), "1970-01-01 00:00:00");
  EXPECT_EQ(c.flow.engine, FlowEngineKind::fem);
  ASSERT_EQ(c.output.probes.size(), 2u);
  EXPECT_EQ(c.output.probes[1].name, "bridge");
  EXPECT_EQ(c.output.probes[1].position, Vec2(400.0, 50.0));
  EXPECT_EQ(c.output.probe_interval, 5.0);
  EXPECT_NO_THROW(check_case_against_mesh(
      c, {"inflow", "outflow", "bank_right", "bank_left", "pier_1", "pier_2"}));
}

// The examples' boundary names are the generator's, and every body lies wholly in the water.
void expect_case_fits_its_mesh(const Case& c) {
  const Mesh mesh = generate_mesh(c.mesh);
  EXPECT_NO_THROW(check_case_against_mesh(c, mesh.group_names));
  const PointLocator locator(mesh);
  for (const BodySpec& b : c.bodies.bodies) {
    const Vec2 along = 0.5 * b.length * Vec2(std::cos(b.angle), std::sin(b.angle));
    const Vec2 across = 0.5 * b.width * Vec2(-std::sin(b.angle), std::cos(b.angle));
    for (const Vec2& corner :
         {Vec2(b.position + along + across), Vec2(b.position + along - across),
          Vec2(b.position - along + across), Vec2(b.position - along - across)})
      EXPECT_TRUE(locator.locate(corner).inside) << "body at " << b.position.transpose();
  }
}

TEST(CaseFile, ExamplesFitTheirGeneratedMeshes) {
  expect_case_fits_its_mesh(read_case(examples + "bridge_piers.yaml"));
  expect_case_fits_its_mesh(read_case(examples + "bend180.yaml"));
  expect_case_fits_its_mesh(read_case(examples + "bridge_flood.yaml"));
}

// ---- values and defaults ------------------------------------------------------------------

TEST(CaseFile, DefaultsAreTheSpecs) {
  const Case c = parse_case(base_case, "cases/river.yaml");
  EXPECT_EQ(c.file, "cases/river.yaml");
  EXPECT_EQ(c.name, "river");  // the file's stem
  EXPECT_EQ(c.mesh.channel.piers.size(), 0u);
  EXPECT_EQ(c.bed.kind, BedConfig::Kind::flat);
  EXPECT_EQ(c.flow.gravity, 9.81);
  EXPECT_EQ(c.flow.water_density, 1000.0);
  EXPECT_EQ(c.flow.viscosity, 1e-6);
  EXPECT_EQ(c.flow.turbulence, TurbulenceModel::none);
  EXPECT_FALSE(c.flow.coriolis);
  EXPECT_EQ(c.flow.wind, Vec2::Zero());
  EXPECT_EQ(c.flow.min_depth, 1e-3);
  EXPECT_EQ(c.time.mode, CouplingMode::two_way);
  EXPECT_EQ(c.time.steady_method, SteadyMethod::solve);
  EXPECT_EQ(parse_case(edited("step: 0.5}", "step: 0.5, steady_method: march}"), "case.yaml")
                .time.steady_method,
            SteadyMethod::march);
  EXPECT_EQ(c.bodies.physics.drag_law, DragLaw::ganser);
  EXPECT_EQ(c.bodies.physics.added_mass_coefficient, 0.5);
  EXPECT_EQ(c.bodies.physics.drag_points, 1);
  EXPECT_EQ(c.bodies.contact.restitution, 1.0);
  EXPECT_EQ(c.bodies.contact.friction, 0.5);
  EXPECT_TRUE(c.bodies.bodies.empty());
  EXPECT_EQ(c.output.directory, "out");
  EXPECT_EQ(c.output.interval, 60.0);
  EXPECT_FALSE(c.output.overwrite);
}

TEST(CaseFile, TablesBecomeTimeSeries) {
  const Case c =
      parse_case(edited("value: 1.0}", "value: [[0, 1.0], [60, 1.2], [120, 1.1]]}"), "case.yaml");
  const TimeSeries& eta = c.flow.boundaries[0].value;
  EXPECT_DOUBLE_EQ(eta(30.0), 1.1);
  EXPECT_DOUBLE_EQ(eta(90.0), 1.15);
  EXPECT_EQ(eta(500.0), 1.1);
}

// A table from a CSV file beside the case (docs/case-format.md "Tables from files"): the same
// series as written inline, the file one of the case's inputs (fingerprinted for restarts).
TEST(CaseFile, TablesFromFilesBecomeTimeSeries) {
  const auto dir = test::fresh_test_folder("flotsam_case_table_file");
  std::ofstream(dir / "eta.csv") << "t [s],eta [m]\n0,1.0\n60,1.2\n120,1.1\n";
  const std::string case_path = (dir / "case.yaml").string();
  const Case c = parse_case(edited("value: 1.0}", "value: {file: eta.csv}}"), case_path);
  const TimeSeries& eta = c.flow.boundaries[0].value;
  EXPECT_DOUBLE_EQ(eta(30.0), 1.1);
  EXPECT_DOUBLE_EQ(eta(90.0), 1.15);
  EXPECT_EQ(eta(500.0), 1.1);
  ASSERT_EQ(c.input_files.size(), 1u);
  EXPECT_EQ(c.input_files[0].key, "flow.boundaries.inflow.value.file");
  EXPECT_EQ(c.input_files[0].path, (dir / "eta.csv").string());
  std::ofstream(dir / "eta.csv") << "t [s],eta [m]\n0,1.0\n0,1.2\n";
  EXPECT_EQ(error_of(edited("value: 1.0}", "value: {file: eta.csv}}"), case_path),
            (dir / "eta.csv").string() +
                ":3: t = 0 does not come after the previous row's t = 0; a table's t must be "
                "strictly increasing");
  std::filesystem::remove_all(dir);
}

TEST(CaseFile, SectionsOfEveryKindAreRead) {
  const Case c = parse_case(appended(R"(bed: {level: 2, slope: 0.001}
bodies:
  physics: {drag_law: constant, drag_coefficient: 1.0, drag_points: 3}
  list:
    - {shape: box, length: 4, width: 2, height: 1.5, density: 300, x: 10, y: 5, u: 1, id: 7}
  release:
    - {line: [[5, 2], [5, 18]], start: 10, end: 70, rate: 6, length: [10, 20],
       width: 1, density: [500, 700], angle_deg: [-45, 45], seed: 42}
output: {directory: results, interval: 5, overwrite: true}
)"),
                            "case.yaml");
  EXPECT_EQ(c.bed.kind, BedConfig::Kind::slope);
  EXPECT_EQ(c.bed.level, 2.0);
  EXPECT_EQ(c.bed.slope, Vec2(0.001, 0.0));
  EXPECT_EQ(c.bodies.physics.drag_law, DragLaw::constant);
  EXPECT_EQ(c.bodies.physics.drag_coefficient, 1.0);
  EXPECT_EQ(c.bodies.physics.drag_points, 3);
  const BodySpec& box = c.bodies.bodies.at(0);
  EXPECT_EQ(box.shape, Shape::box);
  EXPECT_EQ(box.height, 1.5);
  EXPECT_EQ(box.density, 300.0);
  EXPECT_EQ(box.velocity, Vec2(1.0, 0.0));
  EXPECT_EQ(box.id, 7);
  const Release& r = c.bodies.releases.at(0);
  EXPECT_EQ(r.line_start, Vec2(5.0, 2.0));
  EXPECT_EQ(r.line_end, Vec2(5.0, 18.0));
  EXPECT_EQ(r.start_time, 10.0);
  EXPECT_EQ(r.end_time, 70.0);
  EXPECT_EQ(r.rate, 6.0);
  EXPECT_EQ(r.length_min, 10.0);
  EXPECT_EQ(r.length_max, 20.0);
  EXPECT_EQ(r.width_min, 1.0);
  EXPECT_EQ(r.width_max, 1.0);
  EXPECT_EQ(r.height, 1.0);  // a log's: its width
  EXPECT_EQ(r.density_min, 500.0);
  EXPECT_EQ(r.angle_min_deg, -45.0);
  EXPECT_EQ(r.angle_max_deg, 45.0);
  EXPECT_EQ(r.seed, 42ul);
  EXPECT_EQ(c.output.directory, "results");
  EXPECT_TRUE(c.output.overwrite);
}

TEST(CaseFile, FlowOptionsAreRead) {
  const Case c =
      parse_case(edited("  initial: {eta: 1.0}", R"(  initial: {eta_start: 1.2, eta_end: 1.0}
  viscosity: 0.01
  turbulence: {model: smagorinsky, smagorinsky_constant: 0.1}
  coriolis: {latitude_deg: 45}
  wind: {velocity: [3, -4]})"),
                 "case.yaml");
  EXPECT_EQ(c.flow.initial_eta_start, 1.2);
  EXPECT_EQ(c.flow.initial_eta_end, 1.0);
  EXPECT_EQ(c.flow.viscosity, 0.01);
  EXPECT_EQ(c.flow.turbulence, TurbulenceModel::smagorinsky);
  EXPECT_EQ(c.flow.smagorinsky_constant, 0.1);
  EXPECT_TRUE(c.flow.coriolis);
  EXPECT_EQ(c.flow.latitude_deg, 45.0);
  EXPECT_EQ(c.flow.wind, Vec2(3.0, -4.0));
}

TEST(CaseFile, VelocityBoundaryTakesUAndV) {
  const Case c = parse_case(edited("inflow: {type: elevation, value: 1.0}",
                                   "inflow: {type: velocity, u: 0.5, v: [[0, 0], [10, 1]]}"),
                            "case.yaml");
  EXPECT_EQ(c.flow.boundaries[0].kind, BoundaryCondition::Kind::velocity);
  EXPECT_EQ(c.flow.boundaries[0].value(3.0), 0.5);
  EXPECT_DOUBLE_EQ(c.flow.boundaries[0].value_y(5.0), 0.5);
}

TEST(CaseFile, RelativeMeshFileIsReadFromTheCaseFolder) {
  const auto folder = test::scratch_path("flotsam_case_file_test");
  std::filesystem::create_directories(folder / "meshes");
  std::ofstream(folder / "meshes" / "river.msh") << "$MeshFormat\n";
  std::ofstream(folder / "river.yaml")
      << edited("  channel: {length: 100, width: 20}", "  file: meshes/river.msh");
  const Case c = read_case((folder / "river.yaml").string());
  EXPECT_EQ(c.mesh.kind, MeshSource::Kind::file);
  EXPECT_EQ(c.mesh.file, (folder / "meshes" / "river.msh").string());
  std::filesystem::remove_all(folder);
}

// Named pipes read as files would block the run until something writes to them: a case file, a
// mesh file and a raster that are named pipes are refused, naming the file and the key.
TEST(CaseFileError, NamedPipesAreRefusedAsInputs) {
  const auto folder = test::fresh_test_folder("flotsam_case_fifo_test");
  const std::string pipe = (folder / "pipe").string();
  const auto refusal = [](const std::string& path) {
    try {
      read_case(path);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  ASSERT_EQ(mkfifo(pipe.c_str(), 0600), 0);
  EXPECT_EQ(refusal(pipe),
            "the case file '" + pipe + "' is a named pipe, not a file: flotsam reads it whole");
  std::ofstream(folder / "mesh.yaml")
      << edited("  channel: {length: 100, width: 20}", "  file: pipe");
  EXPECT_EQ(refusal((folder / "mesh.yaml").string()),
            (folder / "mesh.yaml").string() + ":2: mesh.file: '" + pipe +
                "' is a named pipe, not a file: flotsam reads its inputs whole from files");
  std::ofstream(folder / "bed.yaml") << appended("bed: {raster: pipe}\n");
  EXPECT_EQ(refusal((folder / "bed.yaml").string()),
            (folder / "bed.yaml").string() + ":12: bed.raster: '" + pipe +
                "' is a named pipe, not a file: flotsam reads its inputs whole from files");
  std::filesystem::remove_all(folder);
}

// ---- the keys of the finite-volume engine, formulas and probes -------------------------------

TEST(CaseFile, EngineIsFemByDefault) {
  const Case c = parse_case(base_case, "case.yaml");
  EXPECT_EQ(c.flow.engine, FlowEngineKind::fem);
  EXPECT_EQ(c.flow.fv.order, 2);
  EXPECT_EQ(c.flow.fv.courant, 0.9);
  EXPECT_EQ(c.flow.fv.velocity_depth, 1e-5);
  EXPECT_EQ(c.flow.dry_depth_or_default(), 1e-3);  // the FEM's (spec 1.5)
  EXPECT_TRUE(c.flow.initial_eta.empty());
  EXPECT_TRUE(c.flow.initial_u.empty());
  EXPECT_TRUE(c.flow.initial_v.empty());
  EXPECT_TRUE(c.output.probes.empty());
  EXPECT_EQ(c.output.probe_interval, 0.0);
}

TEST(CaseFile, FiniteVolumeEngineTakesItsOptions) {
  const Case c =
      parse_case(edited("  initial:",
                        "  engine: fv\n  fv: {order: 1, courant: 0.4, velocity_depth: 0.002, "
                        "cells: split, time_levels: 4}\n  initial:"),
                 "case.yaml");
  EXPECT_EQ(c.flow.engine, FlowEngineKind::fv);
  EXPECT_EQ(c.flow.fv.order, 1);
  EXPECT_EQ(c.flow.fv.courant, 0.4);
  EXPECT_EQ(c.flow.fv.cells, FvCells::split);
  EXPECT_EQ(c.flow.fv.velocity_depth, 0.002);
  EXPECT_EQ(c.flow.fv.time_levels, 4);
  const Case d = parse_case(edited("  initial:", "  engine: fv\n  initial:"), "case.yaml");
  EXPECT_EQ(d.flow.engine, FlowEngineKind::fv);
  EXPECT_EQ(d.flow.fv.order, 2);  // the defaults
  EXPECT_EQ(d.flow.fv.courant, 0.9);
  EXPECT_EQ(d.flow.fv.cells, FvCells::elements);
  EXPECT_EQ(d.flow.fv.time_levels, 0);  // auto
  EXPECT_EQ(parse_case(edited("  initial:", "  engine: fv\n  fv: {time_levels: auto}\n  initial:"),
                       "case.yaml")
                .flow.fv.time_levels,
            0);
  EXPECT_EQ(d.flow.dry_depth_or_default(), 1e-5);  // the finite volumes' (docs/model.md (M-15))
  // A generated mesh of three-node triangles for the finite volumes, six-node for the FEM.
  EXPECT_EQ(d.mesh.element_order, 1);
  EXPECT_EQ(
      parse_case(edited("  initial:", "  engine: fem\n  initial:"), "case.yaml").mesh.element_order,
      2);
  EXPECT_EQ(
      parse_case(edited("  initial:", "  engine: fv\n  dry_depth: 0.002\n  initial:"), "case.yaml")
          .flow.dry_depth_or_default(),
      0.002);
  EXPECT_EQ(
      parse_case(edited("  initial:", "  engine: fv\n  fv: {courant: 1}\n  initial:"), "case.yaml")
          .flow.fv.courant,
      1.0);
}

TEST(CaseFile, BedExpressionIsAFormulaInXAndY) {
  const Case c =
      parse_case(appended("bed:\n  expression: \"-0.1*(1 - ((x-2)^2 + (y-2)^2))\"\n"), "case.yaml");
  EXPECT_EQ(c.bed.kind, BedConfig::Kind::expression);
  EXPECT_EQ(c.bed.expression.text(), "-0.1*(1 - ((x-2)^2 + (y-2)^2))");
  EXPECT_EQ(c.bed.expression.origin(), "case.yaml:13: bed.expression");
  EXPECT_DOUBLE_EQ(c.bed.expression(2.0, 2.0), -0.1);
  EXPECT_DOUBLE_EQ(c.bed.expression(0.0, 0.0), 0.7);
}

TEST(CaseFile, BedRasterIsReadRelativeToTheCaseWithAnOptionalEdit) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "flotsam_bed_raster";
  std::filesystem::create_directories(dir / "data");
  const RasterGrid g = RasterGrid::covering({-10, -10}, {110, 30}, 5.0, "");
  write_geotiff((dir / "data" / "dem.tif").string(), g,
                std::vector<double>(static_cast<std::size_t>(g.columns) * g.rows, 3.0));
  const std::string case_file = (dir / "case.yaml").string();
  const Case c = parse_case(
      appended("bed:\n  raster: data/dem.tif\n  expression: \"x > 50 ? z - 1 : z\"\n"), case_file);
  ASSERT_EQ(c.bed.kind, BedConfig::Kind::raster);
  EXPECT_EQ(c.bed.raster->path(), (dir / "data" / "dem.tif").string());
  EXPECT_EQ(c.bed.origin, case_file + ":13: bed.raster");
  EXPECT_DOUBLE_EQ(c.bed.expression(60.0, 0.0, 3.0), 2.0);

  EXPECT_THAT(error_of(appended("bed:\n  raster: none.tif\n")),
              HasSubstr("case.yaml:13: bed.raster: the raster 'none.tif' does not exist"));
  EXPECT_THAT(error_of(appended("bed:\n  raster: " + (dir / "data" / "dem.tif").string() +
                                "\n  level: 2\n")),
              HasSubstr("case.yaml:14: bed.level: not allowed here: the bed is given by raster"));
  EXPECT_THAT(error_of(appended("bed:\n  raster: " + (dir / "data" / "dem.tif").string() +
                                "\n  expression: \"w + z\"\n")),
              HasSubstr("unknown variable 'w' in 'w + z'; a formula may use only x, y and z"));
  std::filesystem::remove_all(dir);
}

TEST(CaseFile, FloodEnvelopeRastersAndTheirCoordinateSystem) {
  const Case c = parse_case(
      edited("  initial: {eta: 1.0}", "  engine: fv\n  initial: {eta: 1.0}") +
          "output:\n  wet_depth: 0.05\n  rasters: {resolution: 2}\ncrs: \"EPSG:32633\"\n",
      "case.yaml");
  EXPECT_EQ(c.output.wet_depth, 0.05);
  EXPECT_EQ(c.output.raster_resolution, 2.0);
  EXPECT_THAT(c.crs_wkt, HasSubstr("UTM zone 33N"));
  EXPECT_THAT(error_of(appended("output:\n  rasters: {resolution: 2}\n")),
              HasSubstr("case.yaml:13: output.rasters: the flood envelopes and their rasters come "
                        "from the finite-volume engine; set flow.engine: fv"));
  EXPECT_THAT(error_of(edited("  initial: {eta: 1.0}", "  engine: fv\n  initial: {eta: 1.0}") +
                       "output:\n  rasters: {resolution: 0}\n"),
              HasSubstr("case.yaml:14: output.rasters.resolution: expected a number > 0"));
  EXPECT_THAT(error_of(edited("  initial: {eta: 1.0}", "  engine: fv\n  initial: {eta: 1.0}") +
                       "crs: \"EPSG:4326\"\n"),
              HasSubstr("case.yaml:13: crs: 'EPSG:4326' is a geographic coordinate system"));
  EXPECT_THAT(error_of(edited("  initial: {eta: 1.0}", "  engine: fv\n  initial: {eta: 1.0}") +
                       "crs: nowhere\n"),
              HasSubstr("case.yaml:13: crs: 'nowhere' is not a coordinate system GDAL knows"));
}

TEST(CaseFile, RegionFromGeodataFilesNamesTheFeaturesOfBadGeometry) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "flotsam_region_case";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  write_polygon_layer((dir / "town.gpkg").string(), "outline",
                      {{{0, 0}, {200, 0}, {200, 80}, {0, 80}}}, "");
  write_polygon_layer(
      (dir / "houses.gpkg").string(), "buildings",
      {{{50, 20}, {60, 20}, {60, 30}, {50, 30}}, {{55, 25}, {65, 25}, {65, 35}, {55, 35}}}, "");
  const std::string region = R"(mesh:
  region:
    outline: {file: town.gpkg, layer: outline}
    boundaries: {inflow: [[0, 80], [0, 0]], outflow: [[200, 0], [200, 80]]}
    buildings: houses.gpkg
    mesh_size: 10
)";
  const std::string rest = base_case.substr(base_case.find("flow:"));
  const Case c = parse_case(region + rest, (dir / "case.yaml").string());
  ASSERT_EQ(c.mesh.kind, MeshSource::Kind::region);
  EXPECT_EQ(c.mesh.region.outline.points.size(), 4u);
  EXPECT_EQ(c.mesh.region.lines.size(), 2u);
  EXPECT_EQ(c.mesh.region.buildings.size(), 2u);
  std::string message = "no error";
  try {
    generate_mesh(c.mesh);
  } catch (const InputError& e) {
    message = e.what();
  }
  EXPECT_THAT(message, HasSubstr("houses.gpkg, layer 'buildings', feature 1 and houses.gpkg, "
                                 "layer 'buildings', feature 2 overlap"));
  message = "no error";
  try {
    parse_case(region + "    steep: {slope: 0.1, mesh_size: 2}\n" + rest,
               (dir / "case.yaml").string());
  } catch (const InputError& e) {
    message = e.what();
  }
  EXPECT_THAT(message, HasSubstr("case.yaml:7: mesh.region.steep: refining where the terrain is "
                                 "steep needs a terrain: bed.raster"));
  std::filesystem::remove_all(dir);
}

TEST(CaseFile, InitialStateMayBeFormulas) {
  const Case c = parse_case(edited("  initial: {eta: 1.0}",
                                   "  initial: {eta: \"x < 5 ? 0.005 : 0\", u: 0.5, v: \"0.1*y\"}"),
                            "case.yaml");
  EXPECT_EQ(c.flow.initial_eta.text(), "x < 5 ? 0.005 : 0");
  EXPECT_EQ(c.flow.initial_eta.origin(), "case.yaml:5: flow.initial.eta");
  EXPECT_EQ(c.flow.initial_eta(4.0, 1.0), 0.005);
  EXPECT_EQ(c.flow.initial_eta(6.0, 1.0), 0.0);
  EXPECT_EQ(c.flow.initial_eta_start, 0.0);  // unused with a formula
  EXPECT_EQ(c.flow.initial_eta_end, 0.0);
  EXPECT_EQ(c.flow.initial_u(3.0, 7.0), 0.5);  // a number is kept as a constant formula
  EXPECT_DOUBLE_EQ(c.flow.initial_v(3.0, 7.0), 0.7);
  // A number for eta is the flat surface, as before; u and v go with the slope too.
  const Case d = parse_case(
      edited("  initial: {eta: 1.0}", "  initial: {eta_start: 1.2, eta_end: 1.0, u: \"0.2\"}"),
      "case.yaml");
  EXPECT_TRUE(d.flow.initial_eta.empty());
  EXPECT_EQ(d.flow.initial_eta_start, 1.2);
  EXPECT_EQ(d.flow.initial_u(0.0, 0.0), 0.2);
  EXPECT_TRUE(d.flow.initial_v.empty());
}

TEST(CaseFile, FreeBoundaryTakesNoValue) {
  const Case c = parse_case(
      edited("outflow: {type: elevation, value: 0.9}", "outflow: {type: free}"), "case.yaml");
  EXPECT_EQ(c.flow.boundaries[1].kind, BoundaryCondition::Kind::free);
  EXPECT_EQ(c.flow.boundaries[1].group, "outflow");
  EXPECT_EQ(c.flow.boundaries[1].line, 8);
}

TEST(CaseFile, RainIsAnIntensityOrAHyetographWithAnInfiltration) {
  const Case c = parse_case(
      edited("  initial:", "  engine: fv\n  rain: {intensity: 25, infiltration: 4}\n  initial:"),
      "case.yaml");
  EXPECT_TRUE(c.flow.rain.enabled);
  EXPECT_TRUE(c.flow.rain.intensity.is_constant());
  EXPECT_EQ(c.flow.rain.intensity(0.0), 25.0);
  EXPECT_EQ(c.flow.rain.infiltration, 4.0);
  EXPECT_EQ(c.flow.rain.line, 6);
  const Case d = parse_case(edited("  initial:",
                                   "  engine: fv\n  rain:\n    intensity: [[0, 0], [600, 80], "
                                   "[1800, 0]]\n  initial:"),
                            "case.yaml");
  EXPECT_EQ(d.flow.rain.intensity.points().size(), 3u);
  EXPECT_EQ(d.flow.rain.intensity(300.0), 40.0);
  EXPECT_EQ(d.flow.rain.infiltration, 0.0);  // the default
  EXPECT_FALSE(parse_case(base_case, "case.yaml").flow.rain.enabled);
}

TEST(CaseFile, ProbesAreNamedPoints) {
  const Case c = parse_case(appended(R"(output:
  probe_interval: 0.5
  probes:
    - {name: P1, x: 9.5, y: 0.5}
    - {name: gauge_2-b, x: 50, y: -1}
)"),
                            "case.yaml");
  EXPECT_EQ(c.output.probe_interval, 0.5);
  ASSERT_EQ(c.output.probes.size(), 2u);
  EXPECT_EQ(c.output.probes[0].name, "P1");
  EXPECT_EQ(c.output.probes[0].position, Vec2(9.5, 0.5));
  EXPECT_EQ(c.output.probes[0].line, 15);
  EXPECT_EQ(c.output.probes[1].name, "gauge_2-b");
  EXPECT_EQ(c.output.probes[1].position, Vec2(50.0, -1.0));
  EXPECT_EQ(c.output.probes[1].line, 16);
}

TEST(CaseFileError, EngineKeysAreChecked) {
  EXPECT_EQ(error_of(edited("  initial:", "  engine: vf\n  initial:")),
            "case.yaml:5: flow.engine: unknown value 'vf'; expected one of: fem, fv (did you "
            "mean 'fv'?)");
  EXPECT_EQ(error_of(edited("  initial:", "  fv: {order: 1}\n  initial:")),
            "case.yaml:5: flow.fv: not allowed here: flow.fv only applies to 'engine: fv' (the "
            "engine is fem)");
  EXPECT_EQ(error_of(edited("  initial:", "  engine: fem\n  fv: {order: 1}\n  initial:")),
            "case.yaml:6: flow.fv: not allowed here: flow.fv only applies to 'engine: fv' (the "
            "engine is fem)");
  EXPECT_EQ(error_of(edited("  initial:",
                            "  engine: fv\n  turbulence: {model: smagorinsky}\n  initial:")),
            "case.yaml:6: flow.turbulence: not allowed here: flow.turbulence only applies to "
            "'engine: fem' (the finite-volume engine has no eddy viscosity)");
  const auto fv = [](const std::string& options) {
    return edited("  initial:", "  engine: fv\n  fv: {" + options + "}\n  initial:");
  };
  EXPECT_EQ(error_of(fv("order: 3")),
            "case.yaml:6: flow.fv.order: expected an integer in [1, 2], got 3");
  EXPECT_EQ(error_of(fv("order: 1.5")),
            "case.yaml:6: flow.fv.order: expected an integer in [1, 2], got '1.5'");
  EXPECT_EQ(error_of(fv("courant: 0")),
            "case.yaml:6: flow.fv.courant: expected a number in (0, 1], got 0");
  EXPECT_EQ(error_of(fv("courant: 1.2")),
            "case.yaml:6: flow.fv.courant: expected a number in (0, 1], got 1.2");
  EXPECT_EQ(error_of(fv("velocity_depth: 0")),
            "case.yaml:6: flow.fv.velocity_depth: expected a number > 0, got 0");
  EXPECT_EQ(error_of(fv("cells: quads")),
            "case.yaml:6: flow.fv.cells: unknown value 'quads'; expected one of: elements, split");
  EXPECT_EQ(error_of(fv("limiter: minmod")),
            "case.yaml:6: flow.fv.limiter: unknown key; allowed here: order, courant, cells, "
            "velocity_depth, time_levels, pier_drag");
  EXPECT_EQ(error_of(fv("time_levels: 9")),
            "case.yaml:6: flow.fv.time_levels: expected an integer in [1, 8], got 9");
  EXPECT_EQ(error_of(fv("time_levels: fast")),
            "case.yaml:6: flow.fv.time_levels: unknown value 'fast'; expected one of: auto");
  EXPECT_EQ(error_of(fv("pier_drag: -0.5")),
            "case.yaml:6: flow.fv.pier_drag: expected a number in [0, 10], got -0.5");
}

TEST(CaseFileError, BedExpressionIsCheckedWhenRead) {
  EXPECT_EQ(error_of(appended("bed: {expression: \"x + * 2\"}\n")),
            "case.yaml:12: bed.expression: syntax error in 'x + * 2' at character 5 ('* 2'): "
            "Unexpected operator \"*\"");
  EXPECT_EQ(error_of(appended("bed: {expression: \"0.1*z\"}\n")),
            "case.yaml:12: bed.expression: unknown variable 'z' in '0.1*z'; a formula may use "
            "only x and y [m]");
  EXPECT_EQ(error_of(appended("bed: {expression: [1, 2]}\n")),
            "case.yaml:12: bed.expression: expected a formula in x and y (or a number), got a "
            "list");
  EXPECT_EQ(error_of(appended("bed: {level: 1, expression: \"0.1*x\"}\n")),
            "case.yaml:12: bed.level: not allowed here: the bed is given by expression");
  EXPECT_EQ(error_of(appended("bed: {expression: \"0.1*x\", slope: 0.01}\n")),
            "case.yaml:12: bed.slope: not allowed here: the bed is given by expression");
  EXPECT_EQ(error_of(appended("bed:\n  profile_x: [[0, 1], [10, 0]]\n  expression: \"x\"\n")),
            "case.yaml:14: bed.expression: give either 'profile_x' (line 13) or 'expression', "
            "not both");
}

TEST(CaseFileError, InitialFormulasAreCheckedWhenRead) {
  const auto initial = [](const std::string& keys) {
    return edited("  initial: {eta: 1.0}", "  initial: {" + keys + "}");
  };
  EXPECT_EQ(error_of(initial("eta: \"1 + (x\"")),
            "case.yaml:5: flow.initial.eta: syntax error at the end of '1 + (x': Missing "
            "parenthesis");
  EXPECT_EQ(error_of(initial("eta: \"x < 5 ? 1 : 0\", eta_end: 1")),
            "case.yaml:5: flow.initial.eta_end: not allowed here: with 'eta' as a formula the "
            "surface is the formula's");
  EXPECT_EQ(error_of(initial("eta: 1.0, eta_end: 1")),
            "case.yaml:5: flow.initial.eta_end: not allowed here: with 'eta' the surface is flat; "
            "use eta_start and eta_end for a slope");
  EXPECT_EQ(error_of(initial("eta: 1.0, u: \"t\"")),
            "case.yaml:5: flow.initial.u: unknown variable 't' in 't'; a formula may use only x "
            "and y [m]");
  EXPECT_EQ(error_of(initial("eta: 1.0, v: [0, 1]")),
            "case.yaml:5: flow.initial.v: expected a formula in x and y (or a number), got a "
            "list");
  EXPECT_EQ(error_of(initial("eta: 1.0, w: 0")),
            "case.yaml:5: flow.initial.w: unknown key; allowed here: eta, eta_start, u, v, "
            "eta_end");
}

TEST(CaseFileError, FreeBoundaryRejectsValues) {
  EXPECT_EQ(error_of(edited("outflow: {type: elevation, value: 0.9}",
                            "outflow: {type: free, value: 0.9}")),
            "case.yaml:8: flow.boundaries.outflow.value: not allowed here: a free boundary takes "
            "no value: what reaches it leaves");
  EXPECT_EQ(
      error_of(edited("outflow: {type: elevation, value: 0.9}", "outflow: {type: free, u: 1}")),
      "case.yaml:8: flow.boundaries.outflow.u: not allowed here: a free boundary takes no "
      "value: what reaches it leaves");
}

TEST(CaseFileError, RainIsChecked) {
  const auto rain = [](const std::string& keys) {
    return edited("  initial:", "  engine: fv\n  rain: " + keys + "\n  initial:");
  };
  EXPECT_EQ(error_of(rain("{intensity: -5}")),
            "case.yaml:6: flow.rain.intensity: expected a number >= 0, got -5");
  EXPECT_EQ(error_of(rain("{intensity: [[0, 10], [60, -2]]}")),
            "case.yaml:6: flow.rain.intensity[1][1]: expected a number >= 0, got -2");
  EXPECT_EQ(error_of(rain("{intensity: [[0, 10], [600, 20], [300, 5]]}")),
            "case.yaml:6: flow.rain.intensity[2]: t = 300 does not come after the previous row's "
            "t = 600; a table's t must be strictly increasing");
  EXPECT_EQ(error_of(rain("{intensity: 10, infiltration: -1}")),
            "case.yaml:6: flow.rain.infiltration: expected a number >= 0, got -1");
  EXPECT_EQ(error_of(rain("{intensity: 10, infiltration: [[0, 1]]}")),
            "case.yaml:6: flow.rain.infiltration: expected a number >= 0, got a list");
  EXPECT_EQ(error_of(rain("{infiltration: 1}")),
            "case.yaml:6: flow.rain.intensity: missing; this key is required: i [mm/h], a number "
            "or a hyetograph [[t, i], ...]");
  EXPECT_EQ(
      error_of(rain("{intensity: {t: 0}}")),
      "case.yaml:6: flow.rain.intensity: expected a number >= 0, a table [[t, value], ...] or "
      "{file: table.csv}, got a map");
  EXPECT_EQ(error_of(rain("{intensity: 10, duration: 60}")),
            "case.yaml:6: flow.rain.duration: unknown key; allowed here: intensity, infiltration, "
            "raster");
  EXPECT_EQ(error_of(rain("20")), "case.yaml:6: flow.rain: expected a map of keys, got '20'");
}

TEST(CaseFile, SourcesArePointsOrPolygonsWithADischarge) {
  const Case c = parse_case(edited("  initial:", R"(  engine: fv
  sources:
    - {name: culvert, point: [20, 5], discharge: 1.5}
    - polygon: [[40, 2], [50, 2], [50, 8]]
      discharge: [[0, 0], [600, 12], [1800, 0]]
  initial:)"),
                            "case.yaml");
  ASSERT_EQ(c.flow.sources.size(), 2u);
  EXPECT_EQ(c.flow.sources[0].name, "culvert");
  EXPECT_EQ(c.flow.sources[0].origin, "case.yaml:7: flow.sources[0] (culvert)");
  EXPECT_EQ(c.flow.sources[0].point, Vec2(20.0, 5.0));
  EXPECT_TRUE(c.flow.sources[0].polygon.empty());
  EXPECT_EQ(c.flow.sources[0].discharge(100.0), 1.5);
  EXPECT_EQ(c.flow.sources[1].name, "flow.sources[1]");
  EXPECT_EQ(c.flow.sources[1].origin, "case.yaml:8: flow.sources[1]");
  EXPECT_EQ(c.flow.sources[1].polygon.size(), 3u);
  EXPECT_EQ(c.flow.sources[1].discharge(300.0), 6.0);
}

TEST(CaseFileError, SourcesAreChecked) {
  const auto sources = [](const std::string& list, const std::string& engine = "fv") {
    return edited("  initial:", "  engine: " + engine + "\n  sources: " + list + "\n  initial:");
  };
  EXPECT_EQ(error_of(sources("[{point: [20, 5], discharge: -1}]")),
            "case.yaml:6: flow.sources[0].discharge: expected a number >= 0, got -1");
  EXPECT_EQ(error_of(sources("[{point: [20, 5], polygon: [[0, 0], [1, 0], [1, 1]], discharge: "
                             "1}]")),
            "case.yaml:6: flow.sources[0].polygon: give either 'point' (line 6) or 'polygon', not "
            "both");
  EXPECT_EQ(error_of(sources("[{discharge: 1}]")),
            "case.yaml:6: flow.sources[0]: expected 'point: [x, y]' or 'polygon: [[x, y], ...]' "
            "[m]");
  EXPECT_EQ(error_of(sources("[{point: [20, 5]}]")),
            "case.yaml:6: flow.sources[0].discharge: missing; this key is required: Q [m^3/s] >= "
            "0, a number or a hydrograph [[t, Q], ...]");
  EXPECT_EQ(error_of(sources("[]")),
            "case.yaml:6: flow.sources: expected a list of sources {point: [x, y] or polygon, "
            "discharge}");
  EXPECT_EQ(error_of(sources("[{point: [20, 5], discharge: 1}]", "fem")),
            "case.yaml:6: flow.sources: flow.sources are taken by 'engine: fv' only (the FEM "
            "engine has no sources: let the water in through a discharge boundary, or use the "
            "finite-volume engine)");
}

TEST(CaseFile, RainRasterIsReadFromTheCaseFolder) {
  const auto folder = test::scratch_path("flotsam_case_rain_raster");
  std::filesystem::create_directories(folder);
  const RasterGrid g = RasterGrid::covering({0, 0}, {100, 20}, 10.0, "");
  write_geotiff((folder / "rain.tif").string(), g,
                std::vector<double>(static_cast<std::size_t>(g.columns) * g.rows, 1.5));
  const std::string file = (folder / "case.yaml").string();
  const Case c = parse_case(
      edited("  initial:", "  engine: fv\n  rain: {intensity: 25, raster: rain.tif}\n  initial:"),
      file);
  ASSERT_TRUE(c.flow.rain.raster);
  EXPECT_EQ(c.flow.rain.raster->path(), (folder / "rain.tif").string());
  EXPECT_EQ(c.flow.rain.raster_origin, file + ":6: flow.rain.raster");
  EXPECT_EQ(c.flow.rain.raster->at(0, 0), 1.5);
  EXPECT_FALSE(
      parse_case(edited("  initial:", "  engine: fv\n  rain: {intensity: 25}\n  initial:"), file)
          .flow.rain.raster);
  EXPECT_EQ(error_of(edited("  initial:",
                            "  engine: fv\n  rain: {intensity: 25, raster: none.tif}\n  initial:")),
            "case.yaml:6: flow.rain.raster: the raster 'none.tif' does not exist");
}

TEST(CaseFileError, ProbesAreChecked) {
  const auto probes = [](const std::string& list) {
    return appended("output:\n  probes:\n" + list);
  };
  EXPECT_EQ(error_of(probes("    - {x: 1, y: 2}\n")),
            "case.yaml:14: output.probes[0].name: missing; this key is required: the probe's "
            "name, which heads its columns");
  EXPECT_EQ(error_of(probes("    - {name: P1, y: 2}\n")),
            "case.yaml:14: output.probes[0].x: missing; this key is required: [m]");
  EXPECT_EQ(error_of(probes("    - {name: P1, x: 1, y: north}\n")),
            "case.yaml:14: output.probes[0].y: expected a number, got 'north'");
  EXPECT_EQ(error_of(probes("    - {name: \"gauge 1\", x: 1, y: 2}\n")),
            "case.yaml:14: output.probes[0].name: expected a name of letters, digits, '_' and '-' "
            "(it names the probe's columns), got 'gauge 1'");
  EXPECT_EQ(error_of(probes("    - {name: \"\", x: 1, y: 2}\n")),
            "case.yaml:14: output.probes[0].name: expected a name of letters, digits, '_' and '-' "
            "(it names the probe's columns), got ''");
  EXPECT_EQ(error_of(probes("    - {name: P1, x: 1, y: 2}\n    - {name: P1, x: 3, y: 2}\n")),
            "case.yaml:15: output.probes[1].name: the name 'P1' is already used by the probe on "
            "line 14");
  EXPECT_EQ(error_of(probes("    - {name: P1, x: 1, y: 2, z: 0}\n")),
            "case.yaml:14: output.probes[0].z: unknown key; allowed here: name, x, y");
  EXPECT_EQ(error_of(appended("output: {probes: {name: P1, x: 1, y: 2}}\n")),
            "case.yaml:12: output.probes: expected a list, got a map");
  EXPECT_EQ(error_of(appended("output: {probe_interval: -1}\n")),
            "case.yaml:12: output.probe_interval: expected a number >= 0, got -1");
}

TEST(CaseFile, ReleaseZonesAreRead) {
  const Case c = parse_case(appended(R"(bodies:
  release:
    - zone: [[10, 2], [30, 2], [30, 8], [10, 8]]
      count: 12
      start: 5
      shape: box
      length: 4.0
      width: 1.7
      height: 1.5
      density: 108
      angle_deg: [-5, 5]
    - {zone: [[40, 2], [60, 2], [50, 18]], end: 600, rate: 2}
)"),
                            "case.yaml");
  ASSERT_EQ(c.bodies.releases.size(), 2u);
  const Release& cars = c.bodies.releases[0];
  EXPECT_EQ(cars.zone, (std::vector<Vec2>{{10, 2}, {30, 2}, {30, 8}, {10, 8}}));
  EXPECT_EQ(cars.count, 12);
  EXPECT_EQ(cars.start_time, 5.0);
  EXPECT_EQ(cars.rate, 0.0);
  EXPECT_EQ(cars.shape, Shape::box);
  EXPECT_EQ(cars.height, 1.5);
  EXPECT_EQ(cars.source_line, 14);  // the zone's line, for messages
  const Release& logs = c.bodies.releases[1];
  EXPECT_EQ(logs.zone.size(), 3u);
  EXPECT_EQ(logs.count, 0);
  EXPECT_EQ(logs.rate, 2.0);
  EXPECT_EQ(logs.end_time, 600.0);
  EXPECT_EQ(logs.source_line, 23);
}

TEST(CaseFileError, ReleaseZonesAreChecked) {
  const auto release = [](const std::string& item) {
    return appended("bodies:\n  release:\n    - " + item + "\n");
  };
  EXPECT_EQ(error_of(release("{zone: [[0, 0], [10, 0]], count: 3}")),
            "case.yaml:14: bodies.release[0].zone: a polygon needs at least 3 points; got 2");
  EXPECT_EQ(error_of(release("{zone: [[0, 0], [10, 10], [10, 0], [0, 10]], count: 3}")),
            "case.yaml:14: bodies.release[0].zone: the polygon intersects itself: side 1 (points "
            "1 to 2) meets side 3 (points 3 to 4)");
  EXPECT_EQ(error_of(release("{zone: [[0, 0], [5, 5], [10, 10]], count: 3}")),
            "case.yaml:14: bodies.release[0].zone: the polygon has zero area (its points lie on "
            "one line)");
  EXPECT_EQ(error_of(release("{zone: [[0, 0], [5, 0], [5, 5], [5, 0]], count: 3}")),
            "case.yaml:14: bodies.release[0].zone: points 2 and 4 coincide at (5, 0) m");
  EXPECT_EQ(error_of(release("{zone: [[0, 0], [5, 0], [5]], count: 3}")),
            "case.yaml:14: bodies.release[0].zone[2]: expected a pair of numbers [x, y], got a "
            "list");
  EXPECT_EQ(error_of(release("{line: [[5, 2], [5, 18]], zone: [[0, 0], [5, 0], [5, 5]], "
                             "count: 3}")),
            "case.yaml:14: bodies.release[0].zone: give either 'line' (line 14) or 'zone', not "
            "both");
  EXPECT_EQ(error_of(release("{count: 3}")),
            "case.yaml:14: bodies.release[0]: expected a release line 'line: [[x0, y0], [x1, "
            "y1]]' or a zone 'zone: [[x, y], ...]'");
  EXPECT_EQ(error_of(release("{zome: [[0, 0], [5, 0], [5, 5]], count: 3}")),
            "case.yaml:14: bodies.release[0].zome: unknown key (did you mean 'zone'?); allowed "
            "here: start, count, rate, end, shape, length, width, height, density, angle_deg, "
            "seed, line, zone");
  EXPECT_EQ(error_of(release("{zone: [[0, 0], [5, 0], [5, 5]], count: 0}")),
            "case.yaml:14: bodies.release[0].count: expected an integer in [1, 1000000], got 0");
  EXPECT_EQ(error_of(release("{zone: [[0, 0], [5, 0], [5, 5]], count: 3, rate: 2}")),
            "case.yaml:14: bodies.release[0].rate: not allowed here: a release with a count puts "
            "all its bodies at once at 'start'");
  EXPECT_EQ(error_of(release("{zone: [[0, 0], [5, 0], [5, 5]], count: 3, end: 60}")),
            "case.yaml:14: bodies.release[0].end: not allowed here: a release with a count puts "
            "all its bodies at once at 'start'");
  EXPECT_EQ(error_of(release("{zone: [[0, 0], [5, 0], [5, 5]], rate: 2}")),
            "case.yaml:14: bodies.release[0].end: missing; this key is required: the time the "
            "release stops [s] (or give a 'count' of bodies at once)");
}

// ---- errors: each names file, line, key path, and what was expected ------------------------

TEST(CaseFileError, UnknownKeyNamesTheNearestAllowedOne) {
  EXPECT_EQ(
      error_of(edited("  initial: {eta: 1.0}", "  initial: {eta: 1.0}\n  gravty: 9.81")),
      "case.yaml:6: flow.gravty: unknown key (did you mean 'gravity'?); allowed here: "
      "engine, fv, scheme, gravity, density, viscosity, reynolds, friction, turbulence, coriolis, "
      "wind, rain, sources, min_depth, dry_depth, initial, boundaries");
  EXPECT_EQ(error_of(appended("nmae: river\n")),
            "case.yaml:12: nmae: unknown key (did you mean 'name'?); allowed here: name, mesh, "
            "bed, bridges, flow, time, bodies, output, crs");
  EXPECT_EQ(error_of(appended("bodies:\n  list:\n    - {x: 1, y: 2, angel_deg: 30}\n")),
            "case.yaml:14: bodies.list[0].angel_deg: unknown key (did you mean 'angle_deg'?); "
            "allowed here: shape, length, width, height, density, x, y, angle_deg, u, v, omega, "
            "id, anchored");
  EXPECT_EQ(error_of(edited("channel:", "chanel:")),
            "case.yaml:2: mesh.chanel: unknown key (did you mean 'channel'?); allowed here: file, "
            "channel, bend, polygon, region");
}

TEST(CaseFileError, MissingKeyIsNamedWithItsMeaning) {
  EXPECT_EQ(error_of(edited("time: {end: 10, step: 0.5}", "time: {step: 0.5}")),
            "case.yaml:11: time.end: missing; this key is required: the simulated time [s]");
  EXPECT_EQ(error_of(edited("time: {end: 10, step: 0.5}\n", "")),
            "case.yaml:1: time: missing; this key is required: at least time.end");
  EXPECT_EQ(error_of(edited("coefficient: 0.03", "coefficent: 0.03")),
            "case.yaml:4: flow.friction.coefficient: missing; this key is required: Manning's n "
            "[s m^-1/3] (is 'coefficent' on line 4 a misspelling of it?)");
  EXPECT_EQ(error_of(edited("  initial: {eta: 1.0}", "  initial: {eta_start: 1.0}")),
            "case.yaml:5: flow.initial.eta_end: missing; this key is required: eta at the "
            "largest x [m]");
}

TEST(CaseFileError, WrongTypeSaysWhatWasExpectedAndFound) {
  EXPECT_EQ(error_of(edited("length: 100", "length: abc")),
            "case.yaml:2: mesh.channel.length: expected a number > 0, got 'abc'");
  EXPECT_EQ(error_of(edited("length: 100", "length: \"100\"")),
            "case.yaml:2: mesh.channel.length: expected a number > 0, got the quoted text '100'");
  EXPECT_EQ(
      error_of(edited("friction: {law: manning, coefficient: 0.03}", "friction: [manning, 0.03]")),
      "case.yaml:4: flow.friction: expected a map of keys, got a list");
  EXPECT_EQ(error_of(edited("outflow: {type: elevation, value: 0.9}",
                            "outflow: {type: elevation, value: {t: 0}}")),
            "case.yaml:8: flow.boundaries.outflow.value: expected a number, a table [[t, value], "
            "...] or {file: table.csv}, got a map");
  EXPECT_EQ(error_of(appended("output: {overwrite: maybe}\n")),
            "case.yaml:12: output.overwrite: expected true or false, got 'maybe'");
  EXPECT_EQ(error_of(appended("bodies: {physics: {drag_points: 2.5}}\n")),
            "case.yaml:12: bodies.physics.drag_points: expected an integer in [1, 1000], got "
            "'2.5'");
}

TEST(CaseFileError, OutOfRangeGivesTheRange) {
  EXPECT_EQ(error_of(edited("length: 100", "length: -5")),
            "case.yaml:2: mesh.channel.length: expected a number > 0, got -5");
  EXPECT_EQ(error_of(edited("end: 10", "end: 0")),
            "case.yaml:11: time.end: expected a number > 0, got 0");
  EXPECT_EQ(error_of(edited("step: 0.5", "step: -0.1")),
            "case.yaml:11: time.step: expected a number > 0, got -0.1");
  EXPECT_EQ(error_of(edited("step: 0.5}", "step: 0.5, theta: 0.4}")),
            "case.yaml:11: time.theta: expected a number in [0.5, 1], got 0.4");
  EXPECT_EQ(error_of(edited("step: 0.5", "step: 20")),
            "case.yaml:11: time.step: the step 20 s is longer than time.end = 10 s");
  EXPECT_EQ(error_of(edited("step: 0.5}", "step: 0.5, origin: 2023-02-29}")),
            "case.yaml:11: time.origin: '2023-02-29' is not a calendar time: expected "
            "\"YYYY-MM-DD hh:mm:ss\" (UTC) or \"YYYY-MM-DD\"");
  EXPECT_EQ(error_of(appended("bodies: {contact: {restitution: 1.5}}\n")),
            "case.yaml:12: bodies.contact.restitution: expected a number in [0, 1], got 1.5");
  EXPECT_EQ(error_of(edited("  initial:", "  density: -1000\n  initial:")),
            "case.yaml:5: flow.density: expected a number in [500, 2500], got -1000");
  EXPECT_EQ(error_of(edited("  initial:", "  min_depth: 0\n  initial:")),
            "case.yaml:5: flow.min_depth: expected a number > 0, got 0");
  EXPECT_EQ(error_of(appended("bodies:\n  list:\n    - {x: 1, y: 2, density: -600}\n")),
            "case.yaml:14: bodies.list[0].density: expected a number in [10, 25000], got -600");
  EXPECT_EQ(error_of(appended("bodies:\n  list:\n    - {x: 1, y: 2, length: 0.5}\n")),
            "case.yaml:14: bodies.list[0].length: the width 1 m exceeds the length 0.5 m; length "
            "is the long side");
  EXPECT_EQ(error_of(edited("  initial:", "  coriolis: {latitude_deg: 95}\n  initial:")),
            "case.yaml:5: flow.coriolis.latitude_deg: expected a number in [-90, 90], got 95");
}

TEST(CaseFileError, UnknownWordListsTheAllowedOnes) {
  EXPECT_EQ(error_of(edited("law: manning", "law: manningg")),
            "case.yaml:4: flow.friction.law: unknown value 'manningg'; expected one of: none, "
            "manning, chezy, strickler (did you mean 'manning'?)");
  EXPECT_EQ(error_of(edited("step: 0.5}", "step: 0.5, mode: twoway}")),
            "case.yaml:11: time.mode: unknown value 'twoway'; expected one of: frozen, one-way, "
            "two-way (did you mean 'two-way'?)");
  EXPECT_EQ(error_of(edited("step: 0.5}", "step: 0.5, scheme: bdf3}")),
            "case.yaml:11: time.scheme: unknown value 'bdf3'; expected one of: theta, bdf2 (did "
            "you mean 'bdf2'?)");
  EXPECT_EQ(error_of(edited("step: 0.5}", "step: 0.5, steady_method: newton}")),
            "case.yaml:11: time.steady_method: unknown value 'newton'; expected one of: solve, "
            "march");
  EXPECT_EQ(error_of(edited("bank_left: {type: wall}", "bank_left: {type: slip}")),
            "case.yaml:10: flow.boundaries.bank_left.type: unknown value 'slip'; expected one "
            "of: elevation, discharge, velocity, wall, noslip, free");
}

TEST(CaseFileError, NameMustSuitAFolder) {
  EXPECT_EQ(error_of(appended("name: my river\n")),
            "case.yaml:12: name: expected a name of letters, digits, '_', '-' and '.' (it names "
            "the output folder), got 'my river'");
  EXPECT_EQ(error_of(appended("name: ..\n")),
            "case.yaml:12: name: expected a name that does not start with '.' (it names the "
            "output folder), got '..'");
  EXPECT_EQ(error_of(appended("name: " + std::string(201, 'a') + "\n")),
            "case.yaml:12: name: expected a name of at most 200 characters (it names the output "
            "folder and its files), got 201");
}

TEST(CaseFileError, TableRowsMustBeStrictlyIncreasing) {
  EXPECT_EQ(error_of(edited("value: 1.0}", "value: [[0, 1.0], [60, 1.2], [60, 1.3]]}")),
            "case.yaml:7: flow.boundaries.inflow.value[2]: t = 60 does not come after the "
            "previous row's t = 60; a table's t must be strictly increasing");
  EXPECT_EQ(error_of(edited("value: 1.0}", "value: [[0, 1.0, 2.0]]}")),
            "case.yaml:7: flow.boundaries.inflow.value[0]: expected a table row [t, value], got "
            "a list of 3");
  EXPECT_EQ(error_of(appended("bed:\n  profile_x:\n    - [0, 1]\n    - [-10, 0]\n")),
            "case.yaml:15: bed.profile_x[1]: x = -10 does not come after the previous row's x = "
            "0; a table's x must be strictly increasing");
}

TEST(CaseFileError, YamlSyntaxErrorNamesTheLine) {
  EXPECT_EQ(error_of(edited("  initial: {eta: 1.0}", "  initial: eta: 1.0")),
            "case.yaml:5: YAML syntax error: illegal map value");
  EXPECT_EQ(error_of(""),
            "case.yaml:1: the file is empty; expected a map of sections (mesh, flow, time, ...)");
}

TEST(CaseFileError, MissingCaseFileIsNamed) {
  try {
    read_case("/no/such/folder/case.yaml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "cannot open the case file '/no/such/folder/case.yaml': no such file");
  }
}

TEST(CaseFileError, KeyGivenTwiceIsAnError) {
  EXPECT_EQ(error_of(edited("  initial:", "  friction: {law: none}\n  initial:")),
            "case.yaml:5: flow.friction: given twice (first on line 4)");
}

TEST(CaseFileError, KeysThatDoNotApplyAreRejectedWithTheReason) {
  EXPECT_EQ(error_of(edited("bank_left: {type: wall}", "bank_left: {type: wall, value: 1}")),
            "case.yaml:10: flow.boundaries.bank_left.value: not allowed here: a wall takes no "
            "value");
  EXPECT_EQ(error_of(edited("{law: manning, coefficient: 0.03}", "{law: none, coefficient: 0.03}")),
            "case.yaml:4: flow.friction.coefficient: not allowed here: not used with law 'none'");
  EXPECT_EQ(error_of(edited("  initial:",
                            "  viscosity: 1e-6\n  reynolds: {number: 1000}\n  "
                            "initial:")),
            "case.yaml:6: flow.reynolds: give either 'viscosity' (line 5) or 'reynolds', not "
            "both");
  EXPECT_EQ(error_of(appended("bodies:\n  list:\n    - {x: 1, y: 2, height: 2}\n")),
            "case.yaml:14: bodies.list[0].height: not allowed here: a log's height is its width "
            "(its diameter)");
  EXPECT_EQ(error_of(appended("bodies:\n  list:\n    - {x: 1, y: 2, id: 3}\n    - {x: 5, y: 2, "
                              "id: 3}\n")),
            "case.yaml:15: bodies.list[1].id: id 3 is already used by the body on line 14");
}

TEST(CaseFileError, MeshMistakesAreNamed) {
  EXPECT_EQ(error_of(edited("  channel: {length: 100, width: 20}",
                            "  channel: {length: 100, width: 20}\n  bend: {}")),
            "case.yaml:3: mesh.bend: give either 'channel' (line 2) or 'bend', not both");
  EXPECT_EQ(error_of(edited("width: 20}", "width: 20, piers: [{x: 5, y: 10, radius: 6}]}")),
            "case.yaml:2: mesh.channel.piers[0]: a pier at (5, 10) of radius 6 m does not fit "
            "inside the channel [0, 100] x [0, 20] m; it must clear every bank");
  EXPECT_EQ(error_of(edited("width: 20}",
                            "width: 20,\n    piers: [{x: 50, y: 10, radius: 3},\n            "
                            "{x: 54, y: 10, radius: 2}]}")),
            "case.yaml:4: mesh.channel.piers[1]: overlaps pier 1 (line 3)");
  EXPECT_EQ(error_of(edited("  channel: {length: 100, width: 20}", "  file: nothere.msh")),
            "case.yaml:2: mesh.file: no such mesh file 'nothere.msh' (a relative path is read "
            "from the case file's folder)");
  EXPECT_EQ(error_of(edited("  channel: {length: 100, width: 20}",
                            "  polygon: {points: [[0, 0], [1, 0], [1, 1]], groups: [a, b]}")),
            "case.yaml:2: mesh.polygon.groups: expected one group per side, 3 (side i joins "
            "corner i to corner i+1), got 2");
}

// ---- the case against its mesh ------------------------------------------------------------

TEST(CaseAgainstMesh, ConditionOnAGroupTheMeshLacksIsNamed) {
  const Case c = parse_case(base_case, "case.yaml");
  try {
    check_case_against_mesh(c, {"inflow", "outflow", "bank_right"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "case.yaml:10: flow.boundaries.bank_left: the mesh has no boundary group "
                 "'bank_left'; its groups are: inflow, outflow, bank_right");
  }
}

TEST(CaseAgainstMesh, MeshGroupWithoutConditionIsNamed) {
  const Case c = parse_case(base_case, "case.yaml");
  try {
    check_case_against_mesh(c, {"inflow", "outflow", "bank_right", "bank_left", "pier_1"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "case.yaml: flow.boundaries: the mesh's boundary group 'pier_1' has no "
                 "condition; every group needs one (a bank or a pier: 'pier_1: {type: wall}'); "
                 "the mesh's groups are: inflow, outflow, bank_right, bank_left, pier_1");
  }
}

}  // namespace
}  // namespace flotsam

namespace flotsam {
namespace {

// bodies.contact.solver (docs/case-format.md): the soft step and its settings; each solver's own
// settings are refused with the other.
TEST(CaseFile, TheContactSolverAndItsOwnSettingsAreRead) {
  const Case c =
      parse_case(appended("bodies:\n  contact: {solver: soft_step, substeps: 6, contact_hertz: 20, "
                          "damping_ratio: 5}\n"),
                 "case.yaml");
  EXPECT_EQ(c.bodies.contact.solver, ContactSolverKind::soft_step);
  EXPECT_EQ(c.bodies.contact.substeps, 6);
  EXPECT_EQ(c.bodies.contact.contact_hertz, 20.0);
  EXPECT_EQ(c.bodies.contact.damping_ratio, 5.0);
  EXPECT_EQ(parse_case(base_case, "case.yaml").bodies.contact.solver,
            ContactSolverKind::sequential_impulses);
  EXPECT_THAT(error_of(appended("bodies:\n  contact: {solver: soft_step, iterations: 8}\n")),
              HasSubstr("iterations: not allowed here: only used with solver "
                        "'sequential_impulses'"));
  EXPECT_THAT(error_of(appended("bodies:\n  contact: {substeps: 8}\n")),
              HasSubstr("substeps: not allowed here: only used with solver 'soft_step'"));
}

}  // namespace
}  // namespace flotsam

namespace flotsam {
namespace {

// bodies.contact.sleep_time: 0.5 s by default with the soft step, 0 (never) with sequential
// impulses; either may be set.
TEST(CaseFile, SleepingIslandsAreOnByDefaultWithTheSoftStepOnly) {
  const auto contact = [](const std::string& text) {
    return parse_case(appended("bodies:\n  contact: " + text + "\n"), "case.yaml").bodies.contact;
  };
  EXPECT_EQ(contact("{solver: soft_step}").sleep_time, 0.5);
  EXPECT_EQ(contact("{solver: sequential_impulses}").sleep_time, 0.0);
  EXPECT_EQ(contact("{solver: soft_step, sleep_time: 0}").sleep_time, 0.0);
  const ContactConfig set =
      contact("{solver: sequential_impulses, sleep_time: 2, sleep_speed: 0.01}");
  EXPECT_EQ(set.sleep_time, 2.0);
  EXPECT_EQ(set.sleep_speed, 0.01);
}

}  // namespace
}  // namespace flotsam

namespace flotsam {
namespace {

// ---- bridges -------------------------------------------------------------------------------

// base_case on a polygon (mesh.channel makes its own bridges) with the finite-volume engine
// (decks need it), `bridges` appended from line 14.
std::string with_bridges(const std::string& bridges, const std::string& engine = "fv") {
  const std::string polygon =
      test::replaced(base_case, "  channel: {length: 100, width: 20}",
                     "  polygon: {points: [[0, 0], [100, 0], [100, 20], [0, 20]],\n"
                     "            groups: [bank_right, outflow, bank_left, inflow]}");
  return test::replaced(polygon, "flow:\n", "flow:\n  engine: " + engine + "\n") + bridges;
}

TEST(CaseFile, BridgesAreReadWithTheirAxisPiersAndDeck) {
  const Case c = parse_case(with_bridges("bridges:\n"
                                         "  - name: road\n"
                                         "    axis: [[50, -2], [50, 22]]\n"
                                         "    piers: [pier_1]\n"
                                         "    deck: {soffit: 2.5, top: 3.4, width: 8,\n"
                                         "           railing: {height: 1.1, open: false}}\n"
                                         "    backwater_distance: 30\n"
                                         "  - axis: [[80, -2], [80, 22]]\n"),
                            "case.yaml");
  ASSERT_EQ(c.bridges.size(), 2u);
  const BridgeConfig& road = c.bridges[0];
  EXPECT_EQ(road.name, "road");
  EXPECT_EQ(road.start, Vec2(50, -2));
  EXPECT_EQ(road.end, Vec2(50, 22));
  EXPECT_EQ(road.pier_groups, std::vector<std::string>{"pier_1"});
  ASSERT_TRUE(road.deck.has_value());
  EXPECT_EQ(road.deck->soffit, 2.5);
  EXPECT_EQ(road.deck->top, 3.4);
  EXPECT_EQ(road.deck->width, 8.0);
  EXPECT_EQ(road.deck->railing_height, 1.1);
  EXPECT_FALSE(road.deck->railing_open);
  EXPECT_EQ(road.deck->obstacle_top(), 3.4 + 1.1);
  EXPECT_EQ(road.backwater_distance, 30.0);
  EXPECT_EQ(road.origin, "case.yaml:15: bridges[0]");
  EXPECT_EQ(c.bridges[1].name, "bridge_2");
  EXPECT_FALSE(c.bridges[1].deck.has_value());
  EXPECT_EQ(c.bridges[1].backwater_distance, 0.0);  // the default, set on the mesh
}

TEST(CaseFileError, BridgeMistakesAreNamed) {
  EXPECT_EQ(error_of(appended("bridges: [{axis: [[50, -2], [50, 22]]}]\n")),
            "case.yaml:12: bridges: a mesh.channel makes one bridge of each line of its piers; "
            "bridges: is for the other meshes (mesh.polygon, mesh.region, mesh.file)");
  EXPECT_EQ(error_of(with_bridges("bridges: [{axis: [[50, -2], [50, 10], [50, 22]]}]\n")),
            "case.yaml:14: bridges[0].axis: expected the axis' two ends [[x, y], [x, y]], got 3 "
            "points");
  EXPECT_EQ(error_of(with_bridges("bridges: [{axis: [[50, 2], [50, 2]]}]\n")),
            "case.yaml:14: bridges[0].axis: bridge 'bridge_1': the axis' two ends are the same "
            "point (50, 2) m");
  EXPECT_EQ(error_of(with_bridges("bridges: [{name: a, axis: [[50, -2], [50, 22]]},\n"
                                  "          {name: a, axis: [[60, -2], [60, 22]]}]\n")),
            "case.yaml:14: bridges: two bridges are called 'a' (case.yaml:14: bridges[0] and "
            "case.yaml:15: bridges[1]); names must differ");
  EXPECT_EQ(error_of(with_bridges("bridges: [{axis: [[50, -2], [50, 22]],\n"
                                  "            deck: {soffit: 3, top: 2.5, width: 8}}]\n")),
            "case.yaml:15: bridges[0].deck.top: bridge 'bridge_1': the deck top (2.5 m) must "
            "stand above its soffit (3 m)");
  EXPECT_THAT(error_of(with_bridges("bridges: [{axis: [[50, -2], [50, 22]],\n"
                                    "            deck: {soffit: 2, top: 2.5, width: 0}}]\n")),
              HasSubstr("case.yaml:15: bridges[0].deck.width: expected a number > 0"));
  EXPECT_EQ(error_of(with_bridges("bridges: [{axis: [[50, -2], [50, 22]],\n"
                                  "            deck: {soffit: 2, top: 2.5, width: 8}}]\n",
                                  "fem")),
            "case.yaml:14: bridges[0]: bridge 'bridge_1' has a deck: the water under and over a "
            "deck is computed by the finite-volume engine only; set flow.engine: fv");
  EXPECT_THAT(error_of(with_bridges("bridges: [{axis: [[50, -2], [50, 22]], dekc: {}}]\n")),
              HasSubstr("dekc"));
}

}  // namespace
}  // namespace flotsam

namespace flotsam {
namespace {

TEST(CaseFile, BridgesFromALineLayerTakeTheirNamesAxesAndDecks) {
  const std::filesystem::path dir = test::scratch_path("flotsam_case_bridges_layer");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "bridges.geojson") << R"({"type": "FeatureCollection",
 "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::32633"}},
 "features": [
  {"type": "Feature", "properties": {"name": "road", "soffit": 2.5, "deck_top": 3.4,
                                     "deck_width": 8, "railing_height": 1.1, "railing_open": 0},
   "geometry": {"type": "LineString", "coordinates": [[50, -2], [50, 22]]}},
  {"type": "Feature", "properties": {"name": "rail"},
   "geometry": {"type": "LineString", "coordinates": [[80, -2], [80, 22]]}}]})";
  const std::string text =
      with_bridges("bridges: {file: bridges.geojson, backwater_distance: 25}\n");
  const Case c = parse_case(text, (dir / "case.yaml").string());
  ASSERT_EQ(c.bridges.size(), 2u);
  EXPECT_EQ(c.bridges[0].name, "road");
  EXPECT_EQ(c.bridges[0].start, Vec2(50, -2));
  EXPECT_EQ(c.bridges[0].end, Vec2(50, 22));
  EXPECT_EQ(c.bridges[1].name, "rail");
  EXPECT_EQ(c.bridges[1].backwater_distance, 25.0);
  EXPECT_THAT(c.bridges[1].origin, HasSubstr("bridges.geojson"));
  ASSERT_TRUE(c.bridges[0].deck.has_value());
  EXPECT_EQ(c.bridges[0].deck->soffit, 2.5);
  EXPECT_EQ(c.bridges[0].deck->top, 3.4);
  EXPECT_EQ(c.bridges[0].deck->width, 8.0);
  EXPECT_EQ(c.bridges[0].deck->railing_height, 1.1);
  EXPECT_FALSE(c.bridges[0].deck->railing_open);
  EXPECT_FALSE(c.bridges[1].deck.has_value());
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace flotsam

namespace flotsam {
namespace {

// bodies.jams (docs/case-format.md): a layer by default; an accumulation with its porosity in
// [0, 1); the porosity is refused with a layer, and a porosity of 1 (no wood) is out of range.
TEST(CaseFile, TheJamsVerticalExtentAndItsPorosityAreRead) {
  const auto jams = [](const std::string& text) {
    return parse_case(appended("bodies:\n  jams: " + text + "\n"), "case.yaml").bodies.jams;
  };
  EXPECT_EQ(parse_case(base_case, "case.yaml").bodies.jams.vertical_extent, JamExtent::layer);
  const JamConfig set = jams("{vertical_extent: accumulation, porosity: 0.7}");
  EXPECT_EQ(set.vertical_extent, JamExtent::accumulation);
  EXPECT_EQ(set.porosity, 0.7);
  EXPECT_EQ(jams("{vertical_extent: accumulation}").porosity, 0.5);
  EXPECT_THAT(error_of(appended("bodies:\n  jams: {porosity: 0.4}\n")),
              HasSubstr("porosity: not allowed here: only used with vertical_extent "
                        "'accumulation'"));
  EXPECT_THAT(error_of(appended("bodies:\n  jams: {vertical_extent: accumulation, porosity: 1}\n")),
              HasSubstr("porosity"));
  EXPECT_THAT(error_of(appended("bodies:\n  jams: {vertical_extent: stacked}\n")),
              HasSubstr("vertical_extent"));
}

}  // namespace
}  // namespace flotsam

namespace flotsam {
namespace {

// A case with an `ensemble:` section runs as written (flotsam run, info): the section is
// flotsam ensemble's, and the case read is the same as without it.
TEST(CaseFile, AnEnsembleSectionIsLeftToFlotsamEnsemble) {
  const Case with = parse_case(
      appended("ensemble:\n  members: 3\n  sweep: {input: discharge_scale, values: [0.5, 1]}\n"),
      "case.yaml");
  const Case without = parse_case(base_case, "case.yaml");
  EXPECT_EQ(with.name, without.name);
  EXPECT_EQ(with.time.end, without.time.end);
  EXPECT_EQ(with.flow.boundaries.size(), without.flow.boundaries.size());
}

}  // namespace
}  // namespace flotsam

namespace flotsam {
namespace {

// A case saved with a UTF-8 byte-order mark: its first key is read as itself, an `ensemble:`
// section first in the file included.
TEST(CaseFile, AByteOrderMarkIsNotPartOfTheFirstKey) {
  const std::string bom = "\xEF\xBB\xBF";
  const SplitCaseText split = split_ensemble_text(bom + "ensemble:\n  members: 3\nname: x\n");
  EXPECT_EQ(split.ensemble_text, "ensemble:\n  members: 3\n\n");
  EXPECT_EQ(split.case_text, "\n\nname: x\n");
  const Case with = parse_case(bom + base_case, "case.yaml");
  EXPECT_EQ(with.name, parse_case(base_case, "case.yaml").name);
}

}  // namespace
}  // namespace flotsam

namespace flotsam {
namespace {

// Geodata that would be silently wrong: building footprints drawn as closed lines (they were left
// out, and the next error blamed the boundaries), and a boundary line whose name is NULL (it
// became a group the user never named). Each is refused naming the key and the feature.
TEST(CaseFile, FootprintsAsLinesAndUnnamedBoundaryLinesAreRefusedNamingTheFeature) {
  const std::filesystem::path dir = test::fresh_test_folder("region_lines");
  write_polygon_layer((dir / "town.gpkg").string(), "outline",
                      {{{0, 0}, {200, 0}, {200, 80}, {0, 80}}}, "");
  std::ofstream(dir / "houses.geojson") << R"({"type": "FeatureCollection",
    "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::32633"}}, "features": [
    {"type": "Feature", "properties": {}, "geometry": {"type": "LineString",
     "coordinates": [[50, 20], [60, 20], [60, 30], [50, 30], [50, 20]]}}]})";
  std::ofstream(dir / "lines.geojson") << R"({"type": "FeatureCollection",
    "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::32633"}}, "features": [
    {"type": "Feature", "properties": {"name": "inflow"}, "geometry": {"type": "LineString",
     "coordinates": [[0, 80], [0, 0]]}},
    {"type": "Feature", "properties": {"name": null}, "geometry": {"type": "LineString",
     "coordinates": [[200, 0], [200, 80]]}}]})";
  const std::string rest = base_case.substr(base_case.find("flow:"));
  const auto region = [&](const std::string& boundaries, const std::string& buildings) {
    return "mesh:\n  region:\n    outline: {file: town.gpkg, layer: outline}\n    boundaries: " +
           boundaries + "\n" + buildings + "    mesh_size: 10\n" + rest;
  };
  const auto message = [&](const std::string& text) {
    try {
      parse_case(text, (dir / "case.yaml").string());
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(message(region("{inflow: [[0, 80], [0, 0]], outflow: [[200, 0], [200, 80]]}",
                             "    buildings: houses.geojson\n")),
              HasSubstr("case.yaml:5: mesh.region.buildings: houses.geojson, layer 'houses', "
                        "feature 0 is a line; expected polygons"));
  EXPECT_THAT(message(region("{file: lines.geojson}", "")),
              HasSubstr("mesh.region.boundaries: lines.geojson, layer 'lines', feature 1 has no "
                        "'name' (it is NULL); each line needs one"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace flotsam
