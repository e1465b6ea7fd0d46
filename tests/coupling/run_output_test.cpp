// Verifies that a run's --overwrite never deletes a file the case reads (issue 20 item 5): a mesh
// file kept in the output folder of an earlier run stops the run, named with its key.
#include "coupling/run_output.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../support/scratch_path.hpp"
#include "core/error.hpp"
#include "coupling/simulation.hpp"
#include "io/case_file.hpp"
#include "io/output_directory.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

namespace fs = std::filesystem;

TEST(RunOutput, OverwriteKeepsTheMeshFileTheCaseReads) {
  const fs::path folder = test::fresh_test_folder("run_output") / "run";
  prepare_output_directory(folder.string(), false);  // an earlier run's folder
  const fs::path mesh_file = folder / "channel.msh";
  std::ofstream(mesh_file) << "$MeshFormat\n";  // read by the case; the run is given its mesh
  const Case c = parse_case("mesh: {file: " + mesh_file.string() + R"(}
flow:
  initial: {eta_start: 2, eta_end: 2}
  boundaries:
    left: {type: discharge, value: 40}
    right: {type: elevation, value: 2}
    bottom: {type: wall}
    top: {type: wall}
time: {end: 1, step: 1}
)",
                            (folder.parent_path() / "channel.yaml").string());
  Simulation run(c, make_rectangle_mesh({.length = 200, .width = 20, .nx = 40, .ny = 8}),
                 {.output_directory = folder, .overwrite = true, .progress = false});
  try {
    run.run();
    FAIL() << "the run emptied the folder holding its mesh file";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("contains '" + mesh_file.string() +
                                               "', which the case reads (mesh.file)"));
  }
  EXPECT_TRUE(fs::exists(mesh_file));
}

}  // namespace
}  // namespace flotsam
