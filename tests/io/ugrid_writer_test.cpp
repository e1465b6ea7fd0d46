// Verifies that UgridWriter writes the UGRID-1.0 / CF layout QGIS's MDAL 0.9.4 reads
// (../shared/notes/qgis-ugrid-hazard.md): the mesh topology and its attributes, every text
// attribute NC_CHAR, the time axis with its origin, the CRS with its EPSG code, data read back
// bit for bit with NaN stored as the fill value, static fields overwritten in place; that a
// restarted run keeps the records up to its checkpoint and writes the file an unstopped run
// writes; and that a missing or foreign file is an InputError naming it.
#include "io/ugrid_writer.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <netcdf.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "../support/scratch_path.hpp"
#include "core/error.hpp"
#include "geo/gdal_support.hpp"

namespace flotsam {
namespace {

namespace fs = std::filesystem;

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double fill = NC_FILL_DOUBLE;  // the writer's fill value for data

// 2 x 2 squares of 10 m in UTM zone 33N, each split into two counter-clockwise triangles:
//   6 - 7 - 8
//   | / | / |
//   3 - 4 - 5
//   | / | / |
//   0 - 1 - 2
UgridMesh square_mesh(bool with_crs) {
  UgridMesh mesh;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) mesh.nodes.emplace_back(500000.0 + 10.0 * i, 5000000.0 + 10.0 * j);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int a = 3 * j + i;
      mesh.faces.push_back({a, a + 1, a + 4});
      mesh.faces.push_back({a, a + 4, a + 3});
    }
  for (int n = 0; n < 9; ++n) mesh.node_z.push_back(100.0 + n / 3.0);
  if (with_crs) {
    OGRSpatialReference utm;
    EXPECT_EQ(utm.importFromEPSG(32633), OGRERR_NONE);
    mesh.crs_wkt = gdal::wkt_of(utm);
  }
  mesh.time_origin = *parse_calendar_time("2024-01-01 06:30:00");
  return mesh;
}

std::vector<UgridVariable> flow_variables() {
  return {
      {"depth", "water depth", "sea_floor_depth_below_sea_surface", "m", UgridLocation::face, true},
      {"ux", "flow velocity, x-component", "", "m s-1", UgridLocation::face, true},
      {"uy", "flow velocity, y-component", "", "m s-1", UgridLocation::face, true},
      {"wse", "water surface elevation at nodes", "", "m", UgridLocation::node, true},
      {"max_speed", "maximum flow speed", "", "m s-1", UgridLocation::face, false},
  };
}

// Values no decimal writes exactly, so that a round trip through text would show.
std::vector<double> field(int count, double t, double scale) {
  std::vector<double> v;
  for (int k = 0; k < count; ++k) v.push_back(scale * (k + 1) / 7.0 + t / 3.0);
  return v;
}

struct Record {
  double t;
  std::vector<double> depth, ux, uy, wse;
};

Record record(double t) {
  return {t, field(8, t, 1.0), field(8, t, -0.5), field(8, t, 0.25), field(9, t, 2.0)};
}

void append(UgridWriter& w, const Record& r) {
  w.append(r.t, {{"depth", &r.depth}, {"ux", &r.ux}, {"uy", &r.uy}, {"wse", &r.wse}});
}

// --- reading back with the netCDF C API ---

