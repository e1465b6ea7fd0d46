// Unit tests of read_msh: the four MSH flavours Gmsh writes (2.2 / 4.1, ASCII / binary) read
// back to the same mesh, hand-written files give exactly their nodes, elements and groups, and
// every rejected file gives a message naming it.
#include <gmock/gmock.h>
#include <gmsh.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "../support/scratch_path.hpp"
#include "../support/two_pier_channel.hpp"
#include "core/error.hpp"
#include "mesh/gmsh_session.hpp"
#include "mesh/mesh_generator.hpp"
#include "mesh/mesh_summary.hpp"
#include "mesh/msh_reader.hpp"

namespace flotsam {
namespace {

using ::testing::HasSubstr;

/// A fresh folder for this test's files, removed at the end.
class TempFolder {
 public:
  TempFolder() : path_(flotsam::test::fresh_test_folder("flotsam_msh_reader")) {}
  ~TempFolder() { std::filesystem::remove_all(path_); }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(file(name)) << text;
    return file(name);
  }

 private:
  std::filesystem::path path_;
};

std::string read_error(const std::string& path) {
  try {
    read_msh(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// A 2 m x 1 m rectangle cut into two triangles; "bottom" (y = 0) and "wall" (the other sides).
// MSH 2.2 element lines: tag, type, 2 tags (physical, elementary), nodes.
std::string rectangle_msh(const std::string& names, const std::string& triangles,
                          const std::string& bottom_physical = "1") {
  return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n" + names +
         "$EndPhysicalNames\n$Nodes\n4\n1 0 0 0\n2 2 0 0\n3 2 1 0\n4 0 1 0\n$EndNodes\n"
         "$Elements\n6\n1 1 2 " +
         bottom_physical +
         " 1 1 2\n2 1 2 2 2 2 3\n3 1 2 2 3 3 4\n"
         "4 1 2 2 4 4 1\n" +
         triangles + "$EndElements\n";
}
const std::string all_names = "3\n1 1 \"bottom\"\n1 2 \"wall\"\n2 3 \"water\"\n";
const std::string ccw_triangles = "5 2 2 3 1 1 2 3\n6 2 2 3 1 1 3 4\n";

TEST(MshReader, HandWrittenMsh22GivesItsNodesElementsAndGroups) {
  TempFolder folder;
  const Mesh mesh = read_msh(folder.write("rect.msh", rectangle_msh(all_names, ccw_triangles)));
  EXPECT_EQ(mesh.element_count(), 2);
  EXPECT_EQ(mesh.vertex_count, 4);
  EXPECT_EQ(mesh.node_count(), 4 + 5);  // vertices + edges
  EXPECT_THAT(mesh.element_tags, ::testing::UnorderedElementsAre(5, 6));
  EXPECT_EQ(mesh.group_names, (std::vector<std::string>{"bottom", "wall"}));
  const MeshSummary summary = summarize_mesh(mesh);
  EXPECT_DOUBLE_EQ(summary.total_area, 2.0);
  EXPECT_EQ(summary.groups[0].edge_count, 1);
  EXPECT_DOUBLE_EQ(summary.groups[0].length, 2.0);
  EXPECT_EQ(summary.groups[1].edge_count, 3);
  EXPECT_DOUBLE_EQ(summary.groups[1].length, 4.0);
  // Each vertex keeps its file tag (numbered along a curve: tags 1 4 3 2).
  const Vec2 file_position[] = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  for (int n = 0; n < 4; ++n) EXPECT_EQ(mesh.nodes[n], file_position[mesh.node_tags[n] - 1]);
  EXPECT_EQ(std::vector<long>(mesh.node_tags.begin(), mesh.node_tags.begin() + 4),
            (std::vector<long>{1, 4, 3, 2}));
}

TEST(MshReader, UnnamedPhysicalGroupIsNamedByItsNumber) {
  TempFolder folder;
  const std::string names = "2\n1 2 \"wall\"\n2 3 \"water\"\n";
  const Mesh mesh = read_msh(folder.write("rect.msh", rectangle_msh(names, ccw_triangles)));
  EXPECT_EQ(mesh.group_names, (std::vector<std::string>{"1", "wall"}));
}

TEST(MshReader, LineInNoPhysicalGroupHasAnEmptyGroupAndIsRejectedOnTheBoundary) {
  TempFolder folder;
  const auto path = folder.write("rect.msh", rectangle_msh(all_names, ccw_triangles, "0"));
  const RawMesh raw = read_msh_raw(path);
  int unnamed = 0;
  for (const auto& line : raw.lines) unnamed += line.group.empty() ? 1 : 0;
  EXPECT_EQ(unnamed, 1);
  EXPECT_THAT(read_error(path), HasSubstr(path + ": the boundary edge between nodes 1 and 2"));
  EXPECT_THAT(read_error(path), HasSubstr("belongs to no named physical group"));
}

TEST(MshReader, ClockwiseSurfaceIsReoriented) {
  TempFolder folder;
  const std::string clockwise = "5 2 2 3 1 1 3 2\n6 2 2 3 1 1 4 3\n";
  const Mesh mesh = read_msh(folder.write("rect.msh", rectangle_msh(all_names, clockwise)));
  ASSERT_EQ(mesh.element_count(), 2);
  EXPECT_DOUBLE_EQ(mesh.area[0] + mesh.area[1], 2.0);
  EXPECT_GT(mesh.area[0], 0.0);
  EXPECT_GT(mesh.area[1], 0.0);
}

TEST(MshReader, MissingFileIsAnErrorNamingIt) {
  TempFolder folder;
  const auto path = folder.file("no_such_mesh.msh");
  EXPECT_THAT(read_error(path), HasSubstr(path + ": cannot open the mesh file"));
}

TEST(MshReader, UnparseableFileIsAnErrorNamingIt) {
  TempFolder folder;
  const auto path = folder.write("garbage.msh", "this is not a mesh {\n");
  EXPECT_THAT(read_error(path),
              HasSubstr(path + ":1: expected $MeshFormat alone on the file's first line"));
}

TEST(MshReader, FileWithoutTrianglesIsAnErrorNamingIt) {
  TempFolder folder;
  const auto path = folder.write("lines.msh", rectangle_msh(all_names, ""));
  // The header says 6 elements; only the 4 lines follow.
  std::string text = rectangle_msh(all_names, "");
  text.replace(text.find("$Elements\n6"), 11, "$Elements\n4");
  folder.write("lines.msh", text);
  EXPECT_THAT(read_error(path), HasSubstr(path + ": the mesh has no triangles"));
}

TEST(MshReader, QuadrilateralsAreAnErrorNamingTheElementType) {
  TempFolder folder;
  std::string text = rectangle_msh(all_names, "5 3 2 3 1 1 2 3 4\n");
  text.replace(text.find("$Elements\n6"), 11, "$Elements\n5");
  const auto path = folder.write("quads.msh", text);
  EXPECT_THAT(read_error(path),
              HasSubstr(path + ": the mesh holds surface elements of Gmsh type 3"));
}

TEST(MshReader, ThreeNodeTrianglesGetMidNodesAtEdgeMidpoints) {
  // A square with a circular hole meshed at order 1 with Gmsh's own API: even the edges on the
  // circle get their mid node at the straight midpoint (the file knows nothing of the circle).
  TempFolder folder;
  const auto path = folder.file("linear.msh");
  {
    namespace geo = gmsh::model::geo;
    GmshSession session;
    gmsh::option::setNumber("Mesh.MeshSizeMax", 0.2);
    const int p1 = geo::addPoint(0, 0, 0), p2 = geo::addPoint(2, 0, 0);
    const int p3 = geo::addPoint(2, 2, 0), p4 = geo::addPoint(0, 2, 0);
    const int outer = geo::addCurveLoop(
        {geo::addLine(p1, p2), geo::addLine(p2, p3), geo::addLine(p3, p4), geo::addLine(p4, p1)});
    const int c = geo::addPoint(1, 1, 0);
    const int q1 = geo::addPoint(1.5, 1, 0), q2 = geo::addPoint(0.5, 1, 0);
    const int hole =
        geo::addCurveLoop({geo::addCircleArc(q1, c, q2), geo::addCircleArc(q2, c, q1)});
    const int surface = geo::addPlaneSurface({outer, hole});
    geo::synchronize();
    gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {1, 2, 3, 4}), "wall");
    gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {5, 6}), "hole");
    gmsh::model::addPhysicalGroup(2, {surface});
    gmsh::model::mesh::generate(2);
    gmsh::write(path);
  }
  const Mesh mesh = read_msh(path);
  ASSERT_GT(mesh.element_count(), 100);
  // P2 nodes = vertices + edges, edges = (3 T + boundary edges) / 2.
  const int boundary_edges = static_cast<int>(mesh.boundary.size());
  EXPECT_EQ(mesh.node_count(), mesh.vertex_count + (3 * mesh.element_count() + boundary_edges) / 2);
  for (int e = 0; e < mesh.element_count(); ++e) {
    EXPECT_FALSE(mesh.is_curved(e)) << "element " << mesh.element_tags[e];
    for (int k = 0; k < 3; ++k) {
      const auto n = mesh.edge_nodes(e, k);
      EXPECT_NEAR((mesh.nodes[n[2]] - 0.5 * (mesh.nodes[n[0]] + mesh.nodes[n[1]])).norm(), 0.0,
                  1e-15);
    }
  }
}

