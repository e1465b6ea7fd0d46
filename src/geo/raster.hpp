#pragma once
// A georeferenced grid of values (a DEM, a roughness map, a rain field, an output envelope), read
// and written with GDAL (any raster format GDAL reads; GeoTIFF written). Band 1 only.
//
// Georeferencing is GDAL's affine geotransform: the corner of pixel (column c, row r) is
//   x = t[0] + c t[1] + r t[2],   y = t[3] + c t[4] + r t[5]            [m]
// and pixel values belong to pixel centres (c + 1/2, r + 1/2). The coordinate system is kept as
// WKT text, written back into every raster flotsam produces.
//
// Bilinear sampling (docs/model.md "Terrain"): between the four pixel centres around a point; in
// the half-pixel band along the raster's edge the nearest four centres are extended linearly, so
// a plane or a bilinear patch is reproduced exactly everywhere in the raster's extent. A point
// outside the extent, or whose four centres include a nodata pixel, has no value.
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/vec.hpp"

namespace flotsam {

struct RasterGrid {
  int columns = 0, rows = 0;
  std::array<double, 6> transform = {0.0, 1.0, 0.0, 0.0, 0.0, 1.0};  // GDAL geotransform [m]
  std::string crs_wkt;  // coordinate system (WKT); empty: none given

  /// Centre of pixel (c, r) [m].
  Vec2 centre(int c, int r) const;
  /// Fractional pixel coordinates (c, r) of a point: its pixel is (floor c, floor r).
  Vec2 pixel_coordinates(const Vec2& p) const;
  /// Fractional pixel coordinates q lie in the grid's extent (its edges included).
  bool in_extent(const Vec2& q) const;
  /// A north-up grid of square pixels of size `resolution` [m] covering [lo, hi] (corners
  /// aligned to multiples of the resolution).
  static RasterGrid covering(const Vec2& lo, const Vec2& hi, double resolution,
                             const std::string& crs_wkt);
};

class Raster {
 public:
  Raster() = default;
  Raster(RasterGrid grid, std::vector<double> values, std::optional<double> nodata);

  /// Reads band 1 of `path`; `origin` ("case.yaml:12: bed.raster") names it in messages: a
  /// missing or unreadable file, no georeferencing, a rotated grid.
  static Raster read(const std::string& path, const std::string& origin);

  const RasterGrid& grid() const { return grid_; }
  const std::string& path() const { return path_; }
  double at(int c, int r) const { return values_[static_cast<std::size_t>(r) * grid_.columns + c]; }
  bool is_nodata(double v) const;

  /// Bilinear value at p (see the header), or none outside the extent or next to nodata.
  std::optional<double> bilinear(const Vec2& p) const;
  /// The value of the pixel holding p, or none outside the extent or on nodata.
  std::optional<double> nearest(const Vec2& p) const;
  /// The pixel (column, row) holding p, or none outside the extent (on the far edges, the last
  /// pixel).
  std::optional<std::pair<int, int>> pixel_of(const Vec2& p) const;

 private:
  RasterGrid grid_;
  std::vector<double> values_;  // row-major, row 0 first (GDAL's order)
  std::optional<double> nodata_;
  std::string path_;
};

/// The WKT of a coordinate system given as "EPSG:32633", a PROJ string or WKT; an InputError
/// naming `origin` when GDAL does not know it or it is geographic (degrees, not metres).
std::string coordinate_system_wkt(const std::string& definition, const std::string& origin);

/// Two coordinate systems (WKT) are the same (GDAL's IsSame).
bool same_coordinate_system(const std::string& a, const std::string& b);

/// Writes `values` (row-major, grid.columns x grid.rows) as a single-band Float64 GeoTIFF with
/// the grid's georeferencing and coordinate system; NaN values are written as `nodata`.
void write_geotiff(const std::string& path, const RasterGrid& grid,
                   const std::vector<double>& values, double nodata = -9999.0);

}  // namespace flotsam
