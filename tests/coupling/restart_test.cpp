// Verifies that a run stopped at an output and restarted from its checkpoint (--restart) ends
// in the same state, bit for bit, as the run that was never stopped: flow, bodies (with
// contacts and bodies released from a line by a seeded random stream), water balance, and the
// tables it writes.
#include <gdal_priv.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <netcdf.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../support/scratch_path.hpp"
#include "../support/straight_channel.hpp"
#include "core/error.hpp"
#include "coupling/simulation.hpp"
#include "flow/fv/fv_engine.hpp"
#include "geo/gdal_support.hpp"
#include "geo/raster.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

namespace fs = std::filesystem;

Case restart_case(double end) {
  Case c = test::straight_channel_case("restart", 40.0, 2.0);
  c.flow.viscosity = 0.01;
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = 0.03;
  c.time = {.end = end, .step = 1.0, .mode = CouplingMode::two_way};
  c.output.interval = 4.0;
  c.output.probes = {{"gauge", Vec2(100.0, 10.0)}};
  test::add_colliding_logs_and_release(c, 10.0);
  return c;
}

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Restart, ContinuesToTheSameEndStateBitForBit) {
  const fs::path base = test::scratch_path("flotsam_restart_test");
  fs::remove_all(base);
  const Mesh mesh = make_rectangle_mesh({.length = 200, .width = 20, .nx = 40, .ny = 8});
  auto options = [&](const std::string& dir, bool restart) {
    return RunOptions{.output_directory = base / dir,
                      .overwrite = false,
                      .write_output = true,
                      .progress = false,
                      .restart = restart};
  };
  Simulation whole(restart_case(12.0), mesh, options("whole", false));
  whole.run();
  {
    Simulation first_part(restart_case(8.0), mesh, options("split", false));
    first_part.run();
  }
  Simulation rest(restart_case(12.0), mesh, options("split", true));
  rest.run();

  EXPECT_EQ(rest.step_count(), whole.step_count());
  EXPECT_EQ(rest.time(), whole.time());
  EXPECT_EQ(rest.flow().eta(), whole.flow().eta());
  EXPECT_EQ(rest.flow().u(), whole.flow().u());
  EXPECT_EQ(rest.flow().v(), whole.flow().v());
  EXPECT_EQ(rest.flow().water_balance().outflow, whole.flow().water_balance().outflow);
  const BodySet &a = whole.bodies(), &b = rest.bodies();
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), 3);  // bodies were released before and after the stop
  for (int i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a.position[i], b.position[i]) << "body " << i;
    EXPECT_EQ(a.velocity[i], b.velocity[i]) << "body " << i;
    EXPECT_EQ(a.angle[i], b.angle[i]) << "body " << i;
    EXPECT_EQ(a.angular_velocity[i], b.angular_velocity[i]) << "body " << i;
  }
  for (const char* table : {"restart_bodies.csv", "restart_balance.csv", "restart_jams.csv",
                            "restart_probes.csv", "restart.pvd", "restart_bodies.pvd"})
    EXPECT_EQ(text_of(base / "split" / table), text_of(base / "whole" / table)) << table;
  fs::remove_all(base);
}

