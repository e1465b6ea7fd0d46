#include "flow/flood_envelope.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>

#include "core/error.hpp"
#include "core/parallel_for.hpp"
#include "flow/hazard.hpp"
#include "io/binary_archive.hpp"

namespace flotsam {

void FloodEnvelope::reset(int n, double wet_depth_threshold) {
  wet_depth = wet_depth_threshold;
  const auto cells = static_cast<std::size_t>(n);
  for (std::vector<double>* a : per_cell_arrays()) a->assign(cells, 0.0);
  arrival.assign(cells, std::numeric_limits<double>::quiet_NaN());  // never wet yet
}

void FloodEnvelope::update(const std::vector<double>& h, const std::vector<double>& hu,
                           const std::vector<double>& hv, double t, double dt,
                           std::span<const int> cells) {
  const auto cell = [&](int i) {
    const double q = std::sqrt(hu[i] * hu[i] + hv[i] * hv[i]);  // H |u| [m^2/s]
    max_depth[i] = std::max(max_depth[i], h[i]);
    max_unit_discharge[i] = std::max(max_unit_discharge[i], q);
    const bool wet = h[i] > wet_depth;
    const double speed = wet ? q / h[i] : 0.0;  // [m/s]
    step_rating[i] = std::max(step_rating[i], hazard_rating(h[i], speed, 0.0));
    step_rating_with_debris[i] =
        std::max(step_rating_with_debris[i], hazard_rating(h[i], speed, debris_factor(h[i], true)));
    if (wet) {  // wet from the end of the step that wetted it
      max_speed[i] = std::max(max_speed[i], speed);
      australian_class[i] =
          std::max(australian_class[i], 1.0 * australian_hazard_class(h[i], speed));
      vehicle_class[i] = std::max(vehicle_class[i], 1.0 * unstable_vehicle_class(h[i], speed));
      if (std::isnan(arrival[i]))
        arrival[i] = t;
      else
        wet_duration[i] += dt;
    }
  };
  if (cells.empty()) return parallel_for(size(), 20000, cell);
  parallel_for(static_cast<std::ptrdiff_t>(cells.size()), std::ptrdiff_t{20000},
               [&](std::ptrdiff_t k) { cell(cells[k]); });
}

void FloodEnvelope::start_step() {
  std::fill(step_rating.begin(), step_rating.end(), 0.0);
  std::fill(step_rating_with_debris.begin(), step_rating_with_debris.end(), 0.0);
}

void FloodEnvelope::end_step(const std::vector<std::uint8_t>& debris) {
  for (int i = 0; i < size(); ++i) {
    const bool body = !debris.empty() && debris[i] != 0;
    max_hazard_rating[i] =
        std::max(max_hazard_rating[i], body ? step_rating_with_debris[i] : step_rating[i]);
  }
}

std::vector<double> FloodEnvelope::hazard_rating_class() const {
  std::vector<double> rating(max_hazard_rating.size(), 0.0);
  for (std::size_t i = 0; i < rating.size(); ++i)
    if (!std::isnan(arrival[i])) rating[i] = flotsam::hazard_rating_class(max_hazard_rating[i]);
  return rating;
}

void FloodEnvelope::save(ArchiveWriter& w, const std::string& prefix) const {
  w.write(prefix + ".envelope.max_depth", max_depth);
  w.write(prefix + ".envelope.max_speed", max_speed);
  w.write(prefix + ".envelope.max_unit_discharge", max_unit_discharge);
  w.write(prefix + ".envelope.arrival", arrival);
  w.write(prefix + ".envelope.wet_duration", wet_duration);
  w.write(prefix + ".envelope.max_hazard_rating", max_hazard_rating);
  w.write(prefix + ".envelope.step_rating", step_rating);
  w.write(prefix + ".envelope.step_rating_with_debris", step_rating_with_debris);
  w.write(prefix + ".envelope.australian_class", australian_class);
  w.write(prefix + ".envelope.vehicle_class", vehicle_class);
}

void FloodEnvelope::restore(ArchiveReader& r, const std::string& prefix, bool with_rating) {
  const int n = size();
  std::vector<double> shared_rating;  // a shared flow's, not this run's: read past
  for (auto [name, values] :
       {std::pair{"max_depth", &max_depth}, std::pair{"max_speed", &max_speed},
        std::pair{"max_unit_discharge", &max_unit_discharge}, std::pair{"arrival", &arrival},
        std::pair{"wet_duration", &wet_duration},
        std::pair{"max_hazard_rating", with_rating ? &max_hazard_rating : &shared_rating},
        std::pair{"step_rating", &step_rating},
        std::pair{"step_rating_with_debris", &step_rating_with_debris},
        std::pair{"australian_class", &australian_class},
        std::pair{"vehicle_class", &vehicle_class}}) {
    std::vector<double> read = r.read<double>(prefix + ".envelope." + name);
    if (static_cast<int>(read.size()) != n)
      throw_input_error("{}: the checkpoint's envelope '{}' has {} cells, the case's mesh {}",
                        r.path(), name, read.size(), n);
    *values = std::move(read);
  }
}

std::vector<int> pixel_cells(const RasterGrid& grid, const CellLocator& cell_at) {
  std::vector<int> cell(static_cast<std::size_t>(grid.columns) * grid.rows);
  int hint = -1;
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.columns; ++c)
      cell[static_cast<std::size_t>(r) * grid.columns + c] = cell_at(grid.centre(c, r), hint);
  return cell;
}

std::vector<std::string> write_envelope_rasters(const FloodEnvelope& envelope,
                                                const RasterGrid& grid,
                                                const std::vector<int>& cells,
                                                const std::string& prefix) {
  std::vector<std::string> written;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> rating_class = envelope.hazard_rating_class();
  struct Layer {
    const char* name;
    const std::vector<double>* values;
    bool wet_only;  // nodata where the cell was never wet
  };
  for (const Layer& layer : {Layer{"max_depth", &envelope.max_depth, false},
                             Layer{"max_speed", &envelope.max_speed, false},
                             Layer{"max_unit_discharge", &envelope.max_unit_discharge, false},
                             Layer{"arrival_time", &envelope.arrival, true},
                             Layer{"wet_duration", &envelope.wet_duration, false},
                             Layer{"hazard_rating", &envelope.max_hazard_rating, false},
                             Layer{"hazard_rating_class", &rating_class, true},
                             Layer{"australian_hazard_class", &envelope.australian_class, true},
                             Layer{"vehicle_class", &envelope.vehicle_class, true}}) {
    std::vector<double> pixels(cells.size());
    for (std::size_t k = 0; k < cells.size(); ++k) {
      const int i = cells[k];
      pixels[k] =
          i < 0 || (layer.wet_only && std::isnan(envelope.arrival[i])) ? nan : (*layer.values)[i];
    }
    written.push_back(prefix + "_" + layer.name + ".tif");
    write_geotiff(written.back(), grid, pixels);
  }
  return written;
}

}  // namespace flotsam
