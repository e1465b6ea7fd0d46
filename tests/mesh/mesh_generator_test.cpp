// Unit tests of generate_mesh: the paper's channel has the paper's element count, curved
// boundaries carry their mid nodes on the true circles, lengths and areas match the geometry
// analytically, generation is deterministic, and bad geometries are errors naming the culprit.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <thread>

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
constexpr double pi = std::numbers::pi;

/// Spec 8.2: 1500 m x 170 m, bridges at x = 600 and 900 m, piers of radius 30 m at y = 42.5
/// and 127.5 m; default mesh sizes.
MeshSource paper_channel() {
  MeshSource source;
  source.kind = MeshSource::Kind::channel;
  for (double x : {600.0, 900.0})
    for (double y : {42.5, 127.5}) source.channel.piers.push_back({{x, y}, 30.0});
  return source;
}

/// The paper's channel meshed once for all the tests that only look at it.
const Mesh& paper_mesh() {
  static const Mesh mesh = generate_mesh(paper_channel());
  return mesh;
}

const BoundaryGroupSummary& group(const MeshSummary& summary, const std::string& name) {
  for (const auto& g : summary.groups)
    if (g.name == name) return g;
  throw std::runtime_error("no group " + name);
}

std::string error_of(const MeshSource& source, const std::string& msh_path = "") {
  try {
    generate_mesh(source, msh_path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

/// Largest |distance from centre - radius| / radius over the vertices and mid nodes of a group.
double largest_radial_error(const Mesh& mesh, const std::string& name, const Vec2& centre,
                            double radius) {
  const int g = mesh.find_group(name);
  EXPECT_GE(g, 0) << name;
  double largest = 0;
  for (const auto& edge : mesh.boundary) {
    if (edge.group != g) continue;
    for (int node : mesh.edge_nodes(edge.element, edge.local_edge))
      largest = std::max(largest, std::abs((mesh.nodes[node] - centre).norm() - radius) / radius);
  }
  return largest;
}

TEST(MeshGenerator, PaperChannelHasAboutThePapersElementCount) {
  // Paper: 4,468 six-node elements and 9,357 nodes; the default sizes should give it +-10%.
  const Mesh& mesh = paper_mesh();
  EXPECT_NEAR(mesh.element_count(), 4468, 0.10 * 4468);
  EXPECT_NEAR(mesh.node_count(), 9357, 0.10 * 9357);
  EXPECT_EQ(mesh.group_names,
            (std::vector<std::string>{"bank_left", "bank_right", "inflow", "outflow", "pier_1",
                                      "pier_2", "pier_3", "pier_4"}));
  // Euler for a domain with 4 holes: V - E + T = 1 - 4, and P2 nodes = V + E.
  const int E = mesh.node_count() - mesh.vertex_count;
  EXPECT_EQ(mesh.vertex_count - E + mesh.element_count(), -3);
}

TEST(MeshGenerator, PierMidNodesLieOnTheCircles) {
  const MeshSource source = paper_channel();
  const Mesh& mesh = paper_mesh();
  for (int i = 0; i < 4; ++i) {
    const Pier& pier = source.channel.piers[i];
    EXPECT_LE(largest_radial_error(mesh, fmt::format("pier_{}", i + 1), pier.centre, pier.radius),
              1e-9);
  }
}

TEST(MeshGenerator, ThreeNodeMeshHasTheSameVerticesAndTrianglesWithStraightMidNodes) {
  // element_order 1 (engine: fv): Gmsh's triangles without its raising to order 2; the same
  // vertices and triangles in the same numbering, no curved element, every mid node halfway.
  MeshSource source = test::two_pier_channel();
  const Mesh six = generate_mesh(source);
  source.element_order = 1;
  const Mesh three = generate_mesh(source);
  ASSERT_EQ(three.vertex_count, six.vertex_count);
  ASSERT_EQ(three.element_count(), six.element_count());
  for (int n = 0; n < six.vertex_count; ++n) EXPECT_EQ(three.nodes[n], six.nodes[n]) << n;
  int curved_six = 0;
  double largest_offset = 0.0;  // [m] of a mid node from its edge's midpoint
  for (int e = 0; e < three.element_count(); ++e) {
    const auto& el = three.elements[e];
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(el[k], six.elements[e][k]);
      const Vec2 halfway = 0.5 * (three.nodes[el[k]] + three.nodes[el[(k + 1) % 3]]);
      largest_offset = std::max(largest_offset, (three.nodes[el[3 + k]] - halfway).norm());
    }
    EXPECT_FALSE(three.is_curved(e));
    curved_six += six.is_curved(e);
  }
  EXPECT_GT(curved_six, 0);  // the six-node mesh follows the piers' circles
  EXPECT_LE(largest_offset, 1e-12);
  EXPECT_EQ(three.group_names, six.group_names);
}

TEST(MeshGenerator, ChannelLengthsAndAreaMatchTheGeometry) {
  const MeshSource source = paper_channel();
  const MeshSummary summary = summarize_mesh(paper_mesh());
  const double L = 1500, W = 170, r = 30;  // [m]
  EXPECT_NEAR(group(summary, "inflow").length, W, 1e-9 * W);
  EXPECT_NEAR(group(summary, "outflow").length, W, 1e-9 * W);
  EXPECT_NEAR(group(summary, "bank_left").length, L, 1e-9 * L);
  EXPECT_NEAR(group(summary, "bank_right").length, L, 1e-9 * L);
  for (int i = 1; i <= 4; ++i)  // P2 edges through 3 points of the circle
    EXPECT_NEAR(group(summary, fmt::format("pier_{}", i)).length, 2 * pi * r, 1e-4 * 2 * pi * r);
  const double area = L * W - 4 * pi * r * r;  // [m^2]
  EXPECT_NEAR(summary.total_area, area, 1e-3 * area);
  // The pier refinement: elements on the circles about pier_mesh_size, far ones mesh_size.
  EXPECT_LT(summary.min_element_size, source.channel.mesh_size);
  EXPECT_GT(summary.min_quality, 0.5);
}

TEST(MeshGenerator, GenerationIsDeterministic) {
  const Mesh first = generate_mesh(test::two_pier_channel());
  const Mesh second = generate_mesh(test::two_pier_channel());
  ASSERT_EQ(first.node_count(), second.node_count());
  EXPECT_EQ(first.nodes, second.nodes);
  EXPECT_EQ(first.elements, second.elements);
}

TEST(MeshGenerator, ConcurrentGenerationsAreSerializedAndAgree) {
  // Gmsh is one global state: the session mutex makes two threads take turns.
  Mesh first, second;
  std::thread other([&] { first = generate_mesh(test::two_pier_channel()); });
  second = generate_mesh(test::two_pier_channel());
  other.join();
  EXPECT_EQ(first.nodes, second.nodes);
  EXPECT_EQ(first.elements, second.elements);
}

TEST(MeshGenerator, BendLengthsAndAreaAreAnalytic) {
  // Spec 8.1: B = 0.8 m, R_i = 0.4 m (centre line R_c = 0.8 m), reaches of 3 m.
  MeshSource source;
  source.kind = MeshSource::Kind::bend;
  source.bend.mesh_size = 0.08;
  source.bend.centre = {1.0, 2.0};
  const BendGeometry& b = source.bend;
  const Mesh mesh = generate_mesh(source);
  const MeshSummary summary = summarize_mesh(mesh);
  EXPECT_EQ(mesh.group_names,
            (std::vector<std::string>{"bank_inner", "bank_outer", "inflow", "outflow"}));
  const double R_i = b.inner_radius, R_o = b.inner_radius + b.width;                 // [m]
  const double R_c = 0.5 * (R_i + R_o), reaches = b.inlet_length + b.outlet_length;  // [m]
  const double outer = reaches + pi * R_o, inner = reaches + pi * R_i;               // [m]
  EXPECT_NEAR(group(summary, "bank_outer").length, outer, 1e-6 * outer);
  EXPECT_NEAR(group(summary, "bank_inner").length, inner, 1e-6 * inner);
  EXPECT_NEAR(group(summary, "inflow").length, b.width, 1e-12);
  EXPECT_NEAR(group(summary, "outflow").length, b.width, 1e-12);
  // Pappus: area = width x centre-line length.
  const double centre_line = reaches + pi * R_c;  // [m]
  EXPECT_NEAR(summary.total_area / b.width, centre_line, 1e-6 * centre_line);
  // Arc mid nodes on the circles (the straight reaches lie off them: check the arc part only).
  for (const auto& edge : mesh.boundary) {
    const auto n = mesh.edge_nodes(edge.element, edge.local_edge);
    const Vec2 mid = mesh.nodes[n[2]] - b.centre;
    if (mid.x() >= 0) continue;
    const double R = mesh.group_names[edge.group] == "bank_outer" ? R_o : R_i;  // [m]
    EXPECT_NEAR(mid.norm(), R, 1e-9 * R);
  }
  // Inflow at x = centre + inlet length, upper reach; outflow in the lower reach.
  EXPECT_NEAR(summary.upper_corner.x(), b.centre.x() + b.inlet_length, 1e-12);
  EXPECT_NEAR(summary.lower_corner.x(), b.centre.x() - R_o, 1e-12);
  EXPECT_NEAR(summary.upper_corner.y() - summary.lower_corner.y(), 2 * R_o, 1e-12);
}

TEST(MeshGenerator, PolygonKeepsItsSidesGroupsAndArea) {
  // An L shape given clockwise; two sides share the group "wall".
  MeshSource source;
  source.kind = MeshSource::Kind::polygon;
  source.polygon = {.points = {{0, 0}, {0, 2}, {1, 2}, {1, 1}, {3, 1}, {3, 0}},
                    .groups = {"in", "wall", "wall", "wall", "out", "floor"},
                    .mesh_size = 0.25};
  const Mesh mesh = generate_mesh(source);
  const MeshSummary summary = summarize_mesh(mesh);
  EXPECT_EQ(mesh.group_names, (std::vector<std::string>{"floor", "in", "out", "wall"}));
  EXPECT_NEAR(summary.total_area, 4.0, 1e-12);
  EXPECT_NEAR(group(summary, "in").length, 2.0, 1e-12);
  EXPECT_NEAR(group(summary, "wall").length, 4.0, 1e-12);
  EXPECT_NEAR(group(summary, "out").length, 1.0, 1e-12);
  EXPECT_NEAR(group(summary, "floor").length, 3.0, 1e-12);
  EXPECT_EQ(summary.curved_element_count, 0);
  EXPECT_LE(summary.max_element_size, 1.5 * source.polygon.mesh_size);
}

TEST(MeshGenerator, FileSourceReadsTheWrittenMesh) {
  const auto path = test::scratch_path("flotsam_generator.msh").string();
  const Mesh generated = generate_mesh(test::two_pier_channel(), path);
  MeshSource file;
  file.kind = MeshSource::Kind::file;
  file.file = path;
  const Mesh read = generate_mesh(file);
  // A file source with an output path is copied in the format asked for.
  const std::string copy = path + ".v22.msh";
  generate_mesh(file, copy, {.version = 2.2, .binary = true});
  const Mesh copied = read_msh(copy);
  std::filesystem::remove(path);
  std::filesystem::remove(copy);
  EXPECT_EQ(read.source, path);
  EXPECT_EQ(read.elements, generated.elements);
  EXPECT_EQ(read.node_count(), generated.node_count());
  EXPECT_EQ(copied.elements, generated.elements);
  EXPECT_EQ(copied.nodes, read.nodes);
}

TEST(MeshGenerator, OverlappingPiersAreAnErrorNamingThem) {
  MeshSource source = test::two_pier_channel();
  source.channel.piers = {{{60, 30}, 10}, {{100, 30}, 10}, {{115, 30}, 6}};
  EXPECT_THAT(error_of(source), HasSubstr("pier_2 and pier_3 overlap"));
}

TEST(MeshGenerator, PierReachingABankIsAnErrorNamingIt) {
  MeshSource source = test::two_pier_channel();
  source.channel.piers = {{{60, 30}, 10}, {{140, 55}, 8}};
  EXPECT_THAT(error_of(source), HasSubstr("pier_2 (centre (140, 55) m, radius 8 m) reaches the "
                                          "left bank (y = 60 m)"));
  source.channel.piers = {{{5, 30}, 10}};
  EXPECT_THAT(error_of(source), HasSubstr("pier_1 (centre (5, 30) m, radius 10 m) reaches the "
                                          "inflow (x = 0)"));
}

TEST(MeshGenerator, BadPolygonsAreErrorsNamingTheSides) {
  MeshSource source;
  source.kind = MeshSource::Kind::polygon;
  source.polygon = {.points = {{0, 0}, {1, 1}, {1, 0}, {0, 1}},  // a bow tie
                    .groups = {"a", "b", "c", "d"}};
  EXPECT_THAT(error_of(source), HasSubstr("side 1 (points 1 to 2) meets side 3 (points 3 to 4)"));
  source.polygon = {.points = {{0, 0}, {1, 0}}, .groups = {"a", "b"}};
  EXPECT_THAT(error_of(source), HasSubstr("a polygon needs at least 3 points; got 2"));
  source.polygon = {.points = {{0, 0}, {1, 0}, {0, 1}}, .groups = {"a", "b"}};
  EXPECT_THAT(error_of(source), HasSubstr("3 points make 3 sides, but 2 group names are given"));
}

TEST(MeshGenerator, UnwritableMshPathIsAnErrorNamingIt) {
  const std::string path = "/nonexistent_folder_flotsam/mesh.msh";
  EXPECT_THAT(error_of(test::two_pier_channel(), path), HasSubstr(path));
}

}  // namespace
}  // namespace flotsam

namespace flotsam {
namespace {

// Gmsh sets the process's OpenMP thread count (General.NumThreads = 1); the session restores it,
// so that the flow assembly after meshing still runs on every core.
TEST(GmshSession, RestoresTheOpenMpThreadCount) {
  omp_set_num_threads(2);
  { GmshSession session; }
  EXPECT_EQ(omp_get_max_threads(), 2);
}

}  // namespace
}  // namespace flotsam
