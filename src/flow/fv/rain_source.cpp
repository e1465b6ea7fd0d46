#include "flow/fv/rain_source.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <utility>

#include "core/constants.hpp"
#include "core/error.hpp"

namespace flotsam {

namespace {

// The case's hyetograph [mm/h] in m/s.
TimeSeries in_metres_per_second(const TimeSeries& mm_per_hour) {
  std::vector<std::pair<double, double>> points = mm_per_hour.points();
  for (auto& point : points) point.second *= millimetres_per_hour;
  return TimeSeries(std::move(points));
}

// The weight w_i of each cell: the value of the raster's pixel under its centroid (nearest
// pixel). A cell outside the raster or over nodata is an InputError naming the cell and its
// position, as is a weight < 0: a gap in the rain data is not taken for a place without rain.
std::vector<double> weights_from_raster(const RainConfig& rain, const CellMesh& cells) {
  const Raster& raster = *rain.raster;
  std::vector<double> w(cells.cell_count);
  for (int i = 0; i < cells.cell_count; ++i) {
    const Vec2& p = cells.centroid[i];
    const auto value = raster.nearest(p);
    const auto pixel = raster.pixel_of(p);
    if (value && *value >= 0.0 && std::isfinite(*value)) {
      w[i] = *value;
      continue;
    }
    const std::string what =
        !pixel  ? std::string("it lies outside the raster's extent")
        : value ? fmt::format(
                      "its pixel (column {}, row {}) holds {}; a weight must be finite and >= 0",
                      pixel->first, pixel->second, *value)
                : fmt::format("its pixel (column {}, row {}) holds nodata", pixel->first,
                              pixel->second);
    throw_input_error(
        "{}: the rain raster '{}' gives no weight to cell {} at ({:.3f}, {:.3f}) m: {}; the "
        "raster must cover every cell with a weight >= 0 (0: no rain)",
        rain.raster_origin, raster.path(), i, p.x(), p.y(), what);
  }
  return w;
}

}  // namespace

RainSource::RainSource(const RainConfig& rain, const CellMesh& cells)
    : enabled_(rain.enabled),
      intensity_(in_metres_per_second(rain.intensity)),
      f_(rain.enabled ? rain.infiltration * millimetres_per_hour : 0.0),
      area_(cells.area) {
  set_weights(rain.enabled && rain.raster ? weights_from_raster(rain, cells)
                                          : std::vector<double>(cells.cell_count, 1.0));
}

void RainSource::set_weights(std::vector<double> weights) {
  assert(weights.size() == area_.size());
  weight_ = std::move(weights);
  weighted_area_ = 0.0;
  for (std::size_t i = 0; i < weight_.size(); ++i) {
    assert(std::isfinite(weight_[i]) && weight_[i] >= 0.0);
    weighted_area_ += area_[i] * weight_[i];
  }
}

double RainSource::depth(double t0, double t1) const {
  return enabled_ ? intensity_.integral(t0, t1) : 0.0;
}

// (M-17) infiltration: h_i -> h_i - min(h_i, f dt). A cell keeps its velocity (the water that
// soaks away takes its own momentum with it), so hu and hv scale as h; emptied, it is at rest.
double RainSource::infiltrate(std::vector<double>& h, std::vector<double>& hu,
                              std::vector<double>& hv, double dt, std::span<const int> cells,
                              const std::function<void(std::vector<double>&)>& share) {
  const double loss = f_ * dt;  // [m]
  const int n = static_cast<int>(h.size());
  infiltrated_.resize(n);
  if (cells.empty()) {
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; ++i) infiltrated_[i] = infiltrate_cell(h[i], hu[i], hv[i], loss);
  } else {
    const auto count = static_cast<std::ptrdiff_t>(cells.size());
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t k = 0; k < count; ++k) {
      const int i = cells[k];
      infiltrated_[i] = infiltrate_cell(h[i], hu[i], hv[i], loss);
    }
  }
  if (share) share(infiltrated_);
  double volume = 0.0;  // [m^3]
  for (int i = 0; i < n; ++i) volume += area_[i] * infiltrated_[i];
  return volume;
}

}  // namespace flotsam
