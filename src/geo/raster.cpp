#include "geo/raster.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "geo/gdal_support.hpp"

namespace flotsam {

namespace {

using gdal::Dataset;
using gdal::register_drivers;
using gdal::wkt_of;

/// The first index of the two pixel centres used along one axis, and the fraction between them
/// (outside [0, 1] in the half-pixel edge bands: linear extension).
struct Axis {
  int first = 0;
  double fraction = 0.0;
};

Axis axis_at(double pixel, int count) {
  if (count == 1) return {0, 0.0};
  const double centre = pixel - 0.5;  // in units of pixel centres
  const int first = std::clamp(static_cast<int>(std::floor(centre)), 0, count - 2);
  return {first, centre - first};
}

}  // namespace

Vec2 RasterGrid::centre(int c, int r) const {
  const double x = c + 0.5, y = r + 0.5;
  return {transform[0] + x * transform[1] + y * transform[2],
          transform[3] + x * transform[4] + y * transform[5]};
}

Vec2 RasterGrid::pixel_coordinates(const Vec2& p) const {
  const double dx = p.x() - transform[0], dy = p.y() - transform[3];
  const double det = transform[1] * transform[5] - transform[2] * transform[4];
  return {(transform[5] * dx - transform[2] * dy) / det,
          (-transform[4] * dx + transform[1] * dy) / det};
}

RasterGrid RasterGrid::covering(const Vec2& lo, const Vec2& hi, double resolution,
                                const std::string& crs_wkt) {
  RasterGrid g;
  const double x0 = std::floor(lo.x() / resolution) * resolution;
  const double y1 = std::ceil(hi.y() / resolution) * resolution;
  g.columns = std::max(1, static_cast<int>(std::ceil((hi.x() - x0) / resolution - 1e-9)));
  g.rows = std::max(1, static_cast<int>(std::ceil((y1 - lo.y()) / resolution - 1e-9)));
  g.transform = {x0, resolution, 0.0, y1, 0.0, -resolution};  // north up: row 0 at the top
  g.crs_wkt = crs_wkt;
  return g;
}

Raster::Raster(RasterGrid grid, std::vector<double> values, std::optional<double> nodata)
    : grid_(std::move(grid)), values_(std::move(values)), nodata_(nodata) {}

Raster Raster::read(const std::string& path, const std::string& origin) {
  const Dataset d = gdal::open_dataset(path, GDAL_OF_RASTER, origin, "raster");
  if (d->GetRasterCount() < 1) throw_input_error("{}: '{}' has no raster band", origin, path);
  RasterGrid grid;
  grid.columns = d->GetRasterXSize();
  grid.rows = d->GetRasterYSize();
  if (d->GetGeoTransform(grid.transform.data()) != CE_None)
    throw_input_error(
        "{}: '{}' has no georeferencing (no geotransform); expected a raster in a projected "
        "coordinate system in metres",
        origin, path);
  if (grid.transform[1] * grid.transform[5] - grid.transform[2] * grid.transform[4] == 0.0)
    throw_input_error("{}: '{}' has a degenerate geotransform (pixels of zero area)", origin, path);
  const OGRSpatialReference* srs = d->GetSpatialRef();
  if (srs && !gdal::is_undefined(*srs)) {
    if (srs->IsGeographic())
      throw_input_error(
          "{}: '{}' is in geographic coordinates (degrees); expected a projected coordinate "
          "system in metres (reproject it, e.g. gdalwarp -t_srs EPSG:<utm zone>)",
          origin, path);
    grid.crs_wkt = wkt_of(*srs);
  }
  GDALRasterBand* band = d->GetRasterBand(1);
  int has_nodata = 0;
  const double nodata_value = band->GetNoDataValue(&has_nodata);
  const double bytes = 8.0 * grid.columns * grid.rows;  // the values as doubles
  if (bytes > 0.5 * usable_memory())
    throw_input_error(
        "{}: '{}' has {} x {} pixels, {} as 8-byte values: more than half the memory this "
        "process may use ({}); crop it to the domain or coarsen it (gdal_translate -projwin, -tr)",
        origin, path, grid.columns, grid.rows, format_bytes(bytes), format_bytes(usable_memory()));
  std::vector<double> values(static_cast<std::size_t>(grid.columns) * grid.rows);
  if (band->RasterIO(GF_Read, 0, 0, grid.columns, grid.rows, values.data(), grid.columns, grid.rows,
                     GDT_Float64, 0, 0) != CE_None)
    throw_input_error("{}: could not read the values of '{}' ({})", origin, path,
                      CPLGetLastErrorMsg());
  // NaN is nodata; an infinite value is never a terrain, a roughness or a weight (unless the
  // file declares it its nodata value).
  for (std::size_t k = 0; k < values.size(); ++k)
    if (std::isinf(values[k]) && !(has_nodata && values[k] == nodata_value))
      throw_input_error(
          "{}: '{}': pixel (column {}, row {}) holds {}; expected a finite value or the "
          "raster's nodata value",
          origin, path, k % static_cast<std::size_t>(grid.columns),
          k / static_cast<std::size_t>(grid.columns), values[k]);
  Raster raster(std::move(grid), std::move(values),
                has_nodata ? std::optional<double>(nodata_value) : std::nullopt);
  raster.path_ = path;
  return raster;
}

bool Raster::is_nodata(double v) const {
  if (std::isnan(v)) return true;
  return nodata_ && v == *nodata_;
}

bool RasterGrid::in_extent(const Vec2& q) const {
  return q.x() >= 0.0 && q.x() <= columns && q.y() >= 0.0 && q.y() <= rows;
}

std::optional<double> Raster::bilinear(const Vec2& p) const {
  const Vec2 q = grid_.pixel_coordinates(p);
  if (!grid_.in_extent(q)) return std::nullopt;
  const Axis a = axis_at(q.x(), grid_.columns), b = axis_at(q.y(), grid_.rows);
  const int c1 = std::min(a.first + 1, grid_.columns - 1),
            r1 = std::min(b.first + 1, grid_.rows - 1);
  const double v00 = at(a.first, b.first), v10 = at(c1, b.first);
  const double v01 = at(a.first, r1), v11 = at(c1, r1);
  for (double v : {v00, v10, v01, v11})
    if (is_nodata(v)) return std::nullopt;
  const double s = a.fraction, t = b.fraction;
  return (1 - s) * (1 - t) * v00 + s * (1 - t) * v10 + (1 - s) * t * v01 + s * t * v11;
}

std::optional<std::pair<int, int>> Raster::pixel_of(const Vec2& p) const {
  const Vec2 q = grid_.pixel_coordinates(p);
  if (!grid_.in_extent(q)) return std::nullopt;
  return std::pair{std::min(static_cast<int>(q.x()), grid_.columns - 1),
                   std::min(static_cast<int>(q.y()), grid_.rows - 1)};
}

std::optional<double> Raster::nearest(const Vec2& p) const {
  const auto pixel = pixel_of(p);
  if (!pixel) return std::nullopt;
  const double v = at(pixel->first, pixel->second);
  if (is_nodata(v)) return std::nullopt;
  return v;
}

std::string coordinate_system_wkt(const std::string& definition, const std::string& origin) {
  register_drivers();
  OGRSpatialReference srs;
  if (srs.SetFromUserInput(definition.c_str()) != OGRERR_NONE)
    throw_input_error("{}: '{}' is not a coordinate system GDAL knows (expected e.g. EPSG:32633)",
                      origin, definition);
  if (srs.IsGeographic())
    throw_input_error(
        "{}: '{}' is a geographic coordinate system (degrees); expected a projected one in "
        "metres",
        origin, definition);
  return wkt_of(srs);
}

bool same_coordinate_system(const std::string& a, const std::string& b) {
  OGRSpatialReference sa, sb;
  return sa.importFromWkt(a.c_str()) == OGRERR_NONE && sb.importFromWkt(b.c_str()) == OGRERR_NONE &&
         sa.IsSame(&sb);
}

// Written under `path`.part and renamed when whole: a run killed while writing leaves the
// previous file (or none), never a truncated one that reads as nodata.
void write_geotiff(const std::string& path, const RasterGrid& grid,
                   const std::vector<double>& values, double nodata) {
  register_drivers();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
  if (!driver) throw_run_error("GDAL has no GeoTIFF driver: cannot write '{}'", path);
  const std::string part = path + ".part";
  const auto fail = [&](const std::string& what) {
    const std::string gdal = CPLGetLastErrorMsg();
    std::error_code ignored;
    if (std::filesystem::is_regular_file(part, ignored)) std::filesystem::remove(part, ignored);
    throw_run_error("could not write '{}': {}{}", path, what,
                    gdal.empty() ? "" : fmt::format(" ({})", gdal));
  };
  char** options = nullptr;
  options = CSLSetNameValue(options, "COMPRESS", "DEFLATE");
  Dataset d(driver->Create(part.c_str(), grid.columns, grid.rows, 1, GDT_Float64, options));
  CSLDestroy(options);
  if (!d) fail(fmt::format("could not create '{}'", part));
  std::array<double, 6> transform = grid.transform;
  d->SetGeoTransform(transform.data());
  if (!grid.crs_wkt.empty()) {
    OGRSpatialReference srs;
    if (srs.importFromWkt(grid.crs_wkt.c_str()) == OGRERR_NONE) d->SetSpatialRef(&srs);
  }
  GDALRasterBand* band = d->GetRasterBand(1);
  band->SetNoDataValue(nodata);
  std::vector<double> out(values);
  for (double& v : out)
    if (std::isnan(v)) v = nodata;
  if (band->RasterIO(GF_Write, 0, 0, grid.columns, grid.rows, out.data(), grid.columns, grid.rows,
                     GDT_Float64, 0, 0) != CE_None)
    fail("the values were not written");
  CPLErrorReset();
  d.reset();  // closes the file, writing what GDAL still holds
  if (CPLGetLastErrorType() >= CE_Failure) fail("the file was not closed whole");
  std::error_code error;
  std::filesystem::rename(part, path, error);
  if (error) fail(error.message());
}

}  // namespace flotsam