struct Reader {
  int id = -1;
  explicit Reader(const fs::path& path) {
    EXPECT_EQ(nc_open(path.c_str(), NC_NOWRITE, &id), NC_NOERR) << path;
  }
  ~Reader() { nc_close(id); }
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  int var(const std::string& name) const {
    int varid = -1;
    EXPECT_EQ(nc_inq_varid(id, name.c_str(), &varid), NC_NOERR) << name;
    return varid;
  }
  bool has_var(const std::string& name) const {
    int varid = -1;
    return nc_inq_varid(id, name.c_str(), &varid) == NC_NOERR;
  }
  std::size_t dim(const char* name) const {
    int dimid = -1;
    std::size_t length = 0;
    EXPECT_EQ(nc_inq_dimid(id, name, &dimid), NC_NOERR) << name;
    nc_inq_dimlen(id, dimid, &length);
    return length;
  }
  nc_type att_type(int varid, const char* name) const {
    nc_type type = NC_NAT;
    nc_inq_atttype(id, varid, name, &type);
    return type;
  }
  std::string text(const std::string& var_name, const char* name) const {
    const int varid = var_name.empty() ? NC_GLOBAL : var(var_name);
    EXPECT_EQ(att_type(varid, name), NC_CHAR) << var_name << ":" << name;
    std::size_t length = 0;
    nc_inq_attlen(id, varid, name, &length);
    std::string value(length, '\0');
    nc_get_att_text(id, varid, name, value.data());
    return value;
  }
  int integer(const std::string& var_name, const char* name) const {
    const int varid = var(var_name);
    EXPECT_EQ(att_type(varid, name), NC_INT) << var_name << ":" << name;
    int value = 0;
    nc_get_att_int(id, varid, name, &value);
    return value;
  }
  double real(const std::string& var_name, const char* name) const {
    const int varid = var(var_name);
    EXPECT_EQ(att_type(varid, name), NC_DOUBLE) << var_name << ":" << name;
    double value = 0.0;
    nc_get_att_double(id, varid, name, &value);
    return value;
  }
  std::vector<double> doubles(const std::string& name, std::size_t count) const {
    std::vector<double> values(count);
    EXPECT_EQ(nc_get_var_double(id, var(name), values.data()), NC_NOERR) << name;
    return values;
  }
  std::vector<double> record(const std::string& name, std::size_t r, std::size_t count) const {
    std::vector<double> values(count);
    const std::size_t start[2] = {r, 0}, size[2] = {1, count};
    EXPECT_EQ(nc_get_vara_double(id, var(name), start, size, values.data()), NC_NOERR) << name;
    return values;
  }
};

// NaN written -> fill value read; every other value the same bits.
std::vector<double> as_stored(std::vector<double> values) {
  for (double& v : values)
    if (std::isnan(v)) v = fill;
  return values;
}

// Every dimension, variable, attribute and value of a file, as bytes: two files that hold the
// same give the same string, whatever padding the library left after the last record.
std::string contents(const fs::path& path) {
  const Reader r(path);
  std::string out;
  const auto add = [&](const void* data, std::size_t size) {
    out.append(static_cast<const char*>(data), size);
  };
  int variables = 0;
  nc_inq_nvars(r.id, &variables);
  for (int varid = NC_GLOBAL; varid < variables; ++varid) {
    if (varid >= 0) {
      char name[NC_MAX_NAME + 1];
      nc_type type;
      int rank = 0, dims[NC_MAX_VAR_DIMS];
      nc_inq_var(r.id, varid, name, &type, &rank, dims, nullptr);
      std::size_t count = 1, size = 0;
      out += name;
      for (int d = 0; d < rank; ++d) {
        char dim_name[NC_MAX_NAME + 1];
        std::size_t length = 0;
        nc_inq_dim(r.id, dims[d], dim_name, &length);
        out += fmt::format("({} {})", dim_name, length);
        count *= length;
      }
      nc_inq_type(r.id, type, nullptr, &size);
      std::vector<char> values(count * size);
      if (count > 0) {
        EXPECT_EQ(nc_get_var(r.id, varid, values.data()), NC_NOERR) << name;
      }
      add(values.data(), values.size());
    }
    int attributes = 0;
    nc_inq_varnatts(r.id, varid, &attributes);
    for (int k = 0; k < attributes; ++k) {
      char name[NC_MAX_NAME + 1];
      nc_type type;
      std::size_t length = 0, size = 0;
      nc_inq_attname(r.id, varid, k, name);
      nc_inq_att(r.id, varid, name, &type, &length);
      nc_inq_type(r.id, type, nullptr, &size);
      std::vector<char> value(length * size);
      nc_get_att(r.id, varid, name, value.data());
      out += fmt::format("{}:{}:", name, static_cast<int>(type));
      add(value.data(), value.size());
    }
  }
  return out;
}

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

