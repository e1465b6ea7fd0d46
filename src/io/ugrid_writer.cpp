#include "io/ugrid_writer.hpp"

#include <cpl_error.h>
#include <fmt/format.h>
#include <netcdf.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <set>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <tuple>
#include <type_traits>
#include <utility>

#include "core/error.hpp"

namespace flotsam {

namespace {

// What a NaN becomes, and MDAL turns back into "no value": netCDF's own default fill for
// doubles, 9.97e36, which no depth, level or speed can be.
constexpr double fill_value = NC_FILL_DOUBLE;
constexpr int no_node = -999;  // the connectivity's _FillValue (never used by triangles)
constexpr char mesh_name[] = "mesh";
const std::set<std::string> reserved_names = {"mesh",       "node_x", "node_y", "face_x", "face_y",
                                              "face_nodes", "node_z", "crs",    "time"};

void check(int status, const std::string& path, std::string_view what) {
  if (status != NC_NOERR) throw_input_error("'{}': {} failed: {}", path, what, nc_strerror(status));
}

std::string location_name(UgridLocation location) {
  return location == UgridLocation::node ? "node" : "face";
}

// MDAL 0.9.4 pairs the long names holding ", x-component" and ", y-component" (mdal_ugrid.cpp,
// parseNetCDFVariableMetadata) into one vector group named by the rest.
std::string component_mark(std::string_view axis) {
  return fmt::format(", {}-component", axis);
}

// Programming errors in the list of variables, and the rules of the note's pitfalls table: one
// long_name per variable, vector components in pairs, no static vector.
void check_variables(const std::vector<UgridVariable>& variables) {
  std::set<std::string> names, long_names;
  for (const UgridVariable& v : variables) {
    if (v.name.empty() || reserved_names.count(v.name) || !names.insert(v.name).second)
      throw std::invalid_argument(
          fmt::format("UgridWriter: variable name '{}' is empty, "
                      "reserved or given twice",
                      v.name));
    if (v.long_name.empty() || !long_names.insert(v.long_name).second)
      throw std::invalid_argument(
          fmt::format("UgridWriter: '{}': long_name '{}' is empty or not unique (MDAL keys "
                      "groups by it)",
                      v.name, v.long_name));
    if (v.units.empty())
      throw std::invalid_argument(fmt::format("UgridWriter: '{}' has no units", v.name));
  }
  for (const UgridVariable& v : variables) {
    for (const auto& [axis, other] : {std::pair{"x", "y"}, std::pair{"y", "x"}}) {
      const std::size_t at = v.long_name.find(component_mark(axis));
      if (at == std::string::npos) continue;
      if (!v.timed)
        throw std::invalid_argument(fmt::format(
            "UgridWriter: '{}' is a static vector component; MDAL 0.9.4 reads its y as x", v.name));
      std::string pair = v.long_name;
      pair.replace(at, component_mark(axis).size(), component_mark(other));
      const auto match = std::find_if(variables.begin(), variables.end(), [&](const auto& w) {
        return w.long_name == pair && w.location == v.location && w.timed;
      });
      if (match == variables.end())
        throw std::invalid_argument(fmt::format(
            "UgridWriter: '{}' ({}) has no timed '{}' on its location", v.name, v.long_name, pair));
    }
  }
}

void check_mesh(const UgridMesh& mesh) {
  const std::size_t n = mesh.nodes.size();
  if (n == 0 || mesh.faces.empty())
    throw std::invalid_argument("UgridWriter: a mesh without nodes or faces");
  if (!mesh.node_z.empty() && mesh.node_z.size() != n)
    throw std::invalid_argument(
        fmt::format("UgridWriter: node_z has {} values for {} nodes", mesh.node_z.size(), n));
  for (const auto& face : mesh.faces)
    for (const int node : face)
      if (node < 0 || static_cast<std::size_t>(node) >= n)
        throw std::invalid_argument(
            fmt::format("UgridWriter: a face names node {} of {}", node, n));
}

int epsg_code(const OGRSpatialReference& srs) {
  const char* authority = srs.GetAuthorityName(nullptr);
  const char* code = srs.GetAuthorityCode(nullptr);
  return authority && code && std::string_view(authority) == "EPSG" ? std::atoi(code) : 0;
}

/// The EPSG code of a coordinate system, or 0 when it has none (a local or custom system).
int epsg_of(const std::string& wkt) {
  CPLPushErrorHandler(CPLQuietErrorHandler);
  OGRSpatialReference srs;
  int code = 0;
  if (srs.importFromWkt(wkt.c_str()) == OGRERR_NONE) {
    srs.AutoIdentifyEPSG();  // fills in the code of UTM and the usual geographic systems
    code = epsg_code(srs);
    if (code == 0) {  // e.g. a GeoTIFF's WKT without AUTHORITY: the PROJ database's match
      const std::unique_ptr<OGRSpatialReference> match(srs.FindBestMatch(90, "EPSG"));
      if (match) code = epsg_code(*match);
    }
  }
  CPLPopErrorHandler();
  return code;
}

/// Attributes of one variable (or NC_GLOBAL), every text as NC_CHAR (MDAL 0.9.4 rejects a file
/// with an NC_STRING attribute).
struct Attributes {
  int ncid;
  int varid;
  const std::string& path;
  std::string owner;  // for messages
  void text(const char* name, const std::string& value) const {
    check(nc_put_att_text(ncid, varid, name, value.size(), value.c_str()), path,
          fmt::format("writing attribute {} of {}", name, owner));
  }
  void integer(const char* name, int value) const {
    check(nc_put_att_int(ncid, varid, name, NC_INT, 1, &value), path,
          fmt::format("writing attribute {} of {}", name, owner));
  }
  void real(const char* name, double value) const {
    check(nc_put_att_double(ncid, varid, name, NC_DOUBLE, 1, &value), path,
          fmt::format("writing attribute {} of {}", name, owner));
  }
};

int define_variable(int ncid, const std::string& path, const std::string& name, nc_type type,
                    std::initializer_list<int> dimensions) {
  int varid = -1;
  check(nc_def_var(ncid, name.c_str(), type, static_cast<int>(dimensions.size()),
                   dimensions.begin(), &varid),
        path, fmt::format("defining variable '{}'", name));
  return varid;
}

int variable_id(int ncid, const std::string& path, const std::string& name) {
  int varid = -1;
  check(nc_inq_varid(ncid, name.c_str(), &varid), path, fmt::format("finding variable '{}'", name));
  return varid;
}

std::size_t dimension_length(int ncid, const std::string& path, const char* name) {
  int dimid = -1;
  std::size_t length = 0;
  check(nc_inq_dimid(ncid, name, &dimid), path, fmt::format("finding dimension '{}'", name));
  check(nc_inq_dimlen(ncid, dimid, &length), path, fmt::format("reading dimension '{}'", name));
  return length;
}

template <class T>
std::vector<T> read_all(int ncid, const std::string& path, const std::string& name,
                        std::size_t count) {
  std::vector<T> values(count);
  const int varid = variable_id(ncid, path, name);
  int status;
  if constexpr (std::is_same_v<T, int>)
    status = nc_get_var_int(ncid, varid, values.data());
  else
    status = nc_get_var_double(ncid, varid, values.data());
  check(status, path, fmt::format("reading variable '{}'", name));
  return values;
}

/// A text attribute, or "" when absent or not text.
std::string text_attribute(int ncid, int varid, const char* name) {
  nc_type type;
  std::size_t length = 0;
  if (nc_inq_att(ncid, varid, name, &type, &length) != NC_NOERR || type != NC_CHAR) return "";
  std::string value(length, '\0');
  if (nc_get_att_text(ncid, varid, name, value.data()) != NC_NOERR) return "";
  return value;
}

}  // namespace

UgridWriter::UgridWriter(const std::string& path, const UgridMesh& mesh,
                         std::vector<UgridVariable> variables, const std::string& title)
    : path_(path),
      node_count_(mesh.nodes.size()),
      face_count_(mesh.faces.size()),
      variables_(std::move(variables)) {
  check_variables(variables_);
  check_mesh(mesh);
  // CalendarTime::text has the space MDAL needs before the clock time (an ISO "T...Z" loses
  // the time of day in MDAL 0.9.4).
  const std::string origin = mesh.time_origin.text();
  check(nc_create(path_.c_str(), NC_CLOBBER | NC_64BIT_OFFSET, &file_.id), path_, "creating");
  define(mesh, origin, title);
  write_mesh(mesh);
  int previous_mode;
  // From here every record is written whole, so the library need not fill it first.
  check(nc_set_fill(file_.id, NC_NOFILL, &previous_mode), path_, "setting the fill mode");
  sync();
}

void UgridWriter::define(const UgridMesh& mesh, const std::string& origin,
                         const std::string& title) {
  const int id = file_.id;
  int node = -1, face = -1, corner = -1, time = -1;
  check(nc_def_dim(id, "node", node_count_, &node), path_, "defining dimension 'node'");
  check(nc_def_dim(id, "face", face_count_, &face), path_, "defining dimension 'face'");
  check(nc_def_dim(id, "max_face_nodes", 3, &corner), path_, "defining 'max_face_nodes'");
  check(nc_def_dim(id, "time", NC_UNLIMITED, &time), path_, "defining dimension 'time'");
  const bool has_crs = !mesh.crs_wkt.empty();
  const auto attributes = [&](int varid, const std::string& name) {
    return Attributes{id, varid, path_, "'" + name + "'"};
  };

  // The topology (UGRID-1.0 "2D flexible mesh topology").
  const auto topology = attributes(define_variable(id, path_, mesh_name, NC_INT, {}), mesh_name);
  topology.text("cf_role", "mesh_topology");
  topology.text("long_name", "topology of the 2D triangular mesh");
  topology.integer("topology_dimension", 2);  // MDAL refuses a mesh without it
  topology.text("node_coordinates", "node_x node_y");
  topology.text("face_node_connectivity", "face_nodes");
  topology.text("face_dimension", "face");
  // MDAL 0.9.4 (mdal_ugrid.cpp, ignore2DMeshVariables) shows every variable on the faces as a
  // dataset group except those the mesh names: without this, "x/y of the face centroids" appear
  // as two groups in QGIS 3.22.16 (tried; the note's pitfalls table has this row inverted).
  topology.text("face_coordinates", "face_x face_y");

  // Coordinates: projected x, y with a CRS; plain lengths without.
  for (const auto& [name, dimension, axis, what] :
       {std::tuple{"node_x", node, 'x', "mesh nodes"},
        std::tuple{"node_y", node, 'y', "mesh nodes"},
        std::tuple{"face_x", face, 'x', "face centroids"},
        std::tuple{"face_y", face, 'y', "face centroids"}}) {
    const auto a = attributes(define_variable(id, path_, name, NC_DOUBLE, {dimension}), name);
    if (has_crs) a.text("standard_name", fmt::format("projection_{}_coordinate", axis));
    a.text("long_name", fmt::format("{} of the {}", axis, what));
    a.text("units", "m");
    if (has_crs) a.text("grid_mapping", "crs");
  }

  const auto connectivity =
      attributes(define_variable(id, path_, "face_nodes", NC_INT, {face, corner}), "face_nodes");
  connectivity.text("cf_role", "face_node_connectivity");
  connectivity.text("long_name", "the nodes of each face, counter-clockwise");
  connectivity.integer("start_index", 0);  // UGRID's default, but MDAL demands it
  connectivity.integer("_FillValue", no_node);

  if (!mesh.node_z.empty()) {  // MDAL's bed elevation: altitude, on the mesh's nodes
    const auto z = attributes(define_variable(id, path_, "node_z", NC_DOUBLE, {node}), "node_z");
    z.text("standard_name", "altitude");
    z.text("long_name", "bed elevation");
    z.text("units", "m");
    z.text("mesh", mesh_name);
    z.text("location", "node");
    if (has_crs) z.text("grid_mapping", "crs");
  }

  if (has_crs) {  // MDAL reads wkt, then EPSG_code, then epsg; CF readers crs_wkt
    const auto crs = attributes(define_variable(id, path_, "crs", NC_INT, {}), "crs");
    crs.text("long_name", "coordinate reference system");
    if (const int epsg = epsg_of(mesh.crs_wkt); epsg > 0) {
      crs.integer("epsg", epsg);
      crs.text("EPSG_code", fmt::format("EPSG:{}", epsg));
    }
    crs.text("crs_wkt", mesh.crs_wkt);
    crs.text("wkt", mesh.crs_wkt);
  }

  // Named exactly "time" (dimension and variable), or MDAL drops every timed variable.
  time_varid_ = define_variable(id, path_, "time", NC_DOUBLE, {time});
  const auto t = attributes(time_varid_, "time");
  t.text("standard_name", "time");
  t.text("long_name", "time");
  t.text("units", fmt::format("seconds since {}", origin));
  t.text("calendar", "standard");
  t.text("axis", "T");

  for (const UgridVariable& v : variables_) {
    const int where = v.location == UgridLocation::node ? node : face;
    const int varid = v.timed ? define_variable(id, path_, v.name, NC_DOUBLE, {time, where})
                              : define_variable(id, path_, v.name, NC_DOUBLE, {where});
    varids_.push_back(varid);
    const auto a = attributes(varid, v.name);
    a.text("long_name", v.long_name);
    if (!v.standard_name.empty()) a.text("standard_name", v.standard_name);
    a.text("units", v.units);
    a.text("mesh", mesh_name);
    a.text("location", location_name(v.location));
    if (has_crs) a.text("grid_mapping", "crs");
    a.real("_FillValue", fill_value);
  }

  const Attributes global{id, NC_GLOBAL, path_, "the file"};
  global.text("Conventions", "CF-1.8 UGRID-1.0");
  global.text("title", title);
  global.text("source", fmt::format("flotsam {}", FLOTSAM_VERSION));
  global.text("history", fmt::format("written by flotsam {}", FLOTSAM_VERSION));
  // With the fill mode on, the end of the definitions fills the static variables: "no value
  // yet" until set_static writes them.
  check(nc_enddef(id), path_, "ending the definitions");
}

void UgridWriter::write_mesh(const UgridMesh& mesh) {
  std::vector<double> x(node_count_), y(node_count_), cx(face_count_), cy(face_count_);
  std::vector<int> corners(3 * face_count_);
  for (std::size_t i = 0; i < node_count_; ++i) {
    x[i] = mesh.nodes[i].x();
    y[i] = mesh.nodes[i].y();
  }
  for (std::size_t f = 0; f < face_count_; ++f) {
    const auto& [a, b, c] = mesh.faces[f];
    const Vec2 centroid = (mesh.nodes[a] + mesh.nodes[b] + mesh.nodes[c]) / 3.0;
    cx[f] = centroid.x();
    cy[f] = centroid.y();
    std::copy(mesh.faces[f].begin(), mesh.faces[f].end(), corners.begin() + 3 * f);
  }
  const int id = file_.id;
  for (const auto& [name, values] : {std::pair{"node_x", &x}, std::pair{"node_y", &y},
                                     std::pair{"face_x", &cx}, std::pair{"face_y", &cy}})
    check(nc_put_var_double(id, variable_id(id, path_, name), values->data()), path_,
          fmt::format("writing variable '{}'", name));
  check(nc_put_var_int(id, variable_id(id, path_, "face_nodes"), corners.data()), path_,
        "writing variable 'face_nodes'");
  if (!mesh.node_z.empty())
    check(nc_put_var_double(id, variable_id(id, path_, "node_z"), mesh.node_z.data()), path_,
          "writing variable 'node_z'");
}

namespace {

std::string shape(bool timed, UgridLocation location) {
  return fmt::format("({}{})", timed ? "time, " : "", location_name(location));
}

/// What makes the file `old` unfit for this run's records, or "" when it fits.
std::string difference(int old, const std::string& path, const UgridMesh& mesh,
                       const std::vector<UgridVariable>& variables) {
  const std::size_t nodes = dimension_length(old, path, "node");
  const std::size_t faces = dimension_length(old, path, "face");
  if (nodes != mesh.nodes.size() || faces != mesh.faces.size())
    return fmt::format("its mesh has {} nodes and {} faces, this run's {} and {}", nodes, faces,
                       mesh.nodes.size(), mesh.faces.size());
  const auto x = read_all<double>(old, path, "node_x", nodes);
  const auto y = read_all<double>(old, path, "node_y", nodes);
  for (std::size_t i = 0; i < nodes; ++i)
    if (x[i] != mesh.nodes[i].x() || y[i] != mesh.nodes[i].y())
      return fmt::format("its node {} lies at ({}, {}) m, this run's at ({}, {}) m", i, x[i], y[i],
                         mesh.nodes[i].x(), mesh.nodes[i].y());
  const auto corners = read_all<int>(old, path, "face_nodes", 3 * faces);
  for (std::size_t f = 0; f < faces; ++f)
    if (!std::equal(mesh.faces[f].begin(), mesh.faces[f].end(), corners.begin() + 3 * f))
      return fmt::format("its face {} has the nodes {} {} {}, this run's {} {} {}", f,
                         corners[3 * f], corners[3 * f + 1], corners[3 * f + 2], mesh.faces[f][0],
                         mesh.faces[f][1], mesh.faces[f][2]);
  const std::string units = text_attribute(old, variable_id(old, path, "time"), "units");
  const std::string expected = "seconds since " + mesh.time_origin.text();
  if (units != expected)
    return fmt::format("it counts time in '{}', this run in '{}'", units, expected);

  int time_dim = -1;
  check(nc_inq_dimid(old, "time", &time_dim), path, "finding dimension 'time'");
  std::set<std::string> expected_names;
  for (const UgridVariable& v : variables) {
    expected_names.insert(v.name);
    int varid = -1, rank = 0, dims[NC_MAX_VAR_DIMS];
    if (nc_inq_varid(old, v.name.c_str(), &varid) != NC_NOERR)
      return fmt::format("it has no variable '{}' ({}), which this run writes", v.name,
                         v.long_name);
    check(nc_inq_var(old, varid, nullptr, nullptr, &rank, dims, nullptr), path,
          fmt::format("reading variable '{}'", v.name));
    int where = -1;
    check(nc_inq_dimid(old, location_name(v.location).c_str(), &where), path, "finding dimensions");
    const bool same = v.timed ? rank == 2 && dims[0] == time_dim && dims[1] == where
                              : rank == 1 && dims[0] == where;
    if (!same)
      return fmt::format("its variable '{}' is not on {} as this run's", v.name,
                         shape(v.timed, v.location));
  }
  int count = 0;
  check(nc_inq_nvars(old, &count), path, "counting the variables");
  for (int varid = 0; varid < count; ++varid) {
    char name[NC_MAX_NAME + 1];
    check(nc_inq_varname(old, varid, name), path, "reading the variables' names");
    if (text_attribute(old, varid, "mesh") == mesh_name && !reserved_names.count(name) &&
        !expected_names.count(name))
      return fmt::format("it holds the variable '{}', which this run does not write", name);
  }
  return "";
}

}  // namespace

UgridWriter UgridWriter::resume(const std::string& path, const UgridMesh& mesh,
                                std::vector<UgridVariable> variables, double resume_time) {
  check_variables(variables);
  check_mesh(mesh);
  if (!std::filesystem::exists(path))
    throw_input_error(
        "cannot continue '{}': the file is missing; run afresh (--overwrite) or "
        "restore the file",
        path);
  std::size_t kept = 0, records = 0;
  std::string title;
  {
    File old;
    if (const int status = nc_open(path.c_str(), NC_NOWRITE, &old.id); status != NC_NOERR)
      throw_input_error("cannot continue '{}': it is not a NetCDF file ({})", path,
                        nc_strerror(status));
    std::string why;
    try {
      why = difference(old.id, path, mesh, variables);
    } catch (const InputError& e) {  // a NetCDF file, but none of this writer's
      why = fmt::format("it is not a result file of flotsam ({})", e.what());
    }
    if (!why.empty())
      throw_input_error(
          "cannot continue '{}': {}; the file belongs to another case or was edited; run afresh "
          "(--overwrite) or restore the file",
          path, why);
    records = dimension_length(old.id, path, "time");
    // A billionth of margin, for a time that went through decimal text.
    const double cut = resume_time + 1e-9 * std::max(1.0, std::abs(resume_time));  // [s]
    const auto times = read_all<double>(old.id, path, "time", records);
    while (kept < records && times[kept] <= cut) ++kept;
    title = text_attribute(old.id, NC_GLOBAL, "title");
    if (kept < records) {  // the same definitions, then the kept records and the static fields
      UgridWriter part(path + ".part", mesh, variables, title);
      part.copy_records(old.id, kept);
    }
  }
  if (kept < records) {
    std::error_code error;
    std::filesystem::rename(path + ".part", path, error);
    if (error)
      throw_input_error("cannot replace '{}' by its rewound copy: {}", path, error.message());
  }
  UgridWriter writer;
  writer.path_ = path;
  writer.node_count_ = mesh.nodes.size();
  writer.face_count_ = mesh.faces.size();
  writer.variables_ = std::move(variables);
  check(nc_open(path.c_str(), NC_WRITE, &writer.file_.id), path, "opening for writing");
  writer.open_for_append();
  return writer;
}

void UgridWriter::copy_records(int old, std::size_t kept) {
  std::vector<double> values;
  for (std::size_t k = 0; k < variables_.size(); ++k) {
    const UgridVariable& v = variables_[k];
    const std::size_t n = size_of(v.location);
    values.resize(n);
    const int from = variable_id(old, path_, v.name);
    for (std::size_t r = 0; r < (v.timed ? kept : 1); ++r) {
      const std::size_t start[2] = {r, 0}, count[2] = {1, n};
      const std::size_t* s = v.timed ? start : start + 1;
      const std::size_t* c = v.timed ? count : count + 1;
      check(nc_get_vara_double(old, from, s, c, values.data()), path_,
            fmt::format("reading variable '{}'", v.name));
      check(nc_put_vara_double(file_.id, varids_[k], s, c, values.data()), path_,
            fmt::format("writing variable '{}'", v.name));
    }
  }
  values.resize(kept);
  if (kept > 0) {
    const std::size_t start = 0;
    check(nc_get_vara_double(old, variable_id(old, path_, "time"), &start, &kept, values.data()),
          path_, "reading variable 'time'");
    check(nc_put_vara_double(file_.id, time_varid_, &start, &kept, values.data()), path_,
          "writing variable 'time'");
  }
  records_ = kept;
  sync();
}

void UgridWriter::open_for_append() {
  const int id = file_.id;
  varids_.clear();
  for (const UgridVariable& v : variables_) varids_.push_back(variable_id(id, path_, v.name));
  time_varid_ = variable_id(id, path_, "time");
  records_ = dimension_length(id, path_, "time");
  if (records_ > 0) {
    const std::size_t last = records_ - 1;
    check(nc_get_var1_double(id, time_varid_, &last, &last_time_), path_, "reading 'time'");
  }
  int previous_mode;
  check(nc_set_fill(id, NC_NOFILL, &previous_mode), path_, "setting the fill mode");
}

UgridWriter::File::~File() {
  if (id >= 0) nc_close(id);
}

UgridWriter::File& UgridWriter::File::operator=(File&& other) noexcept {
  if (this != &other) {
    if (id >= 0) nc_close(id);
    id = std::exchange(other.id, -1);
  }
  return *this;
}

std::size_t UgridWriter::size_of(UgridLocation location) const {
  return location == UgridLocation::node ? node_count_ : face_count_;
}

std::size_t UgridWriter::index_of(const std::string& name, bool timed) const {
  for (std::size_t k = 0; k < variables_.size(); ++k)
    if (variables_[k].name == name) {
      if (variables_[k].timed != timed) break;
      return k;
    }
  throw std::invalid_argument(fmt::format("UgridWriter '{}': '{}' is not a {} variable", path_,
                                          name, timed ? "timed" : "static"));
}

void UgridWriter::write_values(std::size_t k, std::size_t record,
                               const std::vector<double>& values) {
  const UgridVariable& v = variables_[k];
  buffer_.resize(values.size());
  std::transform(values.begin(), values.end(), buffer_.begin(),
                 [](double value) { return std::isnan(value) ? fill_value : value; });
  const std::size_t start[2] = {record, 0}, count[2] = {1, values.size()};
  check(nc_put_vara_double(file_.id, varids_[k], v.timed ? start : start + 1,
                           v.timed ? count : count + 1, buffer_.data()),
        path_, fmt::format("writing variable '{}'", v.name));
}

void UgridWriter::append(double t,
                         const std::map<std::string, const std::vector<double>*>& values) {
  if (!std::isfinite(t) || (records_ > 0 && !(t > last_time_)))
    throw std::invalid_argument(
        fmt::format("UgridWriter '{}': time {} s does not come after the last record's {} s", path_,
                    t, last_time_));
  for (const auto& [name, field] : values) index_of(name, true);  // no unknown name
  std::vector<std::pair<std::size_t, const std::vector<double>*>> fields;
  for (std::size_t k = 0; k < variables_.size(); ++k) {
    const UgridVariable& v = variables_[k];
    if (!v.timed) continue;
    const auto found = values.find(v.name);
    if (found == values.end() || found->second == nullptr)
      throw std::invalid_argument(
          fmt::format("UgridWriter '{}': no values for '{}' at t = {} s", path_, v.name, t));
    if (found->second->size() != size_of(v.location))
      throw std::invalid_argument(fmt::format("UgridWriter '{}': '{}' has {} values for {} {}s",
                                              path_, v.name, found->second->size(),
                                              size_of(v.location), location_name(v.location)));
    fields.emplace_back(k, found->second);
  }
  // A classic file's header gets its new record count at nc_sync: a reader sees the record
  // only once it is whole, fields and time.
  for (const auto& [k, field] : fields) write_values(k, records_, *field);
  check(nc_put_var1_double(file_.id, time_varid_, &records_, &t), path_, "writing 'time'");
  ++records_;
  last_time_ = t;
  sync();
}

void UgridWriter::set_static(const std::string& name, const std::vector<double>& values) {
  const std::size_t k = index_of(name, false);
  if (values.size() != size_of(variables_[k].location))
    throw std::invalid_argument(
        fmt::format("UgridWriter '{}': '{}' has {} values for {} {}s", path_, name, values.size(),
                    size_of(variables_[k].location), location_name(variables_[k].location)));
  write_values(k, 0, values);
  sync();
}

void UgridWriter::sync() const {
  check(nc_sync(file_.id), path_, "syncing to disk");
}

}  // namespace flotsam
