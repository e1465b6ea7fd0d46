// Rasters (geo/raster.hpp): bilinear sampling exact on planes and bilinear patches over the whole
// extent, nodata and outside, GeoTIFF round trip of values, georeferencing and coordinate system,
// and a GeoTIFF replaced whole or not at all.
#include "geo/raster.hpp"

#include <gdal_priv.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "../support/scratch_path.hpp"
#include "core/error.hpp"

namespace flotsam {
namespace {

namespace fs = std::filesystem;

std::string utm_33n() {
  OGRSpatialReference srs;
  EXPECT_EQ(srs.importFromEPSG(32633), OGRERR_NONE);
  char* wkt = nullptr;
  srs.exportToWkt(&wkt);
  std::string text = wkt;
  CPLFree(wkt);
  return text;
}

/// A north-up grid of 7 x 5 pixels of 2 m x 3 m with its corner at (500000, 4100015) m.
RasterGrid small_grid() {
  RasterGrid g;
  g.columns = 7;
  g.rows = 5;
  g.transform = {500000.0, 2.0, 0.0, 4100015.0, 0.0, -3.0};
  return g;
}

Raster sampled(const RasterGrid& g, double (*f)(const Vec2&)) {
  std::vector<double> v(static_cast<std::size_t>(g.columns) * g.rows);
  for (int r = 0; r < g.rows; ++r)
    for (int c = 0; c < g.columns; ++c)
      v[static_cast<std::size_t>(r) * g.columns + c] = f(g.centre(c, r));
  return Raster(g, v, -9999.0);
}

double plane(const Vec2& p) {
  return 3.0 + 0.02 * (p.x() - 500000.0) - 0.05 * (p.y() - 4100000.0);
}
double patch(const Vec2& p) {  // bilinear: a x y term as well
  const double x = p.x() - 500000.0, y = p.y() - 4100000.0;
  return 1.0 + 0.3 * x - 0.2 * y + 0.01 * x * y;
}

TEST(Raster, BilinearIsExactOnAPlaneAndABilinearPatchOverTheWholeExtent) {
  const RasterGrid g = small_grid();
  const Raster a = sampled(g, plane), b = sampled(g, patch);
  double worst_plane = 0.0, worst_patch = 0.0;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 30; ++j) {  // corner to corner, edge bands included
      const Vec2 p(500000.0 + 14.0 * i / 40, 4100015.0 - 15.0 * j / 30);
      worst_plane = std::max(worst_plane, std::abs(*a.bilinear(p) - plane(p)));
      worst_patch = std::max(worst_patch, std::abs(*b.bilinear(p) - patch(p)));
    }
  EXPECT_LE(worst_plane, 1e-12);
  EXPECT_LE(worst_patch, 1e-11);
}

TEST(Raster, NoValueOutsideTheExtentOrNextToNodata) {
  RasterGrid g = small_grid();
  std::vector<double> v(35, 1.0);
  v[2 * 7 + 3] = -9999.0;  // column 3, row 2
  const Raster r(g, v, -9999.0);
  EXPECT_FALSE(r.bilinear({499999.9, 4100010.0}));
  EXPECT_FALSE(r.bilinear({500001.0, 4100015.1}));
  EXPECT_FALSE(r.bilinear(g.centre(3, 2) + Vec2(0.5, 0.5)));
  EXPECT_EQ(*r.bilinear(g.centre(0, 0)), 1.0);
  EXPECT_FALSE(r.nearest(g.centre(3, 2)));
  EXPECT_EQ(*r.nearest(g.centre(4, 2)), 1.0);
}

// A GeoTIFF is written under <path>.part and renamed when whole: no .part is left, and a write
// that cannot finish (here its .part cannot be created: a folder holds the name) leaves the
// previous file as it was, and says which file it could not write.
TEST(Raster, GeoTiffIsReplacedWholeOrNotAtAll) {
  const fs::path dir = test::fresh_test_folder("flotsam_raster_atomic_test");
  const RasterGrid g = small_grid();
  const std::string path = (dir / "max_depth.tif").string();
  write_geotiff(path, g, std::vector<double>(35, 1.5));
  EXPECT_FALSE(fs::exists(path + ".part"));
  fs::create_directories(path + ".part");  // the next write cannot create its .part
  try {
    write_geotiff(path, g, std::vector<double>(35, 2.5));
    FAIL() << "the write could not create its .part, yet reported no error";
  } catch (const RunError& e) {
    EXPECT_THAT(std::string(e.what()), ::testing::HasSubstr("could not write '" + path + "'"));
  }
  const Raster before = Raster::read(path, "test");
  for (int r = 0; r < 5; ++r)
    for (int c = 0; c < 7; ++c) EXPECT_EQ(before.at(c, r), 1.5);
  fs::remove_all(dir);
}

// A truncated GeoTIFF is refused by flotsam's message, naming the key and the file; GDAL's own
// lines ("ERROR 1: ... scanline ...", naming no file) do not reach stderr.
TEST(Raster, TruncatedGeoTiffIsNamedAndGdalStaysQuiet) {
  const fs::path dir = test::fresh_test_folder("flotsam_raster_truncated_test");
  const std::string path = (dir / "dem.tif").string();
  RasterGrid g = RasterGrid::covering({0.0, 0.0}, {640.0, 640.0}, 2.0, "");
  std::vector<double> v(static_cast<std::size_t>(g.columns) * g.rows);
  for (std::size_t k = 0; k < v.size(); ++k) v[k] = std::sin(0.37 * k) * 100.0;  // incompressible
  write_geotiff(path, g, v);
  fs::resize_file(path, fs::file_size(path) / 2);
  testing::internal::CaptureStderr();
  std::string message = "no error";
  try {
    Raster::read(path, "case.yaml:7: bed.raster");
  } catch (const InputError& e) {
    message = e.what();
  }
  const std::string printed = testing::internal::GetCapturedStderr();
  EXPECT_THAT(message, ::testing::StartsWith("case.yaml:7: bed.raster: "));
  EXPECT_THAT(message, ::testing::HasSubstr(path));
  EXPECT_EQ(printed, "");
  fs::remove_all(dir);
}

// A raster that declares more pixels than memory holds (150,000 x 150,000: 180 GB as doubles;
// the file itself under 2 MB, its blocks sparse) is refused before anything is
// allocated, naming the key, the file and its size, instead of stopping with std::bad_alloc.
TEST(Raster, RasterLargerThanMemoryIsRefused) {
  const fs::path dir = test::fresh_test_folder("flotsam_raster_huge_test");
  const std::string path = (dir / "huge.tif").string();
  GDALAllRegister();
  char** options = CSLSetNameValue(nullptr, "SPARSE_OK", "TRUE");
  GDALDataset* d = GetGDALDriverManager()->GetDriverByName("GTiff")->Create(
      path.c_str(), 150000, 150000, 1, GDT_Float64, options);
  CSLDestroy(options);
  ASSERT_NE(d, nullptr);
  double transform[6] = {500000.0, 1.0, 0.0, 5200000.0, 0.0, -1.0};  // 1 m pixels
  d->SetGeoTransform(transform);
  GDALClose(d);
  ASSERT_LT(fs::file_size(path), 4000000u);  // its strip table only
  try {
    Raster::read(path, "case.yaml:7: bed.raster");
    FAIL() << "a raster of 180 GB was read";
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()),
                ::testing::StartsWith("case.yaml:7: bed.raster: '" + path +
                                      "' has 150000 x 150000 pixels, 180 GB as 8-byte values: "
                                      "more than half the memory this process may use"));
  }
  fs::remove_all(dir);
}

