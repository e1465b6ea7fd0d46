// Verifies the mesh set-up runs share (coupling/mesh_setup.hpp): a finite-volume run given the
// cells, point locator and mesh checksum built once on another copy of its mesh ends in the same
// state, bit for bit, and writes the same checkpoint as the run that builds its own.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "../support/scratch_path.hpp"
#include "../support/straight_channel.hpp"
#include "coupling/mesh_setup.hpp"
#include "coupling/simulation.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

namespace fs = std::filesystem;

std::string text_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(MeshSetup, ARunGivenTheSharedSetUpIsTheRunThatBuildsItsOwnBitForBit) {
  const fs::path base = test::scratch_path("flotsam_mesh_setup_test");
  fs::remove_all(base);
  Case c = test::straight_channel_case("setup", 40.0, 2.0);
  c.flow.engine = FlowEngineKind::fv;
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = 0.03;
  c.time = {.end = 8.0, .step = 1.0, .mode = CouplingMode::one_way};
  c.output.interval = 4.0;
  test::add_colliding_logs_and_release(c, 6.0);
  const Mesh mesh = make_rectangle_mesh({.length = 200, .width = 20, .nx = 40, .ny = 8});
  const auto setup = std::make_shared<const MeshSetup>(prepare_mesh_setup(mesh, c));
  ASSERT_TRUE(setup->cells && setup->locator);
  EXPECT_EQ(setup->cells->cell_count, mesh.element_count());  // cells = elements, the default
  EXPECT_EQ(setup->mesh_checksum, mesh_checksum(mesh));

  Simulation own(c, mesh, {.output_directory = base / "own", .progress = false});
  own.run();
  Simulation shared(c, mesh,
                    {.output_directory = base / "shared", .progress = false, .mesh_setup = setup});
  shared.run();
  ASSERT_EQ(own.bodies().size(), shared.bodies().size());
  ASSERT_GE(own.bodies().size(), 5);
  for (int i = 0; i < own.bodies().size(); ++i) {
    EXPECT_EQ(own.bodies().position[i].x(), shared.bodies().position[i].x()) << "body " << i;
    EXPECT_EQ(own.bodies().position[i].y(), shared.bodies().position[i].y()) << "body " << i;
    EXPECT_EQ(own.bodies().angle[i], shared.bodies().angle[i]) << "body " << i;
  }
  EXPECT_EQ(own.flow().eta(), shared.flow().eta());
  for (const char* file : {"checkpoint.bin", "flow_000002.vtu", "setup_bodies.csv"})
    EXPECT_EQ(text_of(base / "own" / file), text_of(base / "shared" / file)) << file;
}

}  // namespace
}  // namespace flotsam