TEST(UgridWriter, WritesTheMeshTopologyMdalNeeds) {
  const fs::path path = test::fresh_test_folder("ugrid") / "mesh.nc";
  const UgridMesh mesh = square_mesh(true);
  { UgridWriter w(path.string(), mesh, flow_variables(), "two squares"); }
  const Reader r(path);
  int format = 0;
  nc_inq_format(r.id, &format);
  EXPECT_EQ(format, NC_FORMAT_64BIT_OFFSET);
  EXPECT_EQ(r.dim("node"), 9u);
  EXPECT_EQ(r.dim("face"), 8u);
  EXPECT_EQ(r.dim("max_face_nodes"), 3u);
  EXPECT_EQ(r.dim("time"), 0u);
  int unlimited = -1, time_dim = -1;
  nc_inq_unlimdim(r.id, &unlimited);
  nc_inq_dimid(r.id, "time", &time_dim);
  EXPECT_EQ(unlimited, time_dim);

  EXPECT_EQ(r.text("mesh", "cf_role"), "mesh_topology");
  EXPECT_EQ(r.integer("mesh", "topology_dimension"), 2);
  EXPECT_EQ(r.text("mesh", "node_coordinates"), "node_x node_y");
  EXPECT_EQ(r.text("mesh", "face_node_connectivity"), "face_nodes");
  EXPECT_EQ(r.text("mesh", "face_dimension"), "face");
  EXPECT_EQ(r.text("mesh", "face_coordinates"), "face_x face_y");
  EXPECT_EQ(r.text("face_nodes", "cf_role"), "face_node_connectivity");
  EXPECT_EQ(r.integer("face_nodes", "start_index"), 0);
  EXPECT_EQ(r.integer("face_nodes", "_FillValue"), -999);
  EXPECT_EQ(r.text("", "Conventions"), "CF-1.8 UGRID-1.0");
  EXPECT_EQ(r.text("", "title"), "two squares");
  EXPECT_EQ(r.text("", "source"), "flotsam " FLOTSAM_VERSION);

  std::vector<int> corners(24);
  nc_get_var_int(r.id, r.var("face_nodes"), corners.data());
  for (int f = 0; f < 8; ++f)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(corners[3 * f + k], mesh.faces[f][k]) << f;
  const auto x = r.doubles("node_x", 9), y = r.doubles("node_y", 9);
  const auto cx = r.doubles("face_x", 8), cy = r.doubles("face_y", 8);
  for (int n = 0; n < 9; ++n) {
    EXPECT_EQ(x[n], mesh.nodes[n].x());
    EXPECT_EQ(y[n], mesh.nodes[n].y());
  }
  for (int f = 0; f < 8; ++f) {
    const auto& [a, b, c] = mesh.faces[f];
    const Vec2 centroid = (mesh.nodes[a] + mesh.nodes[b] + mesh.nodes[c]) / 3.0;
    EXPECT_EQ(cx[f], centroid.x()) << f;
    EXPECT_EQ(cy[f], centroid.y()) << f;
  }
  EXPECT_EQ(r.doubles("node_z", 9), mesh.node_z);
  EXPECT_EQ(r.text("node_z", "standard_name"), "altitude");
  EXPECT_EQ(r.text("node_z", "long_name"), "bed elevation");
  EXPECT_EQ(r.text("node_z", "mesh"), "mesh");
  EXPECT_EQ(r.text("node_z", "location"), "node");

  // MDAL 0.9.4 fails on a file with any NC_STRING attribute: every text is NC_CHAR.
  int variables = 0;
  nc_inq_nvars(r.id, &variables);
  for (int varid = NC_GLOBAL; varid < variables; ++varid) {
    int attributes = 0;
    nc_inq_varnatts(r.id, varid, &attributes);
    for (int k = 0; k < attributes; ++k) {
      char name[NC_MAX_NAME + 1];
      nc_inq_attname(r.id, varid, k, name);
      const nc_type type = r.att_type(varid, name);
      EXPECT_TRUE(type == NC_CHAR || type == NC_INT || type == NC_DOUBLE)
          << "variable " << varid << " attribute " << name << " has type " << type;
    }
  }
}