TEST(Raster, GeoTiffRoundTripKeepsValuesGeoreferencingAndCoordinateSystem) {
  const fs::path dir = fs::temp_directory_path() / "flotsam_raster_test";
  fs::create_directories(dir);
  RasterGrid g = small_grid();
  g.crs_wkt = utm_33n();
  std::vector<double> v(35);
  for (std::size_t k = 0; k < v.size(); ++k) v[k] = 0.125 * k - 1.0;
  v[10] = std::nan("");  // written as nodata
  const std::string path = (dir / "round_trip.tif").string();
  write_geotiff(path, g, v);
  const Raster back = Raster::read(path, "test");
  EXPECT_EQ(back.grid().columns, 7);
  EXPECT_EQ(back.grid().rows, 5);
  EXPECT_EQ(back.grid().transform, g.transform);
  OGRSpatialReference written, read;
  written.importFromWkt(g.crs_wkt.c_str());
  read.importFromWkt(back.grid().crs_wkt.c_str());
  EXPECT_TRUE(read.IsSame(&written));
  EXPECT_EQ(read.GetEPSGGeogCS(), 4326);
  for (int r = 0; r < 5; ++r)
    for (int c = 0; c < 7; ++c) {
      const std::size_t k = static_cast<std::size_t>(r) * 7 + c;
      if (k == 10)
        EXPECT_TRUE(back.is_nodata(back.at(c, r)));
      else
        EXPECT_EQ(back.at(c, r), v[k]);
    }
  fs::remove_all(dir);
}