TEST(MshReader, AllFourMshFlavoursReadBackTheSameMesh) {
  // The same generated channel with two piers written as MSH 2.2 / 4.1, ASCII / binary.
  TempFolder folder;
  const MeshSource source = test::two_pier_channel(3);
  const Mesh reference = generate_mesh(source);
  for (const double version : {2.2, 4.1})
    for (const bool binary : {false, true}) {
      SCOPED_TRACE(fmt::format("MSH {} {}", version, binary ? "binary" : "ASCII"));
      const auto path = folder.file(fmt::format("channel_{}_{}.msh", version, binary));
      const Mesh written = generate_mesh(source, path, {.version = version, .binary = binary});
      const Mesh mesh = read_msh(path);
      ASSERT_EQ(mesh.node_count(), reference.node_count());
      ASSERT_EQ(written.node_count(), reference.node_count());
      EXPECT_EQ(mesh.vertex_count, reference.vertex_count);
      EXPECT_EQ(mesh.element_count(), reference.element_count());
      EXPECT_EQ(mesh.boundary.size(), reference.boundary.size());
      EXPECT_EQ(mesh.group_names, reference.group_names);
      EXPECT_EQ(mesh.elements, reference.elements);
      double largest_difference = 0;  // [m]; ASCII keeps 16 significant digits
      for (int n = 0; n < mesh.node_count(); ++n)
        largest_difference =
            std::max(largest_difference, (mesh.nodes[n] - reference.nodes[n]).norm());
      EXPECT_LE(largest_difference, 1e-13 * source.channel.length);
    }
}

}  // namespace
}  // namespace flotsam