TEST(UgridWriter, WritesTheCrsWithItsEpsgCode) {
  const fs::path path = test::fresh_test_folder("ugrid") / "crs.nc";
  const UgridMesh mesh = square_mesh(true);
  { UgridWriter w(path.string(), mesh, flow_variables(), "crs"); }
  const Reader r(path);
  EXPECT_EQ(r.integer("crs", "epsg"), 32633);
  EXPECT_EQ(r.text("crs", "EPSG_code"), "EPSG:32633");
  EXPECT_EQ(r.text("crs", "crs_wkt"), mesh.crs_wkt);
  EXPECT_EQ(r.text("crs", "wkt"), mesh.crs_wkt);
  for (const char* name : {"node_x", "node_y", "node_z", "face_x", "face_y", "depth", "ux"})
    EXPECT_EQ(r.text(name, "grid_mapping"), "crs") << name;
  EXPECT_EQ(r.text("node_x", "standard_name"), "projection_x_coordinate");
  EXPECT_EQ(r.text("node_y", "standard_name"), "projection_y_coordinate");
  EXPECT_EQ(r.text("node_x", "units"), "m");
}

TEST(UgridWriter, WithoutCrsOrOriginWritesPlainCoordinatesAndTheEpoch) {
  const fs::path path = test::fresh_test_folder("ugrid") / "plain.nc";
  UgridMesh mesh = square_mesh(false);
  mesh.time_origin = {};
  mesh.node_z.clear();
  { UgridWriter w(path.string(), mesh, flow_variables(), "plain"); }
  const Reader r(path);
  EXPECT_FALSE(r.has_var("crs"));
  EXPECT_FALSE(r.has_var("node_z"));
  EXPECT_EQ(nc_inq_att(r.id, r.var("node_x"), "standard_name", nullptr, nullptr), NC_ENOTATT);
  EXPECT_EQ(nc_inq_att(r.id, r.var("depth"), "grid_mapping", nullptr, nullptr), NC_ENOTATT);
  EXPECT_EQ(r.text("node_x", "long_name"), "x of the mesh nodes");
  EXPECT_EQ(r.text("face_y", "long_name"), "y of the face centroids");
  EXPECT_EQ(r.text("time", "units"), "seconds since 1970-01-01 00:00:00");
}