/// The lines of a text file.
std::vector<std::string> lines_of(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

const char* const tables[] = {"restart_bodies.csv", "restart_balance.csv", "restart_jams.csv",
                              "restart_probes.csv"};

RunOptions options_in(const fs::path& dir, bool restart) {
  return {.output_directory = dir, .progress = false, .restart = restart};
}

// A run killed while it wrote its output at 8 s: after its tables and fields, while it wrote the
// new checkpoint (a cut checkpoint.bin.part and a cut field file beside the checkpoint of 4 s).
// The restart drops the tables' rows of 8 s and later and writes them once: every table and
// every other file of the restarted run (fields, states, indexes, checkpoint) equals the
// uninterrupted run's, line by line.
TEST(Restart, RewindsEveryTableToTheCheckpoint) {
  const fs::path base = test::fresh_test_folder("restart");
  const Mesh mesh = make_rectangle_mesh({.length = 200, .width = 20, .nx = 40, .ny = 8});
  Simulation(restart_case(12.0), mesh, options_in(base / "whole", false)).run();
  const fs::path split = base / "split";
  Simulation(restart_case(4.0), mesh, options_in(split, false)).run();
  fs::copy_file(split / "checkpoint.bin", base / "checkpoint_4s.bin");
  Simulation(restart_case(8.0), mesh, options_in(split, true)).run();
  const std::string checkpoint_8s = text_of(split / "checkpoint.bin");
  std::ofstream(split / "checkpoint.bin.part") << checkpoint_8s.substr(0, 100);
  std::ofstream(split / "flow_000002.vtu.part") << "<?xml";
  fs::copy_file(base / "checkpoint_4s.bin", split / "checkpoint.bin",
                fs::copy_options::overwrite_existing);
  Simulation rest(restart_case(12.0), mesh, options_in(split, true));
  rest.run();
  for (const char* table : tables)
    EXPECT_EQ(lines_of(split / table), lines_of(base / "whole" / table)) << table;
  int files = 0;
  for (const auto& entry : fs::directory_iterator(base / "whole")) {
    const fs::path name = entry.path().filename();
    EXPECT_TRUE(fs::exists(split / name)) << name;
    EXPECT_EQ(lines_of(split / name), lines_of(entry.path())) << name;
    ++files;
  }
  // Flow fields, bodies and states at 0, 4, 8, 12 s, 4 tables, 2 indexes, the boundary, run.bin,
  // the checkpoint and the folder's marker.
  EXPECT_EQ(files, 3 * 4 + 4 + 2 + 4);
  for (const auto& entry : fs::directory_iterator(split))
    EXPECT_NE(entry.path().extension(), ".part") << entry.path();
}

// A table removed before a restart is written again: its header, then the rows after the
// checkpoint's time, as the uninterrupted run writes them.
TEST(Restart, WritesAMissingTableAgainWithItsHeader) {
  const fs::path base = test::fresh_test_folder("restart");
  const Mesh mesh = make_rectangle_mesh({.length = 200, .width = 20, .nx = 40, .ny = 8});
  Simulation(restart_case(12.0), mesh, options_in(base / "whole", false)).run();
  const fs::path split = base / "split";
  Simulation(restart_case(8.0), mesh, options_in(split, false)).run();
  for (const char* table : tables) fs::remove(split / table);
  Simulation(restart_case(12.0), mesh, options_in(split, true)).run();
  for (const char* table : tables) {
    const auto whole = lines_of(base / "whole" / table), rest = lines_of(split / table);
    std::vector<std::string> expected = {whole.front()};
    for (std::size_t k = 1; k < whole.size(); ++k)
      if (std::stod(whole[k]) > 8.0) expected.push_back(whole[k]);
    EXPECT_EQ(rest, expected) << table;
    EXPECT_GT(expected.size(), 1u) << table;
  }
}

/// Every value of NetCDF variable `name` in `path` (the UGRID results).
std::vector<double> netcdf_values(const fs::path& path, const char* name) {
  int id = -1, var = -1, dims = 0, dim[NC_MAX_VAR_DIMS];
  EXPECT_EQ(nc_open(path.c_str(), NC_NOWRITE, &id), NC_NOERR) << path;
  EXPECT_EQ(nc_inq_varid(id, name, &var), NC_NOERR) << name;
  nc_inq_varndims(id, var, &dims);
  nc_inq_vardimid(id, var, dim);
  std::size_t count = 1;
  for (int k = 0; k < dims; ++k) {
    std::size_t length = 0;
    nc_inq_dimlen(id, dim[k], &length);
    count *= length;
  }
  std::vector<double> values(count);
  EXPECT_EQ(nc_get_var_double(id, var, values.data()), NC_NOERR) << name;
  nc_close(id);
  return values;
}

/// The body ids and times of the debris tracks in `path`, in order.
std::vector<std::pair<long, double>> tracks_of(const fs::path& path) {
  gdal::Dataset d(static_cast<GDALDataset*>(
      GDALOpenEx(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
  std::vector<std::pair<long, double>> rows;
  if (!d) {
    ADD_FAILURE() << "cannot open " << path;
    return rows;
  }
  OGRLayer& tracks = *d->GetLayerByName("tracks");
  for (const auto& f : tracks)
    rows.emplace_back(static_cast<long>(f->GetFieldAsInteger64("body")),
                      f->GetFieldAsDouble("t_s"));
  return rows;
}

// The finite-volume engine's flood envelopes (running maxima, arrival, wet duration, hazard) and
// their rasters continue across a restart as if the run had never stopped; so do the UGRID file
// and the debris layers.
TEST(Restart, KeepsTheFloodEnvelopesBitForBit) {
  const fs::path base = test::scratch_path("flotsam_restart_envelope_test");
  fs::remove_all(base);
  const Mesh mesh = make_rectangle_mesh({.length = 200, .width = 20, .nx = 40, .ny = 8});
  auto flood = [](double end) {
    Case c = restart_case(end);
    c.flow.engine = FlowEngineKind::fv;
    c.flow.initial_eta = Expression("x < 50 ? 1.6 : 1.0", "test");  // a surge down the channel
    c.output.raster_resolution = 2.0;
    c.output.formats = {true, true, true};
    return c;
  };
  auto options = [&](const std::string& dir, bool restart) {
    return RunOptions{.output_directory = base / dir, .progress = false, .restart = restart};
  };
  Simulation whole(flood(12.0), mesh, options("whole", false));
  whole.run();
  {
    Simulation first_part(flood(8.0), mesh, options("split", false));
    first_part.run();
  }
  Simulation rest(flood(12.0), mesh, options("split", true));
  rest.run();
  const FloodEnvelope& a = dynamic_cast<const FvEngine&>(whole.flow()).envelope();
  const FloodEnvelope& b = dynamic_cast<const FvEngine&>(rest.flow()).envelope();
  EXPECT_EQ(a.max_depth, b.max_depth);
  EXPECT_EQ(a.max_speed, b.max_speed);
  EXPECT_EQ(a.max_unit_discharge, b.max_unit_discharge);
  EXPECT_EQ(a.wet_duration, b.wet_duration);
  EXPECT_EQ(a.max_hazard_rating, b.max_hazard_rating);
  EXPECT_EQ(a.australian_class, b.australian_class);
  EXPECT_EQ(a.vehicle_class, b.vehicle_class);
  ASSERT_EQ(a.arrival.size(), b.arrival.size());
  for (std::size_t i = 0; i < a.arrival.size(); ++i)
    EXPECT_TRUE(a.arrival[i] == b.arrival[i] ||
                (std::isnan(a.arrival[i]) && std::isnan(b.arrival[i])));
  EXPECT_GT(*std::max_element(a.max_speed.begin(), a.max_speed.end()), 0.5);  // the surge passed
  const Raster ra = Raster::read((base / "whole" / "restart_max_depth.tif").string(), "test");
  const Raster rb = Raster::read((base / "split" / "restart_max_depth.tif").string(), "test");
  for (int r = 0; r < ra.grid().rows; ++r)
    for (int c = 0; c < ra.grid().columns; ++c) EXPECT_EQ(ra.at(c, r), rb.at(c, r));
  for (const char* name : {"time", "depth", "ux", "hazard_rating", "max_depth"}) {
    const auto whole_values = netcdf_values(base / "whole" / "restart.nc", name);
    EXPECT_EQ(whole_values, netcdf_values(base / "split" / "restart.nc", name)) << name;
    if (std::string(name) == "time") {
      EXPECT_EQ(whole_values, (std::vector<double>{0, 4, 8, 12}));
    }
  }
  const auto tracks = tracks_of(base / "whole" / "restart_debris.gpkg");
  EXPECT_EQ(tracks, tracks_of(base / "split" / "restart_debris.gpkg"));
  EXPECT_GE(tracks.size(), 4u);  // the bodies at each of the 4 outputs
  fs::remove_all(base);
}

TEST(Restart, WithoutACheckpointIsAnErrorNamingTheFolder) {
  const fs::path dir = test::scratch_path("flotsam_restart_none");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const Mesh mesh = make_rectangle_mesh({.length = 200, .width = 20, .nx = 40, .ny = 8});
  Simulation s(restart_case(4.0), mesh,
               {.output_directory = dir,
                .overwrite = false,
                .write_output = true,
                .progress = false,
                .restart = true});
  try {
    s.initialize();
    FAIL() << "restarted without a checkpoint";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("holds no checkpoint.bin"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr(dir.string()));
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace flotsam

namespace flotsam {
namespace {

// A jam held against a deck, as an accumulation (bodies.jams, docs/model.md "Vertical extent of
// a jam"): the bodies' wetted heights come from the last contact solve and are kept in the
// checkpoint, so the restarted run goes on bit for bit (finite volumes, the deck's hydraulics).
// The logs (tops 0.15 m above the water) stop against the deck (soffit 0.1 m above it) by t = 8 s
// and stay there, in contact every step (docs/model.md "Pose update from the interval's start"),
// all four acting over the jam's thickness, in the checkpoint at 15 s too.
Case jam_at_deck_case(double end) {
  Case c = test::straight_channel_case("deck", 30.0, 2.0);
  c.flow.engine = FlowEngineKind::fv;
  c.flow.initial_u = Expression("0.75", "test: flow.initial.u");
  c.time = {.end = end, .step = 1.0, .mode = CouplingMode::two_way};
  c.output.interval = 5.0;
  c.bodies.contact.restitution = 0.0;
  c.bodies.jams = {.vertical_extent = JamExtent::accumulation, .porosity = 0.5};
  test::add_logs_across(c, {24.0, 26.0}, {5.0, 15.0});
  c.bridges = {{.name = "bridge",
                .start = Vec2(30.0, -1.0),
                .end = Vec2(30.0, 21.0),
                .pier_groups = {},
                .deck = DeckConfig{.soffit = 2.1, .top = 2.9, .width = 2.0},
                .backwater_distance = 0.0,
                .origin = "test"}};
  return c;
}

TEST(Restart, AJamAgainstADeckGoesOnWithItsThicknessBitForBit) {
  const fs::path base = test::fresh_test_folder("restart_deck");
  const Mesh mesh = make_rectangle_mesh({.length = 100, .width = 20, .nx = 50, .ny = 10});
  Simulation whole(jam_at_deck_case(30.0), mesh, options_in(base / "whole", false));
  whole.initialize();
  int thick_at_restart = 0;  // bodies acting over their jam's T at 15 s: in the checkpoint
  double jammed_from = -1.0, let_go_at = -1.0;  // [s] all four thick; one of them not, after
  while (!whole.done()) {
    whole.step();
    int thick = 0;
    for (int i = 0; i < whole.bodies().size(); ++i)
      thick += whole.bodies().wetted_height[i] > whole.bodies().draft[i];
    if (std::abs(whole.time() - 15.0) < 1e-9) thick_at_restart = thick;
    if (thick == 4 && jammed_from < 0.0) jammed_from = whole.time();
    if (thick < 4 && jammed_from >= 0.0 && let_go_at < 0.0) let_go_at = whole.time();
  }
  // Held against the deck, the raft stays in contact with it every step (no back-off).
  EXPECT_GE(jammed_from, 0.0);
  EXPECT_LT(let_go_at, 0.0) << "jammed from " << jammed_from << " s, one log let go at "
                            << let_go_at << " s";
  whole.write_final_output();
  Simulation(jam_at_deck_case(15.0), mesh, options_in(base / "split", false)).run();
  Simulation rest(jam_at_deck_case(30.0), mesh, options_in(base / "split", true));
  rest.run();
  const BodySet &a = whole.bodies(), &b = rest.bodies();
  ASSERT_EQ(a.size(), 4);
  for (int i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(a.position[i].x(), i < 2 ? 28.1 : 28.7, 0.05) << "body " << i;  // at the deck
    EXPECT_EQ(a.position[i], b.position[i]) << "body " << i;
    EXPECT_EQ(a.velocity[i], b.velocity[i]) << "body " << i;
    EXPECT_EQ(a.wetted_height[i], b.wetted_height[i]) << "body " << i;
  }
  EXPECT_EQ(thick_at_restart, 4);
  EXPECT_EQ(rest.flow().eta(), whole.flow().eta());
  EXPECT_EQ(lines_of(base / "split" / "deck_jams.csv"), lines_of(base / "whole" / "deck_jams.csv"));
  fs::remove_all(base);
}

}  // namespace
}  // namespace flotsam
