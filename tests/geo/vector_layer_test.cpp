// Vector layers (geo/vector_layer.hpp): polygons read back as written with their feature names
// and attributes, and each bad file's message.
#include "geo/vector_layer.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <ogr_spatialref.h>

#include <filesystem>

#include "core/error.hpp"
#include "geo/raster.hpp"

namespace flotsam {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

std::string error_reading(const std::string& path, const std::string& layer,
                          const std::string& field = "") {
  try {
    read_vector_layer(path, layer, "case.yaml:4: mesh.region.buildings", field);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(VectorLayer, PolygonsRoundTripWithNamesAttributesAndCoordinateSystem) {
  const fs::path dir = fs::temp_directory_path() / "flotsam_vector_layer_test";
  fs::create_directories(dir);
  const std::string path = (dir / "town.gpkg").string();
  fs::remove(path);
  const std::string utm = coordinate_system_wkt("EPSG:32633", "test");
  write_polygon_layer(path, "landuse",
                      {{{0, 0}, {10, 0}, {10, 5}}, {{20, 0}, {30, 0}, {30, 8}, {20, 8}}}, utm,
                      "manning_n", {0.03, 0.08});
  const VectorLayer layer = read_vector_layer(path, "landuse", "test", "manning_n");
  ASSERT_EQ(layer.polygons.size(), 2u);
  EXPECT_EQ(layer.polygons[0].ring, (std::vector<Vec2>{{0, 0}, {10, 0}, {10, 5}}));
  EXPECT_EQ(layer.polygons[1].ring.size(), 4u);
  EXPECT_EQ(*layer.polygons[1].value, 0.08);
  EXPECT_EQ(layer.polygons[1].name, "town.gpkg, layer 'landuse', feature 2");
  EXPECT_TRUE(same_coordinate_system(layer.crs_wkt, utm));

  EXPECT_THAT(error_reading(path, "roads"),
              HasSubstr("case.yaml:4: mesh.region.buildings: '" + path +
                        "' has no layer 'roads'; its layers: landuse"));
  EXPECT_THAT(error_reading(path, "landuse", "height"),
              HasSubstr("layer 'landuse' of '" + path + "' has no attribute 'height'"));
  EXPECT_THAT(error_reading((dir / "none.gpkg").string(), ""), HasSubstr("does not exist"));
  const std::string degrees = (dir / "degrees.gpkg").string();
  fs::remove(degrees);
  OGRSpatialReference wgs84;
  wgs84.importFromEPSG(4326);
  char* wkt = nullptr;
  wgs84.exportToWkt(&wkt);
  write_polygon_layer(degrees, "a", {{{10, 45}, {10.1, 45}, {10, 45.1}}}, wkt);
  CPLFree(wkt);
  EXPECT_THAT(error_reading(degrees, "a"),
              HasSubstr("is in geographic coordinates (degrees); expected a projected"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace flotsam