TEST(UgridWriter, RecordsReadBackBitForBitWithNanAsTheFillValue) {
  const fs::path path = test::fresh_test_folder("ugrid") / "records.nc";
  std::vector<Record> records = {record(0.0), record(60.0), record(3600.5)};
  records[1].depth[3] = nan;  // a dry cell
  records[2].wse[0] = nan;
  {
    UgridWriter w(path.string(), square_mesh(true), flow_variables(), "records");
    for (const Record& rec : records) append(w, rec);
    EXPECT_EQ(w.record_count(), 3u);
  }
  const Reader r(path);
  EXPECT_EQ(r.dim("time"), 3u);
  EXPECT_EQ(r.doubles("time", 3), (std::vector<double>{0.0, 60.0, 3600.5}));
  EXPECT_EQ(r.text("time", "units"), "seconds since 2024-01-01 06:30:00");
  EXPECT_EQ(r.text("time", "calendar"), "standard");
  EXPECT_EQ(r.text("time", "axis"), "T");
  EXPECT_EQ(r.text("time", "standard_name"), "time");
  EXPECT_EQ(r.text("ux", "long_name"), "flow velocity, x-component");
  EXPECT_EQ(r.text("uy", "long_name"), "flow velocity, y-component");
  EXPECT_EQ(r.text("depth", "standard_name"), "sea_floor_depth_below_sea_surface");
  EXPECT_EQ(nc_inq_att(r.id, r.var("ux"), "standard_name", nullptr, nullptr), NC_ENOTATT);
  EXPECT_EQ(r.text("ux", "units"), "m s-1");
  EXPECT_EQ(r.text("wse", "location"), "node");
  EXPECT_EQ(r.text("depth", "location"), "face");
  EXPECT_EQ(r.text("depth", "mesh"), "mesh");
  EXPECT_EQ(r.real("depth", "_FillValue"), fill);
  for (std::size_t k = 0; k < records.size(); ++k) {
    EXPECT_EQ(r.record("depth", k, 8), as_stored(records[k].depth)) << k;
    EXPECT_EQ(r.record("ux", k, 8), records[k].ux) << k;
    EXPECT_EQ(r.record("uy", k, 8), records[k].uy) << k;
    EXPECT_EQ(r.record("wse", k, 9), as_stored(records[k].wse)) << k;
  }
  EXPECT_EQ(r.record("depth", 1, 8)[3], fill);
  EXPECT_EQ(r.record("wse", 2, 9)[0], fill);
}

TEST(UgridWriter, EachRecordIsReadableBeforeTheFileCloses) {
  const fs::path path = test::fresh_test_folder("ugrid") / "live.nc";
  UgridWriter w(path.string(), square_mesh(true), flow_variables(), "live");
  const Record first = record(10.0);
  append(w, first);
  {
    const Reader r(path);  // another opener, while the writer holds the file
    EXPECT_EQ(r.dim("time"), 1u);
    EXPECT_EQ(r.doubles("time", 1), std::vector<double>{10.0});
    EXPECT_EQ(r.record("depth", 0, 8), first.depth);
    EXPECT_EQ(r.record("wse", 0, 9), first.wse);
  }
  append(w, record(20.0));
  const Reader r(path);
  EXPECT_EQ(r.dim("time"), 2u);
  EXPECT_EQ(r.record("uy", 1, 8), record(20.0).uy);
}

TEST(UgridWriter, StaticFieldIsFillUntilSetThenOverwrittenInPlace) {
  const fs::path path = test::fresh_test_folder("ugrid") / "static.nc";
  UgridWriter w(path.string(), square_mesh(true), flow_variables(), "static");
  {
    const Reader r(path);
    EXPECT_EQ(r.doubles("max_speed", 8), std::vector<double>(8, fill));
    int rank = 0;
    nc_inq_varndims(r.id, r.var("max_speed"), &rank);
    EXPECT_EQ(rank, 1);  // (face): no time dimension
  }
  append(w, record(0.0));
  w.set_static("max_speed", field(8, 1.0, 3.0));
  std::vector<double> second = field(8, 2.0, 5.0);
  second[7] = nan;
  w.set_static("max_speed", second);
  const Reader r(path);
  EXPECT_EQ(r.doubles("max_speed", 8), as_stored(second));
  EXPECT_EQ(r.text("max_speed", "long_name"), "maximum flow speed");
}

