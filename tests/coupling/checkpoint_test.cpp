// Verifies that a restart continues only the run its checkpoint belongs to: a case edited since
// (any key but time.end and the output folder; output settings only when asked) is refused
// naming each key, and a damaged checkpoint (bytes appended, a bit flipped, a body moved far
// outside the domain with its checksum recomputed) is refused naming the file, never the case.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <regex>
#include <sstream>

#include "../support/case_error.hpp"
#include "../support/scratch_path.hpp"
#include "core/error.hpp"
#include "coupling/simulation.hpp"
#include "io/binary_archive.hpp"
#include "io/case_file.hpp"
#include "io/record_checksum.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// The straight channel of tests/support/straight_channel.hpp as a case file, with one log (the
// run is given the same rectangle as a structured mesh).
const std::string case_text = R"(name: edited
mesh:
  polygon:
    points: [[0, 0], [200, 0], [200, 20], [0, 20]]
    groups: [bottom, right, top, left]
    mesh_size: 5
flow:
  viscosity: 0.01
  friction: {law: manning, coefficient: 0.03}
  initial: {eta_start: 2, eta_end: 2}
  boundaries:
    left: {type: discharge, value: 40}
    right: {type: elevation, value: 2}
    bottom: {type: wall}
    top: {type: wall}
time: {end: 4, step: 1, mode: two-way}
bodies:
  list:
    - {length: 6, width: 0.5, density: 600, x: 40, y: 10}
output: {interval: 2}
)";

Mesh channel_mesh() {
  return make_rectangle_mesh({.length = 200, .width = 20, .nx = 40, .ny = 8});
}

/// The case text with `from` replaced by `to` (once), parsed.
Case edited_case(const std::string& from = "", const std::string& to = "") {
  std::string text = case_text;
  if (!from.empty()) text.replace(text.find(from), from.size(), to);
  return parse_case(text, "edited.yaml");
}

/// Runs the case to 2 s in `folder` (writing its checkpoint there).
void run_first_part(const fs::path& folder) {
  Case c = edited_case();
  c.time.end = 2.0;
  Simulation first(std::move(c), channel_mesh(), {.output_directory = folder, .progress = false});
  first.run();
}

