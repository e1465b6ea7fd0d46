// Verifies that the VTK XML writers (.vtu, .vtp, .pvd) write what their headers declare: every
// appended block's UInt64 size equals the bytes its DataArray tag announces, blocks follow each
// other with no gap up to </AppendedData>, and the arrays read back hold the mesh, the fields
// and the bodies exactly (binary doubles: bit for bit). VTK's own reader checks the same files
// in tests/scripts/check_vtk.py.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "../support/file_size_limit.hpp"
#include "../support/scratch_path.hpp"
#include "core/error.hpp"
#include "io/vtk_writer.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

namespace fs = std::filesystem;

fs::path scratch_folder() {
  return test::fresh_test_folder("flotsam_vtk");
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A minimal reader of flotsam's appended raw VTK XML files, independent of the writer.
struct VtkFile {
  struct Array {
    std::map<std::string, std::string> attributes;
    std::size_t offset = 0;  // of the block's size header, from the byte after '_'
    std::string bytes;       // the block's data, without its size header
  };
  std::string xml;  // everything before the '_' that opens the appended block
  std::vector<Array> arrays;

  explicit VtkFile(const fs::path& path) {
    const std::string text = read_text(path);
    const std::string open = "<AppendedData encoding=\"raw\">\n_";
    const auto start = text.find(open);
    EXPECT_NE(start, std::string::npos);
    xml = text.substr(0, start);
    const std::string blob = text.substr(start + open.size());
    const std::string close = "\n</AppendedData>\n</VTKFile>\n";
    EXPECT_TRUE(blob.ends_with(close));
    const std::size_t blob_size = blob.size() - close.size();

    const std::regex tag("<DataArray ([^>]*)/>"), attribute("(\\w+)=\"([^\"]*)\"");
    for (auto t = std::sregex_iterator(xml.begin(), xml.end(), tag); t != std::sregex_iterator();
         ++t) {
      Array array;
      const std::string inner = (*t)[1];
      for (auto a = std::sregex_iterator(inner.begin(), inner.end(), attribute);
           a != std::sregex_iterator(); ++a)
        array.attributes[(*a)[1]] = (*a)[2];
      array.offset = std::stoull(array.attributes.at("offset"));
      std::uint64_t size = 0;
      std::memcpy(&size, blob.data() + array.offset, sizeof size);
      array.bytes = blob.substr(array.offset + sizeof size, size);
      arrays.push_back(array);
    }
    // In offset order, the blocks follow each other with no gap up to </AppendedData>.
    std::vector<const Array*> by_offset;
    for (const Array& a : arrays) by_offset.push_back(&a);
    std::sort(by_offset.begin(), by_offset.end(),
              [](const Array* a, const Array* b) { return a->offset < b->offset; });
    std::size_t expected_offset = 0;
    for (const Array* a : by_offset) {
      EXPECT_EQ(a->offset, expected_offset) << a->attributes.at("Name");
      expected_offset = a->offset + sizeof(std::uint64_t) + a->bytes.size();
    }
    EXPECT_EQ(expected_offset, blob_size) << "the last block must end at </AppendedData>";
  }

  const Array& array(const std::string& name) const {
    for (const Array& a : arrays)
      if (a.attributes.count("Name") && a.attributes.at("Name") == name) return a;
    throw std::runtime_error("no array " + name);
  }

  template <class T>
  std::vector<T> values(const std::string& name) const {
    const Array& a = array(name);
    std::vector<T> out(a.bytes.size() / sizeof(T));
    std::memcpy(out.data(), a.bytes.data(), out.size() * sizeof(T));
    return out;
  }

  /// The size in bytes the tag declares: tuples x components x size of the type.
  static std::size_t declared_bytes(const Array& a) {
    static const std::map<std::string, std::size_t> type_size = {
        {"Float64", 8}, {"Int64", 8}, {"Int32", 4}, {"UInt8", 1}};
    const std::size_t components = a.attributes.count("NumberOfComponents")
                                       ? std::stoul(a.attributes.at("NumberOfComponents"))
                                       : 1;
    return std::stoull(a.attributes.at("NumberOfTuples")) * components *
           type_size.at(a.attributes.at("type"));
  }
};

// A 2 x 1 rectangle: 6 vertices, 4 triangles, 9 edges, so 15 P2 nodes; 6 boundary edges.
Mesh small_mesh() {
  RectangleSpec spec;
  spec.x0 = 1.0;
  spec.y0 = -2.0;
  spec.length = 4.0;
  spec.width = 3.0;
  spec.nx = 2;
  spec.ny = 1;
  return make_rectangle_mesh(spec);
}

TEST(VtuWriter, DeclaredSizesMatchTheAppendedBlocks) {
  const Mesh mesh = small_mesh();
  ASSERT_EQ(mesh.node_count(), 15);
  std::vector<double> f(15, 1.0), g(6, 2.0), c(4, 3.0);
  std::vector<Vec2> u(15, Vec2(1.0, 2.0));
  VtuFields fields;
  fields.add_point_scalar("f [m]", f);
  fields.add_point_vector("u [m/s]", u);
  fields.add_p1_scalar("g", g);
  fields.add_cell_scalar("c", c);
  const fs::path path = scratch_folder() / "a.vtu";
  write_vtu(path.string(), mesh, fields, 12.5);

  const VtkFile file(path);
  EXPECT_NE(file.xml.find("<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
                          "byte_order=\"LittleEndian\" header_type=\"UInt64\">"),
            std::string::npos);
  EXPECT_NE(file.xml.find("<Piece NumberOfPoints=\"15\" NumberOfCells=\"4\">"), std::string::npos);
  ASSERT_EQ(file.arrays.size(), 9u);  // TimeValue, 4 fields, points, 3 cell arrays
  for (const auto& a : file.arrays)
    EXPECT_EQ(a.bytes.size(), VtkFile::declared_bytes(a)) << a.attributes.at("Name");
  EXPECT_EQ(file.array("Points").bytes.size(), 15u * 3 * 8);
  EXPECT_EQ(file.array("u [m/s]").bytes.size(), 15u * 3 * 8);
  EXPECT_EQ(file.array("g").bytes.size(), 15u * 8);  // P1 written on all P2 nodes
  EXPECT_EQ(file.array("c").bytes.size(), 4u * 8);
  EXPECT_EQ(file.values<double>("TimeValue"), std::vector<double>{12.5});
  EXPECT_FALSE(fs::exists(path.string() + ".part"));
}

// A write that fails (a full disk, imitated by a file size limit) stops with the file named and
// leaves neither the file nor its .part behind (issue 20 item 5).
TEST(VtuWriter, AFailedWriteLeavesNoPartFile) {
  const Mesh mesh = small_mesh();
  std::vector<double> f(15, 1.0);
  VtuFields fields;
  fields.add_point_scalar("f [m]", f);
  const fs::path path = scratch_folder() / "full.vtu";
  try {
    const test::FileSizeLimit full_disk(512);  // [bytes] the file takes about 3 kB
    write_vtu(path.string(), mesh, fields, 0.0);
    ADD_FAILURE() << "the write past the limit succeeded";
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), ::testing::StartsWith("cannot write '" + path.string()));
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path.string() + ".part"));
}