TEST(UgridWriter, ResumeKeepsTheRecordsUpToTheCheckpointAndGoesOn) {
  const fs::path folder = test::fresh_test_folder("ugrid");
  const fs::path path = folder / "run.nc";
  const std::vector<Record> first_run = {record(0.0), record(30.0), record(60.0)};
  const std::vector<double> envelope = field(8, 4.0, 1.5);
  {
    UgridWriter w(path.string(), square_mesh(true), flow_variables(), "restarted");
    for (const Record& rec : first_run) append(w, rec);
    w.set_static("max_speed", envelope);
  }
  // The checkpoint was at t = 30 s: the record at 60 s goes, a new one at 45 s comes.
  const Record again = record(45.0);
  {
    UgridWriter w = UgridWriter::resume(path.string(), square_mesh(true), flow_variables(), 30.0);
    EXPECT_EQ(w.record_count(), 2u);
    append(w, again);
    w.set_static("max_speed", envelope);
  }
  EXPECT_FALSE(fs::exists(folder / "run.nc.part"));
  {
    const Reader r(path);
    EXPECT_EQ(r.doubles("time", 3), (std::vector<double>{0.0, 30.0, 45.0}));
    EXPECT_EQ(r.text("", "title"), "restarted");
    for (int k = 0; k < 2; ++k) {
      EXPECT_EQ(r.record("depth", k, 8), first_run[k].depth);
      EXPECT_EQ(r.record("wse", k, 9), first_run[k].wse);
    }
    EXPECT_EQ(r.record("depth", 2, 8), again.depth);
    EXPECT_EQ(r.record("ux", 2, 8), again.ux);
    EXPECT_EQ(r.record("wse", 2, 9), again.wse);
    EXPECT_EQ(r.doubles("max_speed", 8), envelope);
  }
  // The file of a run that never stopped.
  const fs::path straight = folder / "straight.nc";
  {
    UgridWriter w(straight.string(), square_mesh(true), flow_variables(), "restarted");
    for (const Record& rec : {first_run[0], first_run[1], again}) append(w, rec);
    w.set_static("max_speed", envelope);
  }
  EXPECT_TRUE(contents(path) == contents(straight));
}

TEST(UgridWriter, ResumeAtTheLastRecordKeepsThemAll) {
  const fs::path path = test::fresh_test_folder("ugrid") / "all.nc";
  {
    UgridWriter w(path.string(), square_mesh(true), flow_variables(), "all");
    for (double t : {0.0, 30.0, 60.0}) append(w, record(t));
  }
  UgridWriter w = UgridWriter::resume(path.string(), square_mesh(true), flow_variables(), 60.0);
  EXPECT_EQ(w.record_count(), 3u);
  EXPECT_THROW(append(w, record(60.0)), std::invalid_argument);  // not after the last
  append(w, record(90.0));
  const Reader r(path);
  EXPECT_EQ(r.doubles("time", 4), (std::vector<double>{0.0, 30.0, 60.0, 90.0}));
  EXPECT_EQ(r.record("depth", 3, 8), record(90.0).depth);
}

