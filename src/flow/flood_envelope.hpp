#pragma once
// Flood envelopes (docs/model.md "Flood envelopes"): per cell, over the whole run, the largest
// depth, speed and unit discharge H |u| (the hazard guidelines' depth x velocity), the time the
// cell first became wet (arrival), how long it has been wet, and the largest flood hazard
// (hazard.hpp: the UK hazard rating with flotsam's own debris, the Australian class, the
// vehicles that lose stability). "Wet" means deeper than a threshold (output.wet_depth). Updated
// after every sub-step of the engine, so a peak between two coupling steps is not missed; kept in
// checkpoints, so a restart continues the running maxima.
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "geo/raster.hpp"

namespace flotsam {

class ArchiveWriter;
class ArchiveReader;

struct FloodEnvelope {
  double wet_depth = 0.01;                 // [m] deeper than this counts as wet
  std::vector<double> max_depth;           // [m]
  std::vector<double> max_speed;           // [m/s]
  std::vector<double> max_unit_discharge;  // H |u| [m^2/s]
  std::vector<double> arrival;             // [s] first time wet; NaN: never yet
  std::vector<double> wet_duration;        // [s] the steps that end wet, after the arrival
  std::vector<double> max_hazard_rating;   // HR = d (v + 0.5) + DF [-] (M-H1)
  // The largest HR of the sub-steps of the current coupling step, without debris (DF = 0) and
  // with (DF of (M-H2) where a body is): the flow's alone, so that a run replaying a shared
  // flow folds them with its own bodies as the run that computed it does (end_step).
  std::vector<double> step_rating, step_rating_with_debris;
  std::vector<double> australian_class;  // H1-H6 as 1-6; 0: never wet (M-H3)
  std::vector<double> vehicle_class;     // 0-3: which vehicles lose stability (M-H4)

  /// n cells, nothing seen yet.
  void reset(int n, double wet_depth_threshold);
  /// Every per-cell array (a flood split over ranks gathers each cell's from its owner).
  std::vector<std::vector<double>*> per_cell_arrays() {
    return {&max_depth,        &max_speed,         &max_unit_discharge, &arrival,
            &wet_duration,     &max_hazard_rating, &step_rating,        &step_rating_with_debris,
            &australian_class, &vehicle_class};
  }
  int size() const { return static_cast<int>(max_depth.size()); }

  /// Takes in the state at time t [s], the end of a sub-step of length dt [s]: depth h [m] and
  /// discharge (hu, hv) [m^2/s] per cell; speeds only where wet (h > wet_depth): a film's
  /// velocity is the numerics' (docs/model.md (M-15)), not a hazard.
  /// `cells`: only these (a flood split over ranks: a rank's own); empty: every cell.
  void update(const std::vector<double>& h, const std::vector<double>& hu,
              const std::vector<double>& hv, double t, double dt, std::span<const int> cells = {});

  /// A coupling step begins: its sub-steps' largest ratings start afresh.
  void start_step();
  /// It ends: each cell's largest rating takes the step's, with the debris factor where
  /// `debris` (per cell, 1 where a body lay during the step; empty: nowhere) says a body was.
  void end_step(const std::vector<std::uint8_t>& debris);

  /// FD2321's class (1-4) of each cell's largest hazard rating; 0 where never wet.
  std::vector<double> hazard_rating_class() const;

  /// The envelopes as records `prefix`.envelope.* of a checkpoint; read back checked against n
  /// cells (an InputError naming the checkpoint otherwise). `with_rating` false (a step of a
  /// shared flow): the running largest HR stays this run's, with this run's debris.
  void save(ArchiveWriter& w, const std::string& prefix) const;
  void restore(ArchiveReader& r, const std::string& prefix, bool with_rating = true);
};

/// The cell holding a point (-1 outside the domain), walking from `hint`, which it updates.
using CellLocator = std::function<int(const Vec2& p, int& hint)>;

/// The cell under each pixel centre of `grid` (row-major; -1 outside the domain).
std::vector<int> pixel_cells(const RasterGrid& grid, const CellLocator& cell_at);

/// Writes the envelopes on `grid` as GeoTIFFs `prefix`_max_depth.tif, _max_speed.tif,
/// _max_unit_discharge.tif, _arrival_time.tif, _wet_duration.tif, _hazard_rating.tif,
/// _hazard_rating_class.tif, _australian_hazard_class.tif, _vehicle_class.tif: each pixel the
/// value of its cell (`cells`, from pixel_cells); nodata outside the domain, and where the cell
/// was never wet for the arrival time and the classes. Returns the files written.
std::vector<std::string> write_envelope_rasters(const FloodEnvelope& envelope,
                                                const RasterGrid& grid,
                                                const std::vector<int>& cells,
                                                const std::string& prefix);

}  // namespace flotsam