TEST(VtuWriter, MeshAndFieldsReadBackExactly) {
  const Mesh mesh = small_mesh();
  std::vector<double> f(15), g(6), c(4);
  std::vector<Vec2> u(15);
  for (int n = 0; n < 15; ++n) {
    const Vec2& x = mesh.nodes[n];
    f[n] = x.x() + 2 * x.y();
    u[n] = Vec2(x.y(), -x.x());
  }
  for (int v = 0; v < 6; ++v) g[v] = 3 * mesh.nodes[v].x() - mesh.nodes[v].y();
  for (int e = 0; e < 4; ++e) c[e] = 0.5 + e;
  VtuFields fields;
  fields.add_point_scalar("f", f);
  fields.add_point_vector("u", u);
  fields.add_p1_scalar("g", g);
  fields.add_cell_scalar("c", c);
  const fs::path path = scratch_folder() / "b.vtu";
  write_vtu(path.string(), mesh, fields, 0.0);
  const VtkFile file(path);

  const auto points = file.values<double>("Points");
  const auto f_read = file.values<double>("f");
  const auto u_read = file.values<double>("u");
  const auto g_read = file.values<double>("g");
  for (int n = 0; n < 15; ++n) {
    const double x = mesh.nodes[n].x(), y = mesh.nodes[n].y();
    EXPECT_EQ(points[3 * n], x);
    EXPECT_EQ(points[3 * n + 1], y);
    EXPECT_EQ(points[3 * n + 2], 0.0);
    EXPECT_EQ(f_read[n], f[n]);
    EXPECT_EQ(u_read[3 * n], y);
    EXPECT_EQ(u_read[3 * n + 1], -x);
    EXPECT_EQ(u_read[3 * n + 2], 0.0);
    // g is linear, so linear interpolation at mid nodes is exact up to rounding.
    EXPECT_NEAR(g_read[n], 3 * x - y, 1e-12) << "node " << n;
  }
  EXPECT_EQ(file.values<double>("c"), c);
  const auto connectivity = file.values<std::int64_t>("connectivity");
  const auto offsets = file.values<std::int64_t>("offsets");
  const auto types = file.values<std::uint8_t>("types");
  ASSERT_EQ(connectivity.size(), 24u);
  for (int e = 0; e < 4; ++e) {
    for (int k = 0; k < 6; ++k) EXPECT_EQ(connectivity[6 * e + k], mesh.elements[e][k]);
    EXPECT_EQ(offsets[e], 6 * (e + 1));
    EXPECT_EQ(types[e], 22);  // VTK_QUADRATIC_TRIANGLE
  }
}