// The message of the InputError `f` throws.
template <class F>
std::string input_error_of(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

TEST(UgridWriter, ResumeOnAMissingFileNamesIt) {
  const fs::path path = test::fresh_test_folder("ugrid") / "missing.nc";
  const std::string message = input_error_of(
      [&] { UgridWriter::resume(path.string(), square_mesh(true), flow_variables(), 0.0); });
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  EXPECT_NE(message.find("missing"), std::string::npos) << message;
}

TEST(UgridWriter, ResumeOnAFileOfAnotherMeshOrOtherVariablesNamesWhatDiffers) {
  const fs::path folder = test::fresh_test_folder("ugrid");
  const fs::path path = folder / "other.nc";
  {
    UgridWriter w(path.string(), square_mesh(true), flow_variables(), "other");
    append(w, record(0.0));
  }
  const std::string before = bytes_of(path);

  UgridMesh smaller = square_mesh(true);
  smaller.faces.pop_back();
  std::string message =
      input_error_of([&] { UgridWriter::resume(path.string(), smaller, flow_variables(), 0.0); });
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  EXPECT_NE(message.find("9 nodes and 8 faces, this run's 9 and 7"), std::string::npos) << message;

  UgridMesh moved = square_mesh(true);
  moved.nodes[4].x() += 1.0;
  message =
      input_error_of([&] { UgridWriter::resume(path.string(), moved, flow_variables(), 0.0); });
  EXPECT_NE(message.find("its node 4 lies at"), std::string::npos) << message;

  std::vector<UgridVariable> fewer = flow_variables();
  fewer.erase(fewer.begin() + 3);  // no wse
  message =
      input_error_of([&] { UgridWriter::resume(path.string(), square_mesh(true), fewer, 0.0); });
  EXPECT_NE(message.find("'wse'"), std::string::npos) << message;

  std::vector<UgridVariable> more = flow_variables();
  more.push_back({"speed", "flow speed", "", "m s-1", UgridLocation::face, true});
  message =
      input_error_of([&] { UgridWriter::resume(path.string(), square_mesh(true), more, 0.0); });
  EXPECT_NE(message.find("no variable 'speed'"), std::string::npos) << message;

  UgridMesh later = square_mesh(true);
  later.time_origin = *parse_calendar_time("2024-01-02 06:30:00");
  message =
      input_error_of([&] { UgridWriter::resume(path.string(), later, flow_variables(), 0.0); });
  EXPECT_NE(message.find("seconds since 2024-01-01 06:30:00"), std::string::npos) << message;

  EXPECT_TRUE(bytes_of(path) == before);  // a refused file is left as it was

  const fs::path text = folder / "not_netcdf.nc";
  std::ofstream(text) << "time [s],x [m]\n";
  message = input_error_of(
      [&] { UgridWriter::resume(text.string(), square_mesh(true), flow_variables(), 0.0); });
  EXPECT_NE(message.find(text.string()), std::string::npos) << message;
}

TEST(UgridWriter, ProgrammingErrorsAreRefused) {
  const fs::path folder = test::fresh_test_folder("ugrid");
  const std::string path = (folder / "errors.nc").string();
  UgridWriter w(path, square_mesh(true), flow_variables(), "errors");
  const std::vector<double> eight(8, 1.0), nine(9, 1.0), seven(7, 1.0);
  EXPECT_THROW(w.append(0.0, {{"depth", &eight}, {"ux", &eight}, {"uy", &eight}}),
               std::invalid_argument);  // wse missing
  EXPECT_THROW(w.append(0.0, {{"depth", &seven}, {"ux", &eight}, {"uy", &eight}, {"wse", &nine}}),
               std::invalid_argument);  // wrong size
  EXPECT_THROW(w.append(0.0, {{"depth", &eight},
                              {"ux", &eight},
                              {"uy", &eight},
                              {"wse", &nine},
                              {"max_speed", &eight}}),
               std::invalid_argument);  // a static field among the records
  EXPECT_EQ(w.record_count(), 0u);      // nothing half written
  EXPECT_THROW(w.set_static("depth", eight), std::invalid_argument);
  EXPECT_THROW(w.set_static("max_speed", nine), std::invalid_argument);

  const std::string other = (folder / "refused.nc").string();
  const auto define = [&](std::vector<UgridVariable> variables) {
    UgridWriter(other, square_mesh(true), std::move(variables), "errors");
  };
  auto static_vector = flow_variables();
  static_vector.push_back(
      {"mx", "max velocity, x-component", "", "m s-1", UgridLocation::face, false});
  static_vector.push_back(
      {"my", "max velocity, y-component", "", "m s-1", UgridLocation::face, false});
  EXPECT_THROW(define(static_vector), std::invalid_argument);
  auto unpaired = flow_variables();
  unpaired.erase(unpaired.begin() + 2);  // ux without uy
  EXPECT_THROW(define(unpaired), std::invalid_argument);
  auto same_long_name = flow_variables();
  same_long_name[3].long_name = "water depth";
  EXPECT_THROW(define(same_long_name), std::invalid_argument);
  auto reserved = flow_variables();
  reserved[0].name = "time";
  EXPECT_THROW(define(reserved), std::invalid_argument);
}

}  // namespace
}  // namespace flotsam
