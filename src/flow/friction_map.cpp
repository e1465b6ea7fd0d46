#include "flow/friction_map.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.hpp"
#include "mesh/simple_polygon.hpp"

namespace flotsam {

namespace {

// The points binned in a uniform grid of about one point per bin, so that a zone tests only the
// points in the bins its bounding box overlaps, not every point of the mesh:
//   bin of p = (floor((x - x_min) / size), floor((y - y_min) / size)),
//   size = sqrt(area of the points' box / number of points).
class PointBins {
 public:
  explicit PointBins(std::span<const Vec2> points) : points_(points) {
    if (points.empty()) return;
    box_ = bounding_box(points);
    const Vec2 extent = box_.max - box_.min;
    size_ = std::sqrt(std::max(extent.x() * extent.y(), 1e-300) / points.size());
    size_ = std::max({size_, extent.x() / 4096.0, extent.y() / 4096.0, 1e-9});  // [m]
    columns_ = static_cast<int>(extent.x() / size_) + 1;
    rows_ = static_cast<int>(extent.y() / size_) + 1;
    first_.assign(static_cast<std::size_t>(columns_) * rows_ + 1, 0);
    for (const Vec2& p : points) ++first_[bin(p) + 1];
    for (std::size_t b = 1; b < first_.size(); ++b) first_[b] += first_[b - 1];
    index_.resize(points.size());
    std::vector<int> next(first_.begin(), first_.end() - 1);
    for (int k = 0; k < static_cast<int>(points.size()); ++k) index_[next[bin(points[k])]++] = k;
  }

  /// Calls visit(k) for each point k in the bins that overlap the box [lo, hi].
  template <class Visit>
  void for_each_near(const BoundingBox& box, Visit&& visit) const {
    if (points_.empty()) return;
    const int c0 = column(box.min.x()), c1 = column(box.max.x());
    const int r0 = row(box.min.y()), r1 = row(box.max.y());
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c) {
        const std::size_t b = static_cast<std::size_t>(r) * columns_ + c;
        for (int j = first_[b]; j < first_[b + 1]; ++j) visit(index_[j]);
      }
  }

 private:
  int column(double x) const {
    return std::clamp(static_cast<int>(std::floor((x - box_.min.x()) / size_)), 0, columns_ - 1);
  }
  int row(double y) const {
    return std::clamp(static_cast<int>(std::floor((y - box_.min.y()) / size_)), 0, rows_ - 1);
  }
  std::size_t bin(const Vec2& p) const {
    return static_cast<std::size_t>(row(p.y())) * columns_ + column(p.x());
  }

  std::span<const Vec2> points_;
  BoundingBox box_;
  double size_ = 1.0;  // [m] side of a bin
  int columns_ = 1, rows_ = 1;
  std::vector<int> first_;  // per bin: its first entry in index_ (one past the end last)
  std::vector<int> index_;  // the points, bin by bin
};

// Step 2: the raster's pixel under each point where it has one; its value must be > 0.
int apply_raster(const FrictionMapConfig& map, std::span<const Vec2> points,
                 const std::function<std::string(int)>& name_of, std::vector<double>& k) {
  const Raster& raster = *map.raster;
  int count = 0;
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    const auto value = raster.nearest(points[i]);
    if (!value) continue;  // outside the raster or nodata: the default
    if (!(*value > 0.0) || !std::isfinite(*value)) {
      const auto [c, r] = *raster.pixel_of(points[i]);
      throw_input_error(
          "{}: the raster '{}' holds {} under {} at ({:.3f}, {:.3f}) m (column {}, row {}); a "
          "friction coefficient must be > 0 (nodata, for the default, is allowed)",
          map.raster_origin, raster.path(), *value, name_of(i), points[i].x(), points[i].y(), c, r);
    }
    k[i] = *value;
    ++count;
  }
  if (count == 0 && !points.empty()) {
    const BoundingBox mesh = bounding_box(points);
    const RasterGrid& g = raster.grid();
    const Vec2 a = g.centre(0, 0), b = g.centre(g.columns - 1, g.rows - 1);
    throw_input_error(
        "{}: the raster '{}' has a value under none of the {} points where friction is taken "
        "(pixel centres from ({:.3f}, {:.3f}) to ({:.3f}, {:.3f}) m; the points from ({:.3f}, "
        "{:.3f}) to ({:.3f}, {:.3f}) m): is it in the case's coordinate system?",
        map.raster_origin, raster.path(), points.size(), a.x(), a.y(), b.x(), b.y(), mesh.min.x(),
        mesh.min.y(), mesh.max.x(), mesh.max.y());
  }
  return count;
}

}  // namespace

bool zone_contains(const FrictionZone& zone, const Vec2& p) {
  if (!polygon_contains(zone.ring, p)) return false;
  return std::none_of(zone.holes.begin(), zone.holes.end(),
                      [&](const std::vector<Vec2>& hole) { return polygon_contains(hole, p); });
}

FrictionCoefficients friction_coefficients(const FlowConfig& flow, std::span<const Vec2> points,
                                           const std::function<std::string(int)>& name_of) {
  const FrictionMapConfig& map = flow.friction_map;
  FrictionCoefficients out;
  out.coefficient.assign(points.size(), flow.friction_coefficient);  // step 1
  if (map.raster) out.from_raster = apply_raster(map, points, name_of, out.coefficient);
  out.in_zone.assign(map.zones.size(), 0);
  if (map.zones.empty()) return out;
  const PointBins bins(points);
  for (std::size_t z = 0; z < map.zones.size(); ++z) {  // step 3, in order: the last one wins
    const FrictionZone& zone = map.zones[z];
    bins.for_each_near(bounding_box(zone.ring), [&](int i) {
      if (!zone_contains(zone, points[i])) return;
      out.coefficient[i] = zone.coefficient;
      ++out.in_zone[z];
    });
  }
  return out;
}

std::string friction_field_name(FrictionLaw law) {
  switch (law) {
    case FrictionLaw::none:
      return "";
    case FrictionLaw::manning:
      return "n [s m^-1/3]";
    case FrictionLaw::chezy:
      return "C [m^1/2 s^-1]";
    case FrictionLaw::strickler:
      return "K [m^1/3 s^-1]";
  }
  return "";
}

void log_friction_map(const FrictionMapConfig& map, const FrictionCoefficients& k,
                      std::string_view what) {
  if (map.raster)
    spdlog::info("friction: {} of {} {} take their coefficient from the raster '{}'", k.from_raster,
                 k.coefficient.size(), what, map.raster->path());
  if (map.zones.empty()) return;
  std::size_t empty = 0;
  for (std::size_t z = 0; z < map.zones.size(); ++z) {
    if (k.in_zone[z] > 0) continue;
    if (++empty <= 5)
      spdlog::warn("friction: {} holds the centre of none of the {} (smaller than the mesh?)",
                   map.zones[z].origin, what);
  }
  if (empty > 5) spdlog::warn("friction: {} more zones hold none", empty - 5);
  spdlog::info("friction: {} of {} zones hold {} {} (a point in two zones counted twice)",
               map.zones.size() - empty, map.zones.size(),
               std::accumulate(k.in_zone.begin(), k.in_zone.end(), 0L), what);
}

}  // namespace flotsam
