#pragma once
// The floating debris of a run as GIS layers: one GeoPackage, `<name>_debris.gpkg`, in the case's
// coordinate system, that QGIS opens as two time-aware vector layers (its temporal controller,
// "single field with date/time" on `time`) while the run goes on:
//
//   tracks  polygon: one feature per body per output time, the body's footprint rectangle
//           body (Integer64), t_s (Real, [s]), time (DateTime, UTC, milliseconds kept),
//           kind (String), length_m, width_m (Real, [m]), speed_ms (Real, [m/s]),
//           state (String: floating, grounded), fate (String: floating, deposited, trapped,
//           passed, left), jam (Integer, the jam's index or -1), bridge (String or NULL)
//   jams    polygon: one feature per jam per output time, the convex hull of its bodies'
//           footprints; jam (Integer), t_s, time, bodies (Integer), bridge (String or NULL),
//           blockage (Real, 0-1, NULL away from a bridge), thickness_m (Real, [m])
//
// Each output time is one transaction, after which the dataset is flushed: a reader sees whole
// output times only. The module takes plain structs, so that geo/ needs nothing of bodies/ or
// coupling/. GDAL's errors are InputErrors (a file that cannot be created or continued) or
// RunErrors (a write that fails), naming the file and the layer.
#include <array>
#include <chrono>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/calendar_time.hpp"
#include "core/footprint_corners.hpp"
#include "core/vec.hpp"

class GDALDataset;
class OGRLayer;

namespace flotsam {

/// One body at one output time.
struct TrackPoint {
  long body = 0;                     // the body's id
  Vec2 centre = Vec2::Zero();        // [m]
  Vec2 half_extents = Vec2::Zero();  // (L/2, l/2) [m]: half length, half width
  double angle = 0.0;                // [rad] of the length axis from x, counter-clockwise
  std::string kind;                  // "log", "car", ...
  double speed = 0.0;                // [m/s]
  std::string state;                 // "floating", "grounded"
  std::string fate;                  // "floating", "deposited", "trapped", "passed", "left"
  int jam = -1;                      // the jam holding the body at that time, or -1
  std::string bridge;                // the bridge whose jam holds it, or "": none (NULL)
};

/// One jam at one output time.
struct JamOutline {
  int jam = 0;                                  // its index
  std::vector<std::array<Vec2, 4>> footprints;  // its bodies' corners [m] (footprint_corners)
  int bodies = 0;                               // how many bodies it holds
  std::string bridge;                           // the bridge it leans on, or "": none (NULL)
  double blockage = std::numeric_limits<double>::quiet_NaN();  // [-] 0-1; NaN: none (NULL)
  double thickness = 0.0;                                      // [m]
};

class DebrisLayers {
 public:
  /// Creates `path` (replacing it) with both layers, in the coordinate system `crs_wkt` (empty:
  /// none). `time_origin` is the calendar time (UTC) of t = 0. InputError for a malformed WKT or
  /// a file that cannot be created.
  DebrisLayers(const std::string& path, const std::string& crs_wkt,
               const CalendarTime& time_origin);

  /// A restarted run (docs/output-format.md "Restarting a run", as CsvResume): opens the file
  /// this class wrote, deletes the features of both layers whose t_s is after `resume_time` [s]
  /// (to a billionth), written after the checkpoint by the run that stopped, and goes on after
  /// it. A missing file is created again (a warning says the earlier outputs are lost); a file
  /// whose layers, fields or coordinate system differ is an InputError naming it.
  static DebrisLayers resume(const std::string& path, const std::string& crs_wkt,
                             const CalendarTime& time_origin, double resume_time);

  DebrisLayers(const DebrisLayers&) = delete;
  DebrisLayers& operator=(const DebrisLayers&) = delete;
  DebrisLayers(DebrisLayers&&) noexcept = default;
  DebrisLayers& operator=(DebrisLayers&&) noexcept = default;
  ~DebrisLayers() = default;

  /// Appends the features of output time `t` [s], all in one transaction, then flushes the
  /// file. RunError naming the file and layer when GDAL fails.
  void write(double t, const std::vector<TrackPoint>& tracks, const std::vector<JamOutline>& jams);

  const std::string& path() const { return path_; }

 private:
  struct CloseDataset {
    void operator()(GDALDataset* dataset) const;
  };
  using Dataset = std::unique_ptr<GDALDataset, CloseDataset>;

  DebrisLayers(std::string path, std::chrono::sys_seconds origin, Dataset dataset);
  void write_tracks(double t, const std::vector<TrackPoint>& tracks);
  void write_jams(double t, const std::vector<JamOutline>& jams);

  std::string path_;
  std::chrono::sys_seconds origin_;  // the calendar time of t = 0 (UTC)
  Dataset dataset_;
  OGRLayer* tracks_ = nullptr;  // owned by dataset_
  OGRLayer* jams_ = nullptr;
};

}  // namespace flotsam