TEST(VtuWriter, FieldOfTheWrongLengthIsNamed) {
  const Mesh mesh = small_mesh();
  std::vector<double> wrong(14);
  VtuFields fields;
  fields.add_point_scalar("depth [m]", wrong);
  try {
    write_vtu((scratch_folder() / "c.vtu").string(), mesh, fields, 0.0);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "write_vtu: field 'depth [m]' has 14 values; expected 15 (one per P2 node)");
  }
  VtuFields p1;
  p1.add_p1_scalar("eta", wrong);
  EXPECT_THROW(write_vtu((scratch_folder() / "d.vtu").string(), mesh, p1, 0.0),
               std::invalid_argument);
}

TEST(VtuWriter, FieldNamesAreEscaped) {
  const Mesh mesh = small_mesh();
  std::vector<double> c(4, 1.0);
  VtuFields fields;
  fields.add_cell_scalar("a<b & \"c\"", c);
  const fs::path path = scratch_folder() / "e.vtu";
  write_vtu(path.string(), mesh, fields, 0.0);
  EXPECT_NE(read_text(path).find("Name=\"a&lt;b &amp; &quot;c&quot;\""), std::string::npos);
}

TEST(VtuWriter, UnwritablePathIsAnInputErrorNamingIt) {
  const Mesh mesh = small_mesh();
  const std::string path = (scratch_folder() / "missing" / "f.vtu").string();
  try {
    write_vtu(path, mesh, VtuFields{}, 0.0);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("cannot write '" + path + "': ", 0), 0u) << e.what();
  }
}

// Three bodies and a gone one, laid out by hand (BodySet::add lives in flotsam_bodies).
BodySet three_bodies() {
  BodySet bodies;
  auto push = [&](long id, Vec2 position, double angle, double length, double width,
                  BodyState state) {
    bodies.id.push_back(id);
    bodies.position.push_back(position);
    bodies.angle.push_back(angle);
    bodies.length.push_back(length);
    bodies.width.push_back(width);
    bodies.velocity.push_back(Vec2(id, -id));
    bodies.angular_velocity.push_back(0.25 * id);
    bodies.state.push_back(state);
  };
  push(7, {10.0, 5.0}, 0.0, 20.0, 1.0, BodyState::floating);
  push(13, {0.0, 0.0}, 1.0, 5.0, 1.0, BodyState::gone);
  push(11, {-3.0, 2.0}, std::numbers::pi / 2, 4.0, 2.0, BodyState::grounded);
  push(42, {0.0, 0.0}, std::numbers::pi / 6, 2.0, 1.0, BodyState::floating);
  return bodies;
}

