// Verifies that flow.friction's roughness map is read as given (io/case_friction.cpp): zones
// written in the case and read from a GeoPackage, in the order listed, and a raster read from
// the case's folder; and that each mistake is an InputError naming the file, the line, the key
// and, for a vector file, the feature.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "../support/case_error.hpp"
#include "../support/scratch_path.hpp"
#include "core/error.hpp"
#include "geo/vector_layer.hpp"
#include "io/case_file.hpp"

namespace flotsam {
namespace {

using ::testing::HasSubstr;

// A case whose flow.friction starts on line 5 with `law` (the law and its coefficient, lines 6
// and 7); `extra` continues it.
const std::string manning = "    law: manning\n    coefficient: 0.03\n";
std::string with_friction(const std::string& extra, const std::string& law = manning) {
  return "mesh:\n  channel: {length: 100, width: 20}\nflow:\n  engine: fv\n  friction:\n" + law +
         extra + R"(  initial: {eta: 1.0}
  boundaries:
    inflow: {type: elevation, value: 1.0}
    outflow: {type: elevation, value: 0.9}
    bank_right: {type: wall}
    bank_left: {type: wall}
time: {end: 10}
)";
}

using test::error_of;  // tests/support/case_error.hpp

// Layers are written in UTM zone 33N (a projected coordinate system in metres).
const std::string utm33 = coordinate_system_wkt("EPSG:32633", "test");

std::vector<Vec2> square(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

TEST(CaseFriction, ZonesAreReadInOrderFromTheCaseAndFromVectorFiles) {
  const auto folder = test::fresh_test_folder("flotsam_case_friction");
  std::filesystem::create_directories(folder / "data");
  write_polygon_layer((folder / "data" / "landuse.gpkg").string(), "landuse",
                      {square(0, 0, 10), square(20, 0, 5)}, utm33, "manning_n", {0.06, 0.1});
  const std::string file = (folder / "case.yaml").string();
  const Case c = parse_case(with_friction("    zones:\n"
                                          "      - polygon: [[50, 0], [60, 0], [55, 8]]\n"
                                          "        coefficient: 0.08\n"
                                          "      - {file: data/landuse.gpkg, field: manning_n}\n"
                                          "      - {file: data/landuse.gpkg, coefficient: 0.2}\n"),
                            file);
  const std::vector<FrictionZone>& zones = c.flow.friction_map.zones;
  ASSERT_EQ(zones.size(), 5u);
  EXPECT_EQ(zones[0].ring, (std::vector<Vec2>{{50, 0}, {60, 0}, {55, 8}}));
  EXPECT_EQ(zones[0].coefficient, 0.08);
  EXPECT_EQ(zones[0].origin, file + ":9: flow.friction.zones[0]");
  EXPECT_EQ(zones[1].ring, square(0, 0, 10));
  EXPECT_EQ(zones[1].coefficient, 0.06);
  EXPECT_EQ(zones[1].origin,
            file + ":11: flow.friction.zones[1]: landuse.gpkg, layer 'landuse', feature 1");
  EXPECT_EQ(zones[2].ring, square(20, 0, 5));
  EXPECT_EQ(zones[2].coefficient, 0.1);
  EXPECT_EQ(zones[3].coefficient, 0.2);  // the same for all the file's polygons
  EXPECT_EQ(zones[4].coefficient, 0.2);
  EXPECT_EQ(c.flow.friction_coefficient, 0.03);
  EXPECT_FALSE(c.flow.friction_map.raster);

  // One file as a map, without a list.
  const Case d = parse_case(
      with_friction("    zones: {file: data/landuse.gpkg, layer: landuse, field: manning_n}\n"),
      file);
  ASSERT_EQ(d.flow.friction_map.zones.size(), 2u);
  EXPECT_EQ(d.flow.friction_map.zones[1].coefficient, 0.1);
}

TEST(CaseFriction, RasterIsReadFromTheCaseFolder) {
  const auto folder = test::fresh_test_folder("flotsam_case_friction");
  const RasterGrid g = RasterGrid::covering({0, 0}, {100, 20}, 10.0, "");
  write_geotiff((folder / "n.tif").string(), g,
                std::vector<double>(static_cast<std::size_t>(g.columns) * g.rows, 0.05));
  const std::string file = (folder / "case.yaml").string();
  const Case c = parse_case(with_friction("    raster: n.tif\n"), file);
  ASSERT_TRUE(c.flow.friction_map.raster);
  EXPECT_EQ(c.flow.friction_map.raster->path(), (folder / "n.tif").string());
  EXPECT_EQ(c.flow.friction_map.raster_origin, file + ":8: flow.friction.raster");
  EXPECT_TRUE(c.flow.friction_map.zones.empty());
  EXPECT_EQ(error_of(with_friction("    raster: none.tif\n")),
            "case.yaml:8: flow.friction.raster: the raster 'none.tif' does not exist");
  EXPECT_EQ(error_of(with_friction("    raster: n.tif\n", "    law: none\n")),
            "case.yaml:7: flow.friction.raster: not allowed here: not used with law 'none'");
}

TEST(CaseFriction, ZonesInTheCaseAreChecked) {
  const auto zone = [](const std::string& polygon, const std::string& coefficient = "0.08") {
    return with_friction("    zones:\n      - {polygon: " + polygon +
                         ", coefficient: " + coefficient + "}\n");
  };
  EXPECT_EQ(error_of(zone("[[0, 0], [10, 0], [5, 5]]", "-0.02")),
            "case.yaml:9: flow.friction.zones[0].coefficient: expected a number > 0, got -0.02");
  EXPECT_EQ(error_of(zone("[[0, 0], [10, 0], [5, 5]]", "0")),
            "case.yaml:9: flow.friction.zones[0].coefficient: expected a number > 0, got 0");
  EXPECT_EQ(
      error_of(zone("[[0, 0], [10, 0]]")),
      "case.yaml:9: flow.friction.zones[0].polygon: a polygon needs at least 3 points; got 2");
  EXPECT_EQ(error_of(zone("[[0, 0], [10, 10], [10, 0], [0, 10]]")),
            "case.yaml:9: flow.friction.zones[0].polygon: the polygon intersects itself: side 1 "
            "(points 1 to 2) meets side 3 (points 3 to 4)");
  EXPECT_EQ(error_of(with_friction("    zones:\n      - {coefficient: 0.08}\n")),
            "case.yaml:9: flow.friction.zones[0]: expected a zone {polygon: [[x, y], ...], "
            "coefficient: k} or a vector file {file, layer, field}");
  EXPECT_EQ(error_of(with_friction("    zones:\n      - {polygn: [[0, 0], [10, 0], [5, 5]]}\n")),
            "case.yaml:9: flow.friction.zones[0].polygn: unknown key (did you mean 'polygon'?); "
            "allowed here: polygon, file, coefficient, layer, field");
  EXPECT_EQ(error_of(with_friction("    zones:\n      - {polygon: [[0, 0], [10, 0], [5, 5]]}\n")),
            "case.yaml:9: flow.friction.zones[0].coefficient: missing; this key is required: "
            "Manning's n [s m^-1/3]");
  EXPECT_EQ(error_of(with_friction("    zones:\n      - {polygon: [[0, 0], [10, 0], [5, 5]], "
                                   "coefficient: 9, file: a.gpkg}\n")),
            "case.yaml:9: flow.friction.zones[0].file: give either 'polygon' (line 9) or 'file', "
            "not both");
  EXPECT_EQ(error_of(with_friction("    zones: [[0, 0], [10, 0], [5, 5]]\n")),
            "case.yaml:8: flow.friction.zones[0]: expected a map of keys, got a list");
  EXPECT_EQ(error_of(with_friction("    zones: [{polygon: [[0, 0], [10, 0], [5, 5]]}]\n",
                                   "    law: none\n")),
            "case.yaml:7: flow.friction.zones: not allowed here: not used with law 'none'");
}

TEST(CaseFriction, ZonesFromAVectorFileAreChecked) {
  const auto folder = test::fresh_test_folder("flotsam_case_friction");
  const std::string file = (folder / "case.yaml").string();
  const std::string gpkg = (folder / "landuse.gpkg").string();
  const auto zones_of = [&](const std::vector<std::vector<Vec2>>& rings,
                            const std::vector<double>& n, const std::string& keys) {
    std::filesystem::remove(gpkg);
    write_polygon_layer(gpkg, "landuse", rings, utm33, "manning_n", n);
    return error_of(with_friction("    zones: {file: landuse.gpkg, " + keys + "}\n"), file);
  };
  const std::string at = file + ":8: flow.friction.zones: ";
  EXPECT_EQ(zones_of({square(0, 0, 10), square(20, 0, 5)}, {0.06, -0.05}, "field: manning_n"),
            at + "landuse.gpkg, layer 'landuse', feature 2: manning_n = -0.05; a friction "
                 "coefficient (Manning's n [s m^-1/3]) must be > 0");
  EXPECT_EQ(zones_of({{{0, 0}, {10, 10}, {10, 0}, {0, 10}}}, {0.06}, "field: manning_n"),
            at + "landuse.gpkg, layer 'landuse', feature 1: the polygon intersects itself: side "
                 "1 (points 1 to 2) meets side 3 (points 3 to 4)");
  EXPECT_EQ(zones_of({square(0, 0, 10)}, {0.06}, "field: n"),
            at + "layer 'landuse' of '" + gpkg + "' has no attribute 'n'");
  EXPECT_EQ(zones_of({square(0, 0, 10)}, {0.06}, "layer: fields, field: manning_n"),
            at + "'" + gpkg + "' has no layer 'fields'; its layers: landuse");
  EXPECT_EQ(zones_of({square(0, 0, 10)}, {0.06}, "layer: landuse"),
            file +
                ":8: flow.friction.zones: expected 'field', the attribute holding each "
                "polygon's coefficient (Manning's n [s m^-1/3]), or 'coefficient' for all of "
                "them");
  EXPECT_EQ(error_of(with_friction("    zones: {file: nowhere.gpkg, field: n}\n"), file),
            at + "the vector file '" + (folder / "nowhere.gpkg").string() + "' does not exist");
}

TEST(CaseFriction, MapsInAnotherCoordinateSystemAreRefused) {
  const auto folder = test::fresh_test_folder("flotsam_case_friction");
  write_polygon_layer((folder / "landuse.gpkg").string(), "landuse", {square(0, 0, 10)}, utm33,
                      "manning_n", {0.06});
  const std::string file = (folder / "case.yaml").string();
  const std::string text =
      with_friction("    zones: {file: landuse.gpkg, field: manning_n}\n") + "crs: EPSG:32634\n";
  EXPECT_THAT(error_of(text, file),
              HasSubstr("the key crs and the friction zones' layer (landuse.gpkg, layer "
                        "'landuse', feature 1) are in different coordinate systems"));
  const Case c = parse_case(
      with_friction("    zones: {file: landuse.gpkg, field: manning_n}\n") + "crs: EPSG:32633\n",
      file);
  EXPECT_EQ(c.flow.friction_map.zones.size(), 1u);
}

}  // namespace
}  // namespace flotsam
