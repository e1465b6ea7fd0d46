#pragma once
// Flow results on the mesh as one NetCDF file in the UGRID-1.0 and CF-1.8 conventions, the
// layout QGIS 3.22 (MDAL 0.9.4) opens as a time-aware mesh layer and xarray/xugrid read
// (../shared/notes/qgis-ugrid-hazard.md, "The file MDAL 0.9.4 loads" and its pitfalls table):
//
//   dimensions  node, face, max_face_nodes = 3, time = UNLIMITED
//   int mesh            cf_role "mesh_topology", topology_dimension 2, node_coordinates,
//                       face_node_connectivity, face_dimension, face_coordinates
//   double node_x/node_y(node), face_x/face_y(face)            [m], centroids for the faces
//   int face_nodes(face, max_face_nodes)                        start_index 0, counter-clockwise
//   double node_z(node)                                         bed elevation [m], standard_name
//                                                               altitude (when given)
//   int crs             epsg, EPSG_code, crs_wkt, wkt          (when a CRS is given)
//   double time(time)   "seconds since YYYY-MM-DD hh:mm:ss", calendar "standard"
//   double <name>(time, node|face)  the timed variables, one record per output
//   double <name>(node|face)        the static ones (envelopes), overwritten in place
//
// Every string attribute is NC_CHAR (MDAL rejects NC_STRING); data carry a _FillValue, which a
// NaN becomes (QGIS then shows the cell as empty: dry, never reached).
//
// Format: netCDF classic with 64-bit offsets (CDF-2, NC_64BIT_OFFSET). A classic file is one
// header and plain arrays; after nc_sync another process that opens it (QGIS, xarray, ncdump)
// sees every record written so far, while the run goes on. netCDF-4 (HDF5) keeps its metadata
// in B-trees that a reader can find half-updated while the writer is between two flushes, and
// needs HDF5's SWMR mode, which netCDF-C does not offer. CDF-2 also stays readable by every
// netCDF library since 3.6 (CDF-5 needs 4.4 and is refused by some readers, e.g. scipy's).
// Its limit, 4 GiB per record of one variable or per static variable, is 500 million cells.
//
// Errors of the netCDF library (disk full, a file that is not NetCDF) are InputErrors naming the
// file and the variable, as the CSV writer's are.
#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/calendar_time.hpp"
#include "core/vec.hpp"
#include "io/ugrid_variable.hpp"

namespace flotsam {

/// The mesh the variables live on: linear triangles.
struct UgridMesh {
  std::vector<Vec2> nodes;                // [m]
  std::vector<std::array<int, 3>> faces;  // node indices, counter-clockwise, 0-based
  std::vector<double> node_z;             // [m] bed elevation per node, or empty: none written
  std::string crs_wkt;                    // the coordinate system as WKT, or "": none written
  CalendarTime time_origin{};             // the calendar time (UTC) of the run's t = 0
};

class UgridWriter {
 public:
  /// Creates `path` (replacing it) with the mesh and every variable defined; global attributes
  /// title, source ("flotsam <version>"), history, Conventions "CF-1.8 UGRID-1.0". No wall-clock
  /// time goes in, so two runs of a case write the same contents. std::invalid_argument for a
  /// programming error (a mesh without nodes or faces, node_z of the wrong size, two variables
  /// of one name or long name, a reserved name, a vector component without its pair or static),
  /// InputError for a file that cannot be written.
  UgridWriter(const std::string& path, const UgridMesh& mesh, std::vector<UgridVariable> variables,
              const std::string& title);

  /// A restarted run (docs/output-format.md "Restarting a run", as CsvResume): reopens `path`, a
  /// file this class wrote for the same mesh and variables, keeps its records whose time is at
  /// most `resume_time` [s] (to a billionth), drops later ones (written after the checkpoint by
  /// the run that stopped; the file is rewritten through "<path>.part", since NetCDF cannot
  /// shrink the unlimited dimension) and appends after them: the file then holds what an
  /// unstopped run's would (the bytes after the last record may differ). InputError naming the file
  /// and what differs when it is missing, not NetCDF, or holds another mesh (counts, coordinates,
  /// faces), another time origin, or other variables.
  static UgridWriter resume(const std::string& path, const UgridMesh& mesh,
                            std::vector<UgridVariable> variables, double resume_time);

  ~UgridWriter() = default;
  UgridWriter(const UgridWriter&) = delete;
  UgridWriter& operator=(const UgridWriter&) = delete;
  UgridWriter(UgridWriter&&) noexcept = default;
  UgridWriter& operator=(UgridWriter&&) noexcept = default;

  /// One output at time t [s]: the values of every timed variable by name, each sized as the
  /// nodes or the faces (its location); a NaN is written as the fill value. The file is synced,
  /// so that a reader opening it sees this record whole. std::invalid_argument (a programming
  /// error) for a missing or unknown name, a wrong size, or t not after the last record's time.
  void append(double t, const std::map<std::string, const std::vector<double>*>& values);

  /// Overwrites the static variable `name` (sized as its location; NaN -> fill value), synced.
  /// std::invalid_argument for a name that is not a static variable or a wrong size.
  void set_static(const std::string& name, const std::vector<double>& values);

  const std::string& path() const { return path_; }
  std::size_t record_count() const { return records_; }

 private:
  /// The netCDF id of the open file, closed with it; -1: none (moved from).
  struct File {
    int id = -1;
    File() = default;
    File(File&& other) noexcept : id(std::exchange(other.id, -1)) {}
    File& operator=(File&& other) noexcept;
    ~File();
  };

  UgridWriter() = default;
  void define(const UgridMesh& mesh, const std::string& origin, const std::string& title);
  void write_mesh(const UgridMesh& mesh);
  void copy_records(int old, std::size_t kept);  // of the file `old`, and its static fields
  void open_for_append();  // the variables' ids, the records and the last time of an open file
  std::size_t index_of(const std::string& name, bool timed) const;  // or std::invalid_argument
  void write_values(std::size_t k, std::size_t record, const std::vector<double>& values);
  void sync() const;
  std::size_t size_of(UgridLocation location) const;

  std::string path_;
  File file_;
  std::size_t node_count_ = 0;
  std::size_t face_count_ = 0;
  std::vector<UgridVariable> variables_;
  std::vector<int> varids_;  // per variable
  int time_varid_ = -1;
  std::size_t records_ = 0;  // output times written
  double last_time_ = 0.0;   // [s] the last record's, when records_ > 0
  std::vector<double> buffer_;
};

}  // namespace flotsam