TEST(BodiesVtp, PolygonsSkipGoneBodiesAndCarryTheirData) {
  const BodySet bodies = three_bodies();
  const std::vector<double> force = {1.0, 2.0, 3.0, 4.0};
  const std::vector<Vec2> push = {{1, 1}, {2, 2}, {3, 3}, {4, 4}};
  BodyFields extra;
  extra.add_scalar("drag [N]", force);
  extra.add_vector("contact force [N]", push);
  const fs::path path = scratch_folder() / "bodies.vtp";
  write_bodies_vtp(path.string(), bodies, extra, 3.0);
  const VtkFile file(path);

  EXPECT_NE(file.xml.find("NumberOfPoints=\"12\""), std::string::npos);
  EXPECT_NE(file.xml.find("NumberOfPolys=\"3\""), std::string::npos);
  for (const auto& a : file.arrays)
    EXPECT_EQ(a.bytes.size(), VtkFile::declared_bytes(a)) << a.attributes.at("Name");
  EXPECT_EQ(file.values<std::int64_t>("id"), (std::vector<std::int64_t>{7, 11, 42}));
  EXPECT_EQ(file.values<std::uint8_t>("state"), (std::vector<std::uint8_t>{0, 1, 0}));
  EXPECT_EQ(file.values<double>("drag [N]"), (std::vector<double>{1.0, 3.0, 4.0}));
  EXPECT_EQ(file.values<double>("contact force [N]"),
            (std::vector<double>{1, 1, 0, 3, 3, 0, 4, 4, 0}));
  EXPECT_EQ(file.values<double>("velocity [m/s]"),
            (std::vector<double>{7, -7, 0, 11, -11, 0, 42, -42, 0}));
  EXPECT_EQ(file.values<double>("angular_velocity [rad/s]"),
            (std::vector<double>{1.75, 2.75, 10.5}));
  EXPECT_EQ(file.values<double>("length [m]"), (std::vector<double>{20.0, 4.0, 2.0}));
  EXPECT_EQ(file.values<double>("width [m]"), (std::vector<double>{1.0, 2.0, 1.0}));
  EXPECT_EQ(file.values<double>("TimeValue"), std::vector<double>{3.0});

  // Corners: body 7 along x: (0, 4.5) (20, 4.5) (20, 5.5) (0, 5.5); body 11 turned a quarter:
  // long axis along y, so x spans -3 -+ 1 and y spans 2 -+ 2, counter-clockwise from (-2, 0).
  // Body 42 at pi/6: first corner -(cos, sin) - 0.5 (-sin, cos).
  const double c = std::sqrt(3.0) / 2, s = 0.5;
  const std::vector<double> expected = {
      0,           4.5,         20,          4.5,         20,           5.5,
      0,           5.5,         -2,          0,           -2,           4,
      -4,          4,           -4,          0,           -c + 0.5 * s, -s - 0.5 * c,
      c + 0.5 * s, s - 0.5 * c, c - 0.5 * s, s + 0.5 * c, -c - 0.5 * s, -s + 0.5 * c};
  const auto points = file.values<double>("Points");
  ASSERT_EQ(points.size(), 36u);
  for (int p = 0; p < 12; ++p) {
    EXPECT_NEAR(points[3 * p], expected[2 * p], 1e-14) << "corner " << p;
    EXPECT_NEAR(points[3 * p + 1], expected[2 * p + 1], 1e-14) << "corner " << p;
  }
  EXPECT_EQ(file.values<std::int64_t>("offsets"), (std::vector<std::int64_t>{4, 8, 12}));
}

TEST(BodiesVtp, ExtraArrayOfTheWrongLengthIsNamed) {
  const BodySet bodies = three_bodies();
  const std::vector<double> short_array = {1.0, 2.0, 3.0};
  BodyFields extra;
  extra.add_scalar("lift [N]", short_array);
  try {
    write_bodies_vtp((scratch_folder() / "b.vtp").string(), bodies, extra, 0.0);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "write_bodies_vtp: body array 'lift [N]' has 3 values; expected 4 (one per body)");
  }
}

TEST(BoundaryVtp, EdgesArePolylinesThroughTheirMidNodeWithTheirGroup) {
  const Mesh mesh = small_mesh();
  const fs::path path = scratch_folder() / "boundary.vtp";
  write_boundary_vtp(path.string(), mesh);
  const VtkFile file(path);
  EXPECT_NE(file.xml.find("NumberOfPoints=\"18\""), std::string::npos);
  EXPECT_NE(file.xml.find("NumberOfLines=\"6\""), std::string::npos);
  std::string names;  // each name followed by a NUL
  for (const std::string& name : mesh.group_names) names += name + '\0';
  EXPECT_EQ(file.array("group_names").bytes, names);
  EXPECT_EQ(mesh.group_names.size(), 4u);

  const auto points = file.values<double>("Points");
  const auto groups = file.values<std::int32_t>("group");
  ASSERT_EQ(groups.size(), 6u);
  for (int l = 0; l < 6; ++l) {
    const Vec2 a(points[9 * l], points[9 * l + 1]), m(points[9 * l + 3], points[9 * l + 4]),
        b(points[9 * l + 6], points[9 * l + 7]);
    EXPECT_NEAR((m - 0.5 * (a + b)).norm(), 0.0, 1e-14) << "line " << l;
    const std::string group = mesh.group_names.at(groups[l]);
    // The rectangle is [1, 5] x [-2, 1].
    if (group == "bottom") {
      EXPECT_TRUE(a.y() == -2.0 && b.y() == -2.0);
    }
    if (group == "top") {
      EXPECT_TRUE(a.y() == 1.0 && b.y() == 1.0);
    }
    if (group == "left") {
      EXPECT_TRUE(a.x() == 1.0 && b.x() == 1.0);
    }
    if (group == "right") {
      EXPECT_TRUE(a.x() == 5.0 && b.x() == 5.0);
    }
  }
  EXPECT_EQ(file.values<std::int64_t>("offsets"), (std::vector<std::int64_t>{3, 6, 9, 12, 15, 18}));
}

