#include "flow/flood_envelope.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "io/binary_archive.hpp"

namespace flotsam {

void FloodEnvelope::reset(int n, double wet_depth_threshold) {
  wet_depth = wet_depth_threshold;
  const auto cells = static_cast<std::size_t>(n);
  max_depth.assign(cells, 0.0);
  max_speed.assign(cells, 0.0);
  max_unit_discharge.assign(cells, 0.0);
  arrival.assign(cells, std::numeric_limits<double>::quiet_NaN());
  wet_duration.assign(cells, 0.0);
}

void FloodEnvelope::update(const std::vector<double>& h, const std::vector<double>& hu,
                           const std::vector<double>& hv, double t, double dt) {
  const int n = size();
#pragma omp parallel for schedule(static) if (n >= 20000)
  for (int i = 0; i < n; ++i) {
    const double q = std::sqrt(hu[i] * hu[i] + hv[i] * hv[i]);  // H |u| [m^2/s]
    max_depth[i] = std::max(max_depth[i], h[i]);
    max_unit_discharge[i] = std::max(max_unit_discharge[i], q);
    if (h[i] > wet_depth) {  // wet from the end of the step that wetted it
      max_speed[i] = std::max(max_speed[i], q / h[i]);
      if (std::isnan(arrival[i]))
        arrival[i] = t;
      else
        wet_duration[i] += dt;
    }
  }
}

void FloodEnvelope::save(ArchiveWriter& w, const std::string& prefix) const {
  w.write(prefix + ".envelope.max_depth", max_depth);
  w.write(prefix + ".envelope.max_speed", max_speed);
  w.write(prefix + ".envelope.max_unit_discharge", max_unit_discharge);
  w.write(prefix + ".envelope.arrival", arrival);
  w.write(prefix + ".envelope.wet_duration", wet_duration);
}

void FloodEnvelope::restore(ArchiveReader& r, const std::string& prefix) {
  const int n = size();
  for (auto [name, values] :
       {std::pair{"max_depth", &max_depth}, std::pair{"max_speed", &max_speed},
        std::pair{"max_unit_discharge", &max_unit_discharge}, std::pair{"arrival", &arrival},
        std::pair{"wet_duration", &wet_duration}}) {
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
  for (auto [name, values] :
       {std::pair{"max_depth", &envelope.max_depth}, std::pair{"max_speed", &envelope.max_speed},
        std::pair{"max_unit_discharge", &envelope.max_unit_discharge},
        std::pair{"arrival_time", &envelope.arrival},
        std::pair{"wet_duration", &envelope.wet_duration}}) {
    std::vector<double> pixels(cells.size());
    for (std::size_t k = 0; k < cells.size(); ++k)
      pixels[k] = cells[k] < 0 ? nan : (*values)[cells[k]];
    written.push_back(prefix + "_" + name + ".tif");
    write_geotiff(written.back(), grid, pixels);
  }
  return written;
}

}  // namespace flotsam
