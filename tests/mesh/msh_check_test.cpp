// Unit tests of check_msh: the four MSH flavours Gmsh writes pass with their exact counts, a
// hand-written 4.1 file passes and reads, and each kind of damage is refused before Gmsh sees the
// file, naming the file, the line (or byte) and what was expected there. The damaged files that
// crashed Gmsh 4.8 itself (tests/fuzz/gmsh_crashes) are refused the same way.
#include "mesh/msh_check.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../support/scratch_path.hpp"
#include "core/error.hpp"
#include "mesh/mesh_generator.hpp"
#include "mesh/msh_reader.hpp"

namespace flotsam {
namespace {

using ::testing::HasSubstr;

class TempFolder {
 public:
  TempFolder() : path_(flotsam::test::fresh_test_folder("flotsam_msh_check")) {}
  ~TempFolder() { std::filesystem::remove_all(path_); }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(file(name), std::ios::binary) << text;
    return file(name);
  }

 private:
  std::filesystem::path path_;
};

// A unit square in two counter-clockwise triangles, its four sides in the curve "wall": MSH 4.1
// as Gmsh lays it out (entities, node blocks per entity, element blocks per type).
const std::string square_41 =
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
    "$PhysicalNames\n2\n1 1 \"wall\"\n2 2 \"water\"\n$EndPhysicalNames\n"
    "$Entities\n0 1 1 0\n"
    "1 0 0 0 1 1 0 1 1 0\n"    // curve 1, physical 1, no bounding points
    "1 0 0 0 1 1 0 1 2 1 1\n"  // surface 1, physical 2, bounded by curve 1
    "$EndEntities\n"
    "$Nodes\n2 4 1 4\n"
    "1 1 0 2\n1\n2\n0 0 0\n1 0 0\n"  // block 1: nodes 1, 2 on curve 1
    "2 1 0 2\n3\n4\n1 1 0\n0 1 0\n"  // block 2: nodes 3, 4 on surface 1
    "$EndNodes\n"
    "$Elements\n2 6 1 6\n"
    "1 1 1 4\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n"
    "2 1 2 2\n5 1 2 3\n6 1 3 4\n"
    "$EndElements\n";

// `text` with `from` (which must occur) replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// The 1-based line of `text` on which `part` starts.
int line_of(const std::string& text, const std::string& part) {
  const auto at = text.find(part);
  EXPECT_NE(at, std::string::npos) << part;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

std::string check_error(const std::string& path) {
  try {
    check_msh(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// A mesh file that is a named pipe (`flotsam info pipe.msh`) is refused, not waited on.
TEST(MshCheck, ANamedPipeIsRefused) {
  const auto folder = test::fresh_test_folder("flotsam_msh_fifo_test");
  const std::string pipe = (folder / "river.msh").string();
  ASSERT_EQ(mkfifo(pipe.c_str(), 0600), 0);
  try {
    check_msh(pipe);
    FAIL() << "a named pipe was read as a mesh";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              pipe + ": the mesh file is a named pipe, not a file: flotsam reads it whole");
  }
  std::filesystem::remove_all(folder);
}

TEST(MshCheck, HandWrittenMsh41PassesWithItsCountsAndReads) {
  TempFolder folder;
  const auto path = folder.write("square.msh", square_41);
  const MshCounts counts = check_msh(path);
  EXPECT_EQ(counts.format, "4.1 ASCII");
  EXPECT_EQ(counts.nodes, 4u);
  EXPECT_EQ(counts.triangles, 2u);
  EXPECT_EQ(counts.lines, 4u);
  EXPECT_EQ(counts.elements, 6u);
  const Mesh mesh = read_msh(path);
  EXPECT_EQ(mesh.element_count(), 2);
  EXPECT_EQ(mesh.vertex_count, 4);
}

TEST(MshCheck, AllFourFlavoursGmshWritesPassWithTheirCounts) {
  TempFolder folder;
  MeshSource source;
  source.kind = MeshSource::Kind::channel;
  source.channel = {.length = 120,
                    .width = 40,
                    .piers = {{{60, 20}, 6}},
                    .mesh_size = 8,
                    .pier_mesh_size = 4,
                    .refine_distance = 20};
  for (const double version : {2.2, 4.1})
    for (const bool binary : {false, true}) {
      const std::string flavour = fmt::format("{:.1f} {}", version, binary ? "binary" : "ASCII");
      SCOPED_TRACE(flavour);
      const auto path = folder.file(fmt::format("channel_{}_{}.msh", version, binary));
      generate_mesh(source, path, {.version = version, .binary = binary});
      const MshCounts counts = check_msh(path);
      const RawMesh raw = read_msh_raw(path);
      EXPECT_EQ(counts.format, flavour);
      EXPECT_EQ(counts.triangles, raw.triangles.size());
      EXPECT_EQ(counts.lines, raw.lines.size());  // every line of the file lies on the triangles
      EXPECT_GE(counts.nodes, raw.nodes.size());  // the file may hold unused nodes
    }
}

struct Damage {
  std::string name;  // what is wrong
  std::string from, to;
  std::string line_part;  // the text on the line the message must name
  std::string message;
};

TEST(MshCheck, EachDamageIsRefusedNamingTheFileTheLineAndWhatWasExpected) {
  TempFolder folder;
  const std::vector<Damage> damages = {
      {"a node block longer than the header's count (Gmsh 4.8 writes past its array)",
       "$Nodes\n2 4 1 4", "$Nodes\n2 3 1 3", "2 1 0 2",
       "$Nodes: block 2 holds 2 nodes, more than the 1 the header declares are left"},
      {"a node block header missing its count, read as the next tag (tests/fuzz/gmsh_crashes)",
       "2 1 0 2\n3\n4\n", "2 1 0\n3\n4\n", "3\n4\n1 1 0",
       "$Nodes: block 2 holds 3 nodes, more than the 2 the header declares are left"},
      {"an element naming a node the file does not define", "6 1 3 4", "6 1 3 9", "6 1 3 9",
       "$Elements: element 6 refers to node 9, which $Nodes does not define"},
      {"an element split over two lines", "5 1 2 3", "5 1 2\n3", "5 1 2",
       "expected node 3 of element 5 on the same line"},
      {"a number that does not parse", "1 1 0\n0 1 0", "1 1 0\n0 1e9x 0", "0 1e9x 0",
       "$Nodes: expected a node coordinate (a finite number), got '1e9x'"},
      {"a coordinate that is not finite", "0 0 0\n1 0 0", "0 nan 0\n1 0 0", "0 nan 0", "got 'nan'"},
      {"a version flotsam does not read", "4.1 0 8", "4 0 8", "4 0 8",
       "flotsam reads MSH 2.2 and 4.1 files, not version 4"},
      {"a section flotsam does not read", "$EndElements\n", "$EndElements\n$Periodic\n0\n",
       "$Periodic", "section $Periodic is not one flotsam reads"},
      {"a section without its end", "$EndNodes\n", "", "$Elements",
       "$Nodes: expected $EndNodes (the declared counts are met), got '$Elements'"},
      {"a node block of an entity $Entities does not define", "2 1 0 2", "2 5 0 2", "2 5 0 2",
       "block 2 belongs to entity 5 of dimension 2, which $Entities does not define"},
      {"triangles in a curve's block", "1 1 1 4\n", "1 1 2 4\n", "1 1 2 4",
       "block 1 holds elements of type 2 (dimension 2) in an entity of dimension 1"},
      {"a physical name of dimension 7", "1 1 \"wall\"", "7 1 \"wall\"", "7 1 \"wall\"",
       "expected a physical group's dimension (an integer from 0 to 3), got '7'"},
      {"a node tag defined twice", "1\n2\n0 0 0", "1\n3\n0 0 0", "0 1 0\n$EndNodes",
       "node tag 3 is defined twice"},
      {"a curve bounded by a point $Entities lacks", "1 0 0 0 1 1 0 1 1 0\n",
       "1 0 0 0 1 1 0 1 1 1 4\n", "1 0 0 0 1 1 0 1 1 1 4",
       "entity 1 of dimension 1 is bounded by entity 4 of dimension 0"},
      {"an element type Gmsh does not know", "2 1 2 2\n", "2 1 99 2\n", "2 1 99 2",
       "element type 99 is not one flotsam reads"},
      {"3- and 6-node triangles in one surface (Gmsh 4.8 corrupts its memory)",
       "$Elements\n2 6 1 6\n1 1 1 4\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n2 1 2 2\n5 1 2 3\n6 1 3 4\n",
       "$Elements\n3 6 1 6\n1 1 1 4\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n2 1 2 1\n5 1 2 3\n"
       "2 1 9 1\n6 1 3 4 2 3 4\n",
       "2 1 9 1",
       "block 3 is of type 9, but entity 1 of dimension 2 already holds elements of type 2"},
  };
  for (const Damage& d : damages) {
    SCOPED_TRACE(d.name);
    const std::string text = replaced(square_41, d.from, d.to);
    const auto path = folder.write("damaged.msh", text);
    const std::string where = fmt::format("{}:{}: ", path, line_of(text, d.line_part));
    EXPECT_THAT(check_error(path), HasSubstr(where));
    EXPECT_THAT(check_error(path), HasSubstr(d.message));
    try {  // read_msh refuses it with the same message, before Gmsh
      read_msh(path);
      ADD_FAILURE() << "read";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), check_error(path));
    }
  }
}

TEST(MshCheck, TruncatedBinaryFileIsRefusedNamingTheByte) {
  TempFolder folder;
  MeshSource source;
  source.kind = MeshSource::Kind::channel;
  source.channel = {.length = 60,
                    .width = 20,
                    .piers = {},
                    .mesh_size = 5,
                    .pier_mesh_size = 5,
                    .refine_distance = 10};
  const auto whole = folder.file("whole.msh");
  generate_mesh(source, whole, {.version = 4.1, .binary = true});
  std::stringstream bytes;
  bytes << std::ifstream(whole, std::ios::binary).rdbuf();
  const std::string text = bytes.str();
  // Cut inside the elements' header (4 counts of 8 bytes after "$Elements\n"): the first count
  // is whole, the second is not.
  const std::size_t cut = text.find("$Elements") + 20;
  const auto path = folder.write("cut.msh", text.substr(0, cut));
  EXPECT_THAT(check_error(path),
              HasSubstr(fmt::format("{}: byte {}: $Elements: expected", path, cut - 2)));
  EXPECT_THAT(check_error(path), HasSubstr("got the end of the file"));
}

TEST(MshCheck, FileWhoseNameDoesNotEndInMshIsRefused) {
  TempFolder folder;
  const auto path = folder.write("square.geo", square_41);  // Gmsh would run it as a script
  EXPECT_THAT(check_error(path),
              HasSubstr(path + ": a Gmsh mesh file's name must end in .msh or .msh2"));
}

// Every file that crashed Gmsh 4.8's own parser is refused with a message naming it and a line.
TEST(MshCheck, FilesThatCrashedGmshAreRefusedBeforeGmshSeesThem) {
  int files = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(FLOTSAM_SOURCE_DIR "/tests/fuzz/gmsh_crashes")) {
    const std::string path = entry.path().string();
    SCOPED_TRACE(path);
    EXPECT_THAT(check_error(path), HasSubstr(path + ":"));
    EXPECT_THROW(read_msh(path), InputError);
    ++files;
  }
  EXPECT_GE(files, 1);
}

}  // namespace
}  // namespace flotsam
