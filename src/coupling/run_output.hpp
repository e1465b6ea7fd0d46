#pragma once
// What a run writes (docs/output-format.md): into <output.directory>/<name>/
//   <name>.pvd + flow_NNNNNN.vtu          flow fields every output interval
//   <name>_bodies.pvd + bodies_NNNNNN.vtp bodies (when the case has any)
//   boundary.vtp                          the boundary with its groups, once
//   <name>_bodies.csv                     every body at every output time (trajectories)
//   <name>_balance.csv                    water volume balance at every output time, with the
//                                         rain and infiltration (a case with rain), the
//                                         sources' volume (a case with sources) and the
//                                         volume out through each open boundary group
//   <name>_jams.csv                       jam statistics at every output time (spec 6.3)
//   run.bin + state_NNNNNN.bin            the mesh once, the state at every output, for
//                                         `flotsam render` (io/run_state.hpp)
//   <name>_max_depth.tif, ...             the flood envelopes as GeoTIFF rasters, rewritten at
//                                         every output (output.rasters)
//   <name>_crs.wkt                        the coordinate system of every coordinate written,
//                                         when the case has one
//   <name>.nc                             the flow every output and its envelopes, UGRID NetCDF
//                                         for QGIS and xarray (output.formats: ugrid)
//   <name>_debris.gpkg                    the bodies' tracks and the jams, GeoPackage layers
//                                         (output.formats: gpkg, a case with bodies)
// The .vtu/.vtp/.pvd files are written with output.formats: vtk.
#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "bodies/body_set.hpp"
#include "coupling/jam_statistics.hpp"
#include "flow/flow_engine.hpp"
#include "geo/debris_layers.hpp"
#include "io/csv_writer.hpp"
#include "io/output_directory.hpp"
#include "io/pvd_writer.hpp"
#include "io/ugrid_writer.hpp"

namespace flotsam {

/// What the case adds to a run's files: the open boundary groups (pictures draw them open; the
/// balance table has a column of the outflow through each), whether it rains (the balance
/// table's rain and infiltration columns) and whether it has sources.
struct RunLayout {
  std::vector<std::uint8_t> open_group;  // per mesh group: 1 inflow/outflow, 0 wall
  bool rain = false;
  bool sources = false;
  std::vector<std::array<Vec2, 4>> decks;  // [m] bridge decks' footprints, for the pictures
  OutputFormats formats{};
  std::string crs_wkt;         // the case's coordinate system, or ""
  CalendarTime time_origin{};  // the calendar time of t = 0
};

class RunOutput {
 public:
  /// Prepares the folder (io/output_directory.hpp policy) and writes boundary.vtp and run.bin.
  /// `shared_folder` (or ""): the runs replaying one shared flow (coupling/shared_flow.hpp) have
  /// the same mesh and write the same boundary.vtp, and the same flow_NNNNNN.vtu at the same
  /// time: each is written once into that folder (the fields named by their time) and linked
  /// into the folder of every run after (io/shared_file.hpp). `indexes`: when the .pvd indexes
  /// are written (PvdWriter::Start): after each output from the first, or once by close().
  RunOutput(const std::filesystem::path& directory, const std::string& name, const Mesh& mesh,
            const RunLayout& layout, bool overwrite, const std::string& case_file,
            const std::vector<ProtectedInput>& inputs,
            const std::filesystem::path& shared_folder = {},
            PvdWriter::Start indexes = PvdWriter::Start::at_first_add);

  /// Continues the output of a run in `directory` (a restart from the checkpoint at
  /// `resume_time` [s]): the indexes list again the `times` already written, the tables are
  /// rewound to resume_time (CsvResume) and get their rows appended, and the next output is
  /// number times.size().
  RunOutput(const std::filesystem::path& directory, const std::string& name, const Mesh& mesh,
            const RunLayout& layout, const std::vector<double>& times, bool with_bodies,
            double resume_time);

  /// Writes the next output, at the run's time t [s] (in frozen mode the flow's own clock
  /// stays at its steady state's).
  /// `jammed`: one flag per body (bodies in a jam, spec 6.3), or empty.
  void write(double t, const FlowEngine& flow, const BodySet& bodies, bool with_bodies,
             const std::vector<std::uint8_t>& jammed);

  /// The run has ended: indexes written only when closed are written now (an output after it is
  /// an error).
  void close();

  /// From now on every output also writes the flood envelopes as rasters on `grid`.
  void write_rasters_on(const RasterGrid& grid) { raster_grid_ = grid; }
  /// Writes <name>_crs.wkt, the coordinate system (WKT) of every coordinate the run writes.
  void write_coordinate_system(const std::string& wkt) const;

  /// One row of jam statistics (with the backwater rise per bridge when `with_backwater`), and
  /// with output.formats: gpkg the bodies and the jams as features of the debris layers.
  void write_jams(double t, const JamStatistics& stats, const JamGeometry& geometry,
                  const std::vector<double>& rise, bool with_backwater, const BodySet& bodies);

  const std::filesystem::path& directory() const { return directory_; }
  int count() const { return static_cast<int>(times_.size()); }
  const std::vector<double>& times() const { return times_; }  // [s] of each output so far

 private:
  void write_bodies(const BodySet& bodies, double t);
  void write_ugrid(double t, const FlowEngine& flow);
  void write_debris_layers(double t, const JamStatistics& stats, const JamGeometry& geometry,
                           const BodySet& bodies);
  std::vector<std::string> open_group_names(const Mesh& mesh) const;
  std::vector<std::string> balance_columns(const Mesh& mesh) const;

  std::filesystem::path directory_;
  std::string name_;
  std::vector<std::uint8_t> open_group_;  // per mesh group: 1 inflow/outflow, 0 wall
  bool rain_ = false;                     // the balance table has rain and infiltration columns
  bool sources_ = false;                  // and a sources column
  PvdWriter flow_index_, body_index_;     // from the first file on, or when closed
  std::vector<double> times_;             // [s] of each output written, in order
  std::optional<RasterGrid> raster_grid_;
  std::filesystem::path shared_folder_;  // or ""
  std::optional<CsvResume> resume_;      // tables continue files of an earlier run (restart)
  std::unique_ptr<CsvWriter> trajectories_, balance_;
  std::unique_ptr<JamStatisticsWriter> jams_;
  OutputFormats formats_;
  std::string crs_wkt_;
  CalendarTime time_origin_;
  std::optional<UgridWriter> ugrid_;    // from the first output on
  std::optional<DebrisLayers> debris_;  // from the first output with bodies on
};

}  // namespace flotsam