TEST(Raster, CoveringGridAlignsToTheResolution) {
  const RasterGrid g = RasterGrid::covering({10.3, -4.1}, {29.9, 5.0}, 2.0, "");
  EXPECT_EQ(g.transform[0], 10.0);
  EXPECT_EQ(g.transform[3], 6.0);
  EXPECT_EQ(g.columns, 10);  // 10 .. 30
  EXPECT_EQ(g.rows, 6);      // 6 .. -6
  EXPECT_EQ(g.centre(0, 0), Vec2(11.0, 5.0));
}

TEST(Raster, ReadErrorsNameTheOriginAndTheFile) {
  const fs::path dir = fs::temp_directory_path() / "flotsam_raster_errors";
  fs::create_directories(dir);
  const auto message = [](const std::string& path) {
    try {
      Raster::read(path, "case.yaml:7: bed.raster");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(
      message((dir / "none.tif").string()),
      "case.yaml:7: bed.raster: the raster '" + (dir / "none.tif").string() + "' does not exist");
  { std::ofstream((dir / "text.tif").string()) << "not a raster"; }
  EXPECT_NE(message((dir / "text.tif").string()).find("is not a raster GDAL can read"),
            std::string::npos);
  RasterGrid geographic = small_grid();
  geographic.transform = {10.0, 0.001, 0.0, 45.0, 0.0, -0.001};
  OGRSpatialReference wgs84;
  wgs84.importFromEPSG(4326);
  char* wkt = nullptr;
  wgs84.exportToWkt(&wkt);
  geographic.crs_wkt = wkt;
  CPLFree(wkt);
  write_geotiff((dir / "degrees.tif").string(), geographic, std::vector<double>(35, 1.0));
  EXPECT_NE(message((dir / "degrees.tif").string()).find("is in geographic coordinates (degrees)"),
            std::string::npos);
  // An infinite pixel (NaN is nodata; +-Inf is neither a value nor nodata) is named.
  for (const double bad :
       {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()}) {
    RasterGrid g = small_grid();
    g.crs_wkt = utm_33n();
    std::vector<double> v(35, 1.0);
    v[1 * 7 + 5] = bad;  // column 5, row 1
    write_geotiff((dir / "inf.tif").string(), g, v);
    EXPECT_EQ(message((dir / "inf.tif").string()),
              "case.yaml:7: bed.raster: '" + (dir / "inf.tif").string() +
                  "': pixel (column 5, row 1) holds " + (bad > 0 ? "inf" : "-inf") +
                  "; expected a finite value or the raster's nodata value");
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace flotsam
