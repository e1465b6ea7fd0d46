// Verifies that values legal as numbers but absurd for a case are refused at input, naming the
// key (issue 20 item 4): a magnitude beyond 1e9, densities and sizes outside their physical
// ranges, a viscosity of 0 under the Ganser drag; and that the run's size is estimated from the
// case before meshing, a mesh too large for memory refused naming the file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "../support/case_error.hpp"
#include "../support/scratch_path.hpp"
#include "core/error.hpp"
#include "io/case_estimate.hpp"
#include "io/case_file.hpp"

namespace flotsam {
namespace {

const std::string base_case = R"(mesh:
  channel: {length: 100, width: 20, mesh_size: 2}
flow:
  friction: {law: manning, coefficient: 0.03}
  initial: {eta: 1.0}
  boundaries:
    inflow: {type: elevation, value: 1.0}
    outflow: {type: elevation, value: 0.9}
    bank_right: {type: wall}
    bank_left: {type: wall}
time: {end: 10, step: 0.5}
output: {interval: 2}
)";

// base_case with `from` replaced by `to` (`from` must occur).
std::string edited(const std::string& from, const std::string& to) {
  return test::replaced(base_case, from, to);
}

using test::error_of;  // tests/support/case_error.hpp

TEST(CaseRanges, AbsurdValuesAreRefusedNamingTheKey) {
  EXPECT_EQ(error_of(base_case + "bodies:\n  list:\n    - {x: 1, y: 2, density: 1e308}\n"),
            "case.yaml:15: bodies.list[0].density: expected a number in [10, 25000] of magnitude "
            "at most 1e+09 (no key needs more), got 1e308");
  EXPECT_EQ(error_of(base_case + "bodies:\n  list:\n    - {x: 1, y: 2, density: 30000}\n"),
            "case.yaml:15: bodies.list[0].density: expected a number in [10, 25000], got 30000");
  EXPECT_EQ(error_of(edited("length: 100", "length: 1e308")),
            "case.yaml:2: mesh.channel.length: expected a number > 0 of magnitude at most 1e+09 "
            "(no key needs more), got 1e308");
  EXPECT_EQ(error_of(edited("end: 10", "end: 1e308")),
            "case.yaml:11: time.end: expected a number > 0 of magnitude at most 1e+09 (no key "
            "needs more), got 1e308");
  EXPECT_EQ(error_of(base_case + "bodies:\n  list:\n    - {x: 1, y: 2, length: 5000}\n"),
            "case.yaml:15: bodies.list[0].length: expected a number in (0, 1000], got 5000");
}

TEST(CaseRanges, GanserDragNeedsAViscosity) {
  const std::string still = edited("  initial:", "  viscosity: 0\n  initial:");
  EXPECT_EQ(error_of(still), "no error");  // no bodies: a flow without viscosity is fine
  EXPECT_EQ(error_of(still + "bodies:\n  list:\n    - {x: 1, y: 2}\n"),
            "case.yaml:5: flow.viscosity: the Ganser drag of the bodies needs a viscosity > 0 "
            "(its Reynolds number divides by it); give the water's, 1e-6 m^2/s, or set "
            "bodies.physics.drag_law: constant");
  EXPECT_EQ(error_of(still + "bodies:\n  physics: {drag_law: constant}\n  list:\n    - {x: 1, "
                             "y: 2}\n"),
            "no error");
}

TEST(CaseEstimate, CountsElementsStepsAndOutputs) {
  const RunEstimate e = estimate_run(parse_case(base_case, "case.yaml"));
  // 100 m x 20 m in equilateral triangles of side 2 m: 2000 / (sqrt(3)/4 * 4) = 1154.7
  EXPECT_NEAR(e.elements, 2000.0 / (std::sqrt(3.0) / 4.0 * 4.0), 1e-9);
  EXPECT_EQ(e.steps, 20.0);
  EXPECT_EQ(e.outputs, 6.0);
  EXPECT_FALSE(is_large(e));

  const Case huge = parse_case(edited("mesh_size: 2", "mesh_size: 0.001"), "case.yaml");
  const RunEstimate h = estimate_run(huge);
  EXPECT_TRUE(is_large(h));
  EXPECT_EQ(describe_estimate(h),
            "about 4.6e+09 elements, 20 steps, 6 outputs, about 1.7e+04 GB "
            "of output");
  try {
    check_estimate(huge, h);
    FAIL() << "a mesh of 4.6e9 elements was accepted";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), ::testing::StartsWith("case.yaml: mesh: the domain and its mesh_size "
                                                    "make about 4.6e+09 elements"));
  }
}

// A mesh file's triangles are counted in the file (mesh/msh_check.hpp) before it is read: two
// triangles, four lines and a point in a hand-written MSH 2.2 file.
TEST(CaseEstimate, CountsTheTrianglesOfAMeshFile) {
  const auto folder = test::fresh_test_folder("flotsam_case_estimate");
  const std::string path = (folder / "square.msh").string();
  std::ofstream(path) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n"
                         "3 1 1 0\n4 0 1 0\n$EndNodes\n$Elements\n7\n1 15 2 0 1 1\n"
                         "2 1 2 1 1 1 2\n3 1 2 1 1 2 3\n4 1 2 1 1 3 4\n5 1 2 1 1 4 1\n"
                         "6 2 2 2 1 1 2 3\n7 2 2 2 1 1 3 4\n$EndElements\n";
  Case c = parse_case(base_case, "case.yaml");
  c.mesh.kind = MeshSource::Kind::file;
  c.mesh.file = path;
  const RunEstimate e = estimate_run(c);
  EXPECT_TRUE(e.counted);
  EXPECT_EQ(e.elements, 2.0);
  EXPECT_EQ(e.steps, 20.0);
  EXPECT_EQ(e.outputs, 6.0);
  EXPECT_EQ(describe_estimate(e), "2 elements, 20 steps, 6 outputs, about 7.2e-06 GB of output");
  std::ofstream(path, std::ios::app) << "$Periodic\n0\n$EndPeriodic\n";  // damaged: refused
  EXPECT_THROW(estimate_run(c), InputError);
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace flotsam