/// The message of the InputError that restarting `c` in `folder` raises ("" when none).
std::string restart_error(Case c, const fs::path& folder, bool accept_output_changes = false) {
  Simulation rest(std::move(c), channel_mesh(),
                  {.output_directory = folder,
                   .progress = false,
                   .restart = true,
                   .accept_output_changes = accept_output_changes});
  try {
    rest.run();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Checkpoint, RestartRefusesAnEditedCaseNamingEachKey) {
  const fs::path folder = test::fresh_test_folder("checkpoint");
  run_first_part(folder);
  Case edited = edited_case("viscosity: 0.01", "viscosity: 0.02");
  const std::string message = restart_error(edited, folder);
  EXPECT_THAT(message, HasSubstr((folder / "checkpoint.bin").string()));
  EXPECT_THAT(message, HasSubstr("flow.viscosity: 0.01 then, 0.02 now"));
  EXPECT_THAT(restart_error(edited_case("density: 600", "density: 700"), folder),
              HasSubstr("bodies.list[0].density: 600 then, 700 now"));
  EXPECT_THAT(restart_error(
                  edited_case("    - {length: 6", "    - {x: 60, y: 5}\n    - {length: 6"), folder),
              HasSubstr("bodies.list[1].x: added (40)"));
  EXPECT_THAT(restart_error(edited_case("name: edited", "name: renamed"), folder),
              HasSubstr("name: edited then, renamed now"));
  // Writing a default value out is a change too: the case is not the same text.
  EXPECT_THAT(restart_error(edited_case("mode: two-way}", "mode: two-way, scheme: theta}"), folder),
              HasSubstr("time.scheme: added (theta)"));
}

// Each edit a user makes between a run and its restart (issue 20 item 1): physics, numerics,
// boundaries, bodies, contacts, releases and their seeds. Each is refused with its key and two
// values; the case carries a release line here, so that its seed can change.
TEST(Checkpoint, RestartRefusesEveryKindOfEditNamingTheKey) {
  const std::string with_release = test::replaced(
      case_text, "bodies:\n  list:",
      "bodies:\n  release:\n    - {line: [[20, 5], [20, 15]], rate: 30, end: 3, seed: 3}\n"
      "  list:");
  const fs::path folder = test::fresh_test_folder("checkpoint");
  {
    Case c = parse_case(with_release, "edited.yaml");
    c.time.end = 2.0;
    Simulation(std::move(c), channel_mesh(), {.output_directory = folder, .progress = false}).run();
  }
  const struct {
    std::string from, to, message;
  } edits[] = {
      {"coefficient: 0.03", "coefficient: 0.04", "flow.friction.coefficient: 0.03 then, 0.04 now"},
      {"step: 1,", "step: 0.5,", "time.step: 1 then, 0.5 now"},
      {"mode: two-way", "mode: one-way", "time.mode: two-way then, one-way now"},
      {"value: 2}", "value: 2.5}", "flow.boundaries.right.value: 2 then, 2.5 now"},
      {"  viscosity:", "  gravity: 9.8\n  viscosity:", "flow.gravity: added (9.8)"},
      {"  release:", "  contact: {restitution: 0.5}\n  release:",
       "bodies.contact.restitution: added (0.5)"},
      {"seed: 3", "seed: 4", "bodies.release[0].seed: 3 then, 4 now"},
  };
  for (const auto& edit : edits) {
    SCOPED_TRACE(edit.message);
    const Case edited = parse_case(test::replaced(with_release, edit.from, edit.to), "edited.yaml");
    EXPECT_THAT(restart_error(edited, folder), HasSubstr(edit.message));
  }
  EXPECT_EQ(restart_error(parse_case(with_release, "edited.yaml"), folder), "");  // unchanged
}

TEST(Checkpoint, RestartTakesALaterEndAndOutputChangesOnlyWhenAsked) {
  const fs::path folder = test::fresh_test_folder("checkpoint");
  run_first_part(folder);
  const Case later = edited_case("interval: 2", "interval: 1");
  const std::string refused = restart_error(later, folder);
  EXPECT_THAT(refused, HasSubstr("output.interval: 2 then, 1 now"));
  EXPECT_THAT(refused, HasSubstr("--accept-output-changes"));
  EXPECT_EQ(restart_error(later, folder, true), "");  // to time.end = 4 s, outputs every second
  std::ifstream balance(folder / "edited_balance.csv");
  const auto rows = std::count(std::istreambuf_iterator<char>(balance), {}, '\n') - 1;
  EXPECT_EQ(rows, 2 + 2);  // 0 and 2 s, then 3 and 4 s
}

/// The mesh with its elements in reverse order: the same mesh in another numbering, as a run of
/// an older flotsam (which kept Gmsh's order) numbered it.
Mesh with_elements_reversed(Mesh mesh) {
  const int last = mesh.element_count() - 1;
  std::reverse(mesh.elements.begin(), mesh.elements.end());
  std::reverse(mesh.neighbours.begin(), mesh.neighbours.end());
  std::reverse(mesh.area.begin(), mesh.area.end());
  std::reverse(mesh.element_tags.begin(), mesh.element_tags.end());
  for (auto& across : mesh.neighbours)
    for (int& e : across)
      if (!Mesh::is_boundary(e)) e = last - e;
  for (auto& edge : mesh.boundary) edge.element = last - edge.element;
  return mesh;
}

// build_mesh numbers every mesh along a curve (docs/mesh.md): a checkpoint written by a flotsam
// that numbered the same mesh otherwise is refused by its mesh checksum, with the usual message.
TEST(Checkpoint, RestartRefusesTheSameMeshInAnotherNumbering) {
  const fs::path folder = test::fresh_test_folder("checkpoint");
  Case c = edited_case();
  c.time.end = 2.0;
  Simulation(std::move(c), with_elements_reversed(channel_mesh()),
             {.output_directory = folder, .progress = false})
      .run();
  const std::string message = restart_error(edited_case(), folder);
  EXPECT_THAT(message, HasSubstr((folder / "checkpoint.bin").string()));
  EXPECT_THAT(message, HasSubstr("the mesh (its nodes, elements and groups): "));
  EXPECT_THAT(message, HasSubstr("run the case afresh"));
}

/// Bytes of a file.
std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_bytes(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

TEST(Checkpoint, RestartRefusesADamagedCheckpointNamingTheFile) {
  const fs::path folder = test::fresh_test_folder("checkpoint");
  run_first_part(folder);
  const fs::path checkpoint = folder / "checkpoint.bin";
  const std::string good = bytes_of(checkpoint);

  write_bytes(checkpoint, good + "junk");
  std::string message = restart_error(edited_case(), folder);
  EXPECT_THAT(message, HasSubstr(checkpoint.string()));
  EXPECT_THAT(message, HasSubstr("4 bytes after its last record"));

  std::string flipped = good;
  flipped[good.size() / 2] ^= 0x10;  // one bit, somewhere in the flow's records
  write_bytes(checkpoint, flipped);
  message = restart_error(edited_case(), folder);
  EXPECT_THAT(message, HasSubstr(checkpoint.string()));
  EXPECT_THAT(message, HasSubstr("is damaged"));

  write_bytes(checkpoint, good.substr(0, good.size() - 100));
  EXPECT_THAT(restart_error(edited_case(), folder), HasSubstr("truncated"));
}

/// Rewrites record `name` of the archive at `file` through `edit`, with its checksum
/// recomputed (the layout of io/binary_archive.hpp): what a checksum cannot catch.
void patch_record(const fs::path& file, const std::string& name,
                  const std::function<void(char*)>& edit) {
  std::string bytes = bytes_of(file);
  std::size_t at = 16 + 4;  // signature, version
  while (at < bytes.size()) {
    const std::size_t start = at;
    std::uint32_t length = 0, size = 0;
    std::uint64_t count = 0;
    std::memcpy(&length, &bytes[at], 4);
    const std::string found = bytes.substr(at + 4, length);
    at += 4 + length;
    std::memcpy(&size, &bytes[at], 4);
    std::memcpy(&count, &bytes[at + 4], 8);
    at += 12;
    if (found == name) {
      edit(&bytes[at]);
      const auto sum = record_checksum_for(archive_version);
      sum->add(&bytes[start], at + size * count - start);
      const std::uint64_t check = sum->value();
      std::memcpy(&bytes[at + size * count], &check, 8);
      write_bytes(file, bytes);
      return;
    }
    at += size * count + 8;
  }
  FAIL() << "no record " << name;
}

TEST(Checkpoint, RestartRefusesABodyFarOutsideTheDomainNamingIt) {
  const fs::path folder = test::fresh_test_folder("checkpoint");
  run_first_part(folder);
  patch_record(folder / "checkpoint.bin", "bodies.position", [](char* data) {
    const double far[2] = {1e9, 10.0};  // [m] body 0
    std::memcpy(data, far, sizeof far);
  });
  const std::string message = restart_error(edited_case(), folder);
  EXPECT_THAT(message, HasSubstr((folder / "checkpoint.bin").string()));
  EXPECT_THAT(message, HasSubstr("body 0 at (1000000000, 10) m lies far outside the domain"));
  EXPECT_THAT(message, Not(HasSubstr("edited.yaml")));

  patch_record(folder / "checkpoint.bin", "bodies.position", [](char* data) {
    const double nan[2] = {std::nan(""), 10.0};
    std::memcpy(data, nan, sizeof nan);
  });
  EXPECT_THAT(restart_error(edited_case(), folder), HasSubstr("body 0 has position (nan, 10) m"));
}

}  // namespace
}  // namespace flotsam