TEST(PvdWriter, IndexIsValidAfterEveryAdd) {
  const fs::path dir = scratch_folder();
  const fs::path path = dir / "flow.pvd";
  PvdWriter pvd(path.string());
  const std::string head =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "<Collection>\n";
  const std::string tail = "</Collection>\n</VTKFile>\n";
  EXPECT_EQ(read_text(path), head + tail);
  pvd.add(0.0, "flow_000000.vtu");
  pvd.add(0.1, "flow_000001.vtu");
  pvd.add(60.0, "a&b.vtu");
  EXPECT_EQ(read_text(path),
            head +
                "  <DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"flow_000000.vtu\"/>\n"
                "  <DataSet timestep=\"0.10000000000000001\" group=\"\" part=\"0\" "
                "file=\"flow_000001.vtu\"/>\n"
                "  <DataSet timestep=\"60\" group=\"\" part=\"0\" file=\"a&amp;b.vtu\"/>\n" +
                tail);
  EXPECT_EQ(std::stod("0.10000000000000001"), 0.1);
  PvdWriter parts((dir / "all.pvd").string());
  parts.add(5.0, "flow_000001.vtu");
  parts.add(5.0, "bodies_000001.vtp", 1);
  EXPECT_EQ(read_text(dir / "all.pvd"),
            head + "  <DataSet timestep=\"5\" group=\"\" part=\"0\" file=\"flow_000001.vtu\"/>\n" +
                "  <DataSet timestep=\"5\" group=\"\" part=\"1\" file=\"bodies_000001.vtp\"/>\n" +
                tail);  // the time round-trips exactly
  EXPECT_FALSE(fs::exists(path.string() + ".part"));
}

// An index written when closed (an ensemble's member): no file before, one listing every
// dataset after, nothing when nothing was added; the destructor closes an index left open.
TEST(PvdWriter, IndexWrittenWhenClosed) {
  const fs::path dir = scratch_folder();
  const std::string head =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "<Collection>\n";
  const std::string listed =
      "  <DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"flow_000000.vtu\"/>\n"
      "  <DataSet timestep=\"240\" group=\"\" part=\"0\" file=\"flow_000001.vtu\"/>\n";
  const std::string tail = "</Collection>\n</VTKFile>\n";
  const fs::path path = dir / "flow.pvd";
  PvdWriter pvd(path.string(), PvdWriter::Start::when_closed);
  pvd.add(0.0, "flow_000000.vtu");
  pvd.add(240.0, "flow_000001.vtu");
  EXPECT_FALSE(fs::exists(path));
  pvd.close();
  EXPECT_EQ(read_text(path), head + listed + tail);
  EXPECT_THROW(pvd.add(480.0, "flow_000002.vtu"), std::logic_error);
  pvd.close();  // once
  EXPECT_EQ(read_text(path), head + listed + tail);
  {
    PvdWriter left_open((dir / "open.pvd").string(), PvdWriter::Start::when_closed);
    left_open.add(0.0, "flow_000000.vtu");
    left_open.add(240.0, "flow_000001.vtu");
  }
  EXPECT_EQ(read_text(dir / "open.pvd"), head + listed + tail);
  {
    PvdWriter empty((dir / "empty.pvd").string(), PvdWriter::Start::when_closed);
    empty.close();
  }
  EXPECT_FALSE(fs::exists(dir / "empty.pvd"));
  EXPECT_FALSE(fs::exists(path.string() + ".part"));
}

}  // namespace
}  // namespace flotsam
