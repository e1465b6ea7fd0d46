// Debris as GIS layers (geo/debris_layers.hpp): a GeoPackage read back with OGR as QGIS would
// read it (features per layer, coordinate system, footprints, date-times, attributes, the jams'
// hulls), a restarted run that drops what came after its checkpoint, and bad input refused.
#include "geo/debris_layers.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <ogrsf_frmts.h>
#include <spdlog/sinks/ringbuffer_sink.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <set>

#include "core/error.hpp"
#include "geo/gdal_support.hpp"
#include "geo/vector_layer.hpp"

namespace flotsam {
namespace {

const CalendarTime origin = *parse_calendar_time("2024-01-01 06:30:00");

using ::testing::HasSubstr;
namespace fs = std::filesystem;

constexpr double x0 = 500000.0, y0 = 5000000.0;  // [m] a corner of the scene in UTM 33N

std::string utm33n_wkt() {
  OGRSpatialReference srs;
  srs.importFromEPSG(32633);
  return gdal::wkt_of(srs);
}

fs::path fresh_directory(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// Three bodies: a free log turned by 30 degrees, and two cars side by side, axis-aligned, in a
/// jam: [x0, x0 + 2] x [y0, y0 + 1] and [x0 + 2, x0 + 4] x [y0, y0 + 1], whose hull is their
/// union, 4 m^2. At the bridge "north" when `at_bridge`.
struct Scene {
  std::vector<TrackPoint> tracks;
  std::vector<JamOutline> jams;
};

Scene scene(bool at_bridge, double speed = 1.25) {
  const std::string bridge = at_bridge ? "north" : "";
  Scene s;
  s.tracks.push_back({1,
                      {x0 + 100, y0 + 200},
                      {10, 0.25},
                      std::numbers::pi / 6,
                      "log",
                      speed,
                      "floating",
                      "floating",
                      -1,
                      ""});
  s.tracks.push_back(
      {2, {x0 + 1, y0 + 0.5}, {1, 0.5}, 0.0, "car", 0.0, "grounded", "trapped", 0, bridge});
  s.tracks.push_back(
      {3, {x0 + 3, y0 + 0.5}, {1, 0.5}, 0.0, "car", 0.0, "grounded", "trapped", 0, bridge});
  JamOutline jam{0,  {}, 2, bridge, at_bridge ? 0.35 : std::numeric_limits<double>::quiet_NaN(),
                 1.0};
  for (int k : {1, 2})
    jam.footprints.push_back(
        footprint_corners(s.tracks[k].centre, s.tracks[k].half_extents, s.tracks[k].angle));
  s.jams.push_back(jam);
  return s;
}

gdal::Dataset open_read_only(const std::string& path) {
  gdal::register_drivers();
  return gdal::Dataset(GDALDataset::FromHandle(
      GDALOpenEx(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
}

/// The one feature of `layer` matching `filter` (an OGR SQL where clause).
std::unique_ptr<OGRFeature> only_feature(OGRLayer& layer, const std::string& filter) {
  layer.SetAttributeFilter(filter.c_str());
  EXPECT_EQ(layer.GetFeatureCount(), 1) << filter;
  layer.ResetReading();
  std::unique_ptr<OGRFeature> feature(layer.GetNextFeature());
  layer.SetAttributeFilter(nullptr);
  return feature;
}

std::set<double> times_in(OGRLayer& layer) {
  std::set<double> times;
  layer.ResetReading();
  for (const auto& feature : layer) times.insert(feature->GetFieldAsDouble("t_s"));
  return times;
}

TEST(DebrisLayers, FootprintCornersTurnCounterClockwiseAboutTheCentre) {
  const auto straight = footprint_corners({10, 20}, {2, 1}, 0.0);
  EXPECT_EQ(straight[0], Vec2(8, 19));
  EXPECT_EQ(straight[1], Vec2(12, 19));
  EXPECT_EQ(straight[2], Vec2(12, 21));
  EXPECT_EQ(straight[3], Vec2(8, 21));
  // A quarter turn: the length axis along y, the rear right corner at (+1, -2) from the centre.
  const auto turned = footprint_corners({10, 20}, {2, 1}, std::numbers::pi / 2);
  const Vec2 expected[4] = {{11, 18}, {11, 22}, {9, 22}, {9, 18}};
  for (int k = 0; k < 4; ++k) EXPECT_LT((turned[k] - expected[k]).norm(), 1e-14) << k;
}

TEST(DebrisLayers, TracksAndJamsReadBackWithOgr) {
  const fs::path dir = fresh_directory("flotsam_debris_layers_test");
  const std::string path = (dir / "bridge_debris.gpkg").string();
  const std::string utm = utm33n_wkt();
  {
    DebrisLayers created(path, utm, origin);
    DebrisLayers layers = std::move(created);  // movable: the dataset goes with it
    const Scene before = scene(false), after = scene(true);
    layers.write(30.0, before.tracks, before.jams);
    {  // flushed: another reader (QGIS) sees the first output while the file is open
      const gdal::Dataset reader = open_read_only(path);
      ASSERT_TRUE(reader);
      EXPECT_EQ(reader->GetLayerByName("tracks")->GetFeatureCount(), 3);
      EXPECT_EQ(reader->GetLayerByName("jams")->GetFeatureCount(), 1);
    }
    layers.write(90.5, after.tracks, after.jams);
  }
  const gdal::Dataset d = open_read_only(path);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->GetLayerCount(), 2);
  OGRLayer* tracks = d->GetLayerByName("tracks");
  OGRLayer* jams = d->GetLayerByName("jams");
  ASSERT_TRUE(tracks && jams);
  EXPECT_EQ(tracks->GetFeatureCount(), 6);
  EXPECT_EQ(jams->GetFeatureCount(), 2);
  OGRSpatialReference expected_srs;
  expected_srs.importFromEPSG(32633);
  for (OGRLayer* l : {tracks, jams}) {
    ASSERT_NE(l->GetSpatialRef(), nullptr);
    EXPECT_TRUE(l->GetSpatialRef()->IsSame(&expected_srs)) << l->GetName();
    EXPECT_EQ(wkbFlatten(l->GetGeomType()), wkbPolygon);
  }

  // The log at t = 90.5 s: its rotated rectangle, corner by corner, and its attributes.
  const auto log = only_feature(*tracks, "body = 1 AND t_s = 90.5");
  ASSERT_TRUE(log);
  const OGRLinearRing* ring = log->GetGeometryRef()->toPolygon()->getExteriorRing();
  ASSERT_EQ(ring->getNumPoints(), 5);  // 4 corners and the closing one
  const auto corners = footprint_corners({x0 + 100, y0 + 200}, {10, 0.25}, std::numbers::pi / 6);
  const double s3 = std::sqrt(3.0);  // e = (s3/2, 1/2), n = (-1/2, s3/2), L/2 = 10, l/2 = 0.25
  const Vec2 by_hand[4] = {{x0 + 100 - 5 * s3 + 0.125, y0 + 200 - 5 - 0.125 * s3},
                           {x0 + 100 + 5 * s3 + 0.125, y0 + 200 + 5 - 0.125 * s3},
                           {x0 + 100 + 5 * s3 - 0.125, y0 + 200 + 5 + 0.125 * s3},
                           {x0 + 100 - 5 * s3 - 0.125, y0 + 200 - 5 + 0.125 * s3}};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(ring->getX(k), corners[k].x()) << k;  // stored bit for bit
    EXPECT_EQ(ring->getY(k), corners[k].y()) << k;
    EXPECT_NEAR(ring->getX(k), by_hand[k].x(), 2e-9) << k;  // a few ulps of 5e6 m
    EXPECT_NEAR(ring->getY(k), by_hand[k].y(), 2e-9) << k;
  }
  EXPECT_EQ(ring->getX(4), ring->getX(0));
  EXPECT_EQ(ring->getY(4), ring->getY(0));
  EXPECT_FALSE(ring->isClockwise());
  EXPECT_NEAR(log->GetGeometryRef()->toPolygon()->get_Area(), 20 * 0.5, 1e-6);

  int year, month, day, hour, minute, zone;
  float second;
  ASSERT_TRUE(log->GetFieldAsDateTime(log->GetFieldIndex("time"), &year, &month, &day, &hour,
                                      &minute, &second, &zone));
  EXPECT_EQ(std::vector<int>({year, month, day, hour, minute, zone}),
            std::vector<int>({2024, 1, 1, 6, 31, 100}));  // 100: UTC
  EXPECT_EQ(second, 30.5f);
  EXPECT_EQ(log->GetFieldDefnRef(log->GetFieldIndex("body"))->GetType(), OFTInteger64);
  EXPECT_EQ(log->GetFieldAsInteger64("body"), 1);
  EXPECT_EQ(log->GetFieldAsDouble("t_s"), 90.5);
  EXPECT_STREQ(log->GetFieldAsString("kind"), "log");
  EXPECT_EQ(log->GetFieldAsDouble("length_m"), 20.0);
  EXPECT_EQ(log->GetFieldAsDouble("width_m"), 0.5);
  EXPECT_EQ(log->GetFieldAsDouble("speed_ms"), 1.25);
  EXPECT_STREQ(log->GetFieldAsString("state"), "floating");
  EXPECT_STREQ(log->GetFieldAsString("fate"), "floating");
  EXPECT_EQ(log->GetFieldAsInteger("jam"), -1);
  EXPECT_TRUE(log->IsFieldNull(log->GetFieldIndex("bridge")));

  const auto car = only_feature(*tracks, "body = 3 AND t_s = 90.5");
  ASSERT_TRUE(car);
  EXPECT_STREQ(car->GetFieldAsString("kind"), "car");
  EXPECT_STREQ(car->GetFieldAsString("state"), "grounded");
  EXPECT_STREQ(car->GetFieldAsString("fate"), "trapped");
  EXPECT_EQ(car->GetFieldAsInteger("jam"), 0);
  EXPECT_STREQ(car->GetFieldAsString("bridge"), "north");
  const auto early = only_feature(*tracks, "body = 3 AND t_s = 30");
  ASSERT_TRUE(early);
  ASSERT_TRUE(early->GetFieldAsDateTime(early->GetFieldIndex("time"), &year, &month, &day, &hour,
                                        &minute, &second, &zone));
  EXPECT_EQ(std::vector<int>({hour, minute}), std::vector<int>({6, 30}));
  EXPECT_EQ(second, 30.0f);
  EXPECT_TRUE(early->IsFieldNull(early->GetFieldIndex("bridge")));

  // The jam: the hull of two touching rectangles is their union, [x0, x0 + 4] x [y0, y0 + 1].
  const auto jam = only_feature(*jams, "t_s = 90.5");
  ASSERT_TRUE(jam);
  EXPECT_EQ(jam->GetFieldAsInteger("jam"), 0);
  EXPECT_EQ(jam->GetFieldAsInteger("bodies"), 2);
  EXPECT_STREQ(jam->GetFieldAsString("bridge"), "north");
  EXPECT_EQ(jam->GetFieldAsDouble("blockage"), 0.35);
  EXPECT_EQ(jam->GetFieldAsDouble("thickness_m"), 1.0);
  ASSERT_EQ(wkbFlatten(jam->GetGeometryRef()->getGeometryType()), wkbPolygon);
  EXPECT_EQ(jam->GetGeometryRef()->toPolygon()->get_Area(), 4.0);
  OGREnvelope box;
  jam->GetGeometryRef()->getEnvelope(&box);
  EXPECT_EQ(std::vector<double>({box.MinX, box.MinY, box.MaxX, box.MaxY}),
            std::vector<double>({x0, y0, x0 + 4, y0 + 1}));
  const auto free_jam = only_feature(*jams, "t_s = 30");
  ASSERT_TRUE(free_jam);
  EXPECT_TRUE(free_jam->IsFieldNull(free_jam->GetFieldIndex("bridge")));
  EXPECT_TRUE(free_jam->IsFieldNull(free_jam->GetFieldIndex("blockage")));
  EXPECT_EQ(free_jam->GetGeometryRef()->toPolygon()->get_Area(), 4.0);
  fs::remove_all(dir);
}

TEST(DebrisLayers, ResumeDropsWhatCameAfterTheCheckpoint) {
  const fs::path dir = fresh_directory("flotsam_debris_layers_resume_test");
  const std::string path = (dir / "run_debris.gpkg").string();
  const std::string utm = utm33n_wkt();
  {
    DebrisLayers layers(path, utm, origin);
    for (double t : {10.0, 20.0, 30.0}) layers.write(t, scene(true).tracks, scene(true).jams);
  }
  {  // the run stopped after t = 30 s; its checkpoint was at t = 20 s
    DebrisLayers layers = DebrisLayers::resume(path, utm, origin, 20.0);
    layers.write(30.0, scene(true, 9.0).tracks, scene(true).jams);
  }
  {
    const gdal::Dataset d = open_read_only(path);
    ASSERT_TRUE(d);
    OGRLayer& tracks = *d->GetLayerByName("tracks");
    OGRLayer& jams = *d->GetLayerByName("jams");
    EXPECT_EQ(tracks.GetFeatureCount(), 9);
    EXPECT_EQ(jams.GetFeatureCount(), 3);
    EXPECT_EQ(times_in(tracks), (std::set<double>{10.0, 20.0, 30.0}));
    EXPECT_EQ(times_in(jams), (std::set<double>{10.0, 20.0, 30.0}));
    EXPECT_EQ(only_feature(tracks, "body = 1 AND t_s = 30")->GetFieldAsDouble("speed_ms"), 9.0);
    EXPECT_EQ(only_feature(tracks, "body = 1 AND t_s = 20")->GetFieldAsDouble("speed_ms"), 1.25);
  }

  // A missing file is written again, with a warning that the earlier outputs are lost.
  const std::string missing = (dir / "gone_debris.gpkg").string();
  auto warnings = std::make_shared<spdlog::sinks::ringbuffer_sink_mt>(8);
  spdlog::default_logger()->sinks().push_back(warnings);
  {
    DebrisLayers layers = DebrisLayers::resume(missing, utm, origin, 20.0);
    layers.write(30.0, scene(true).tracks, {});
  }
  spdlog::default_logger()->sinks().pop_back();
  ASSERT_EQ(warnings->last_formatted().size(), 1u);
  EXPECT_THAT(warnings->last_formatted()[0],
              HasSubstr("'" + missing +
                        "' was missing: written again from t = 20 s on; the earlier outputs are "
                        "lost"));
  EXPECT_EQ(open_read_only(missing)->GetLayerByName("tracks")->GetFeatureCount(), 3);
  EXPECT_EQ(open_read_only(missing)->GetLayerByName("jams")->GetFeatureCount(), 0);

  // Another coordinate system, or a GeoPackage of other layers: refused, naming the file.
  try {
    DebrisLayers::resume(path, "", origin, 20.0);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("cannot continue '" + path +
                                    "': layer 'tracks' is in the coordinate system 'WGS 84 / UTM "
                                    "zone 33N', this run in 'none'"));
  }
  const std::string other = (dir / "other.gpkg").string();
  write_polygon_layer(other, "tracks", {{{0, 0}, {1, 0}, {0, 1}}}, utm);
  try {
    DebrisLayers::resume(other, utm, origin, 20.0);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("cannot continue '" + other +
                                    "': layer 'tracks' has the fields (id Integer), not the ones "
                                    "this run writes (body Integer64, t_s Real, time DateTime"));
  }
  fs::remove_all(dir);
}

TEST(DebrisLayers, DefaultOriginIsTheEpochAndNoCoordinateSystemIsNone) {
  const fs::path dir = fresh_directory("flotsam_debris_layers_origin_test");
  const std::string path = (dir / "run_debris.gpkg").string();
  // No origin: t counts from 1970-01-01 00:00:00 (as in the UGRID files); no coordinate system.
  {
    DebrisLayers layers(path, "", CalendarTime{});
    layers.write(86400.0 + 0.25, scene(false).tracks, {});
  }
  const gdal::Dataset d = open_read_only(path);
  OGRLayer& tracks = *d->GetLayerByName("tracks");
  const OGRSpatialReference* srs = tracks.GetSpatialRef();
  EXPECT_TRUE(srs == nullptr || gdal::is_undefined(*srs));
  const auto log = only_feature(tracks, "body = 1");
  int year, month, day, hour, minute, zone;
  float second;
  ASSERT_TRUE(log->GetFieldAsDateTime(log->GetFieldIndex("time"), &year, &month, &day, &hour,
                                      &minute, &second, &zone));
  EXPECT_EQ(std::vector<int>({year, month, day, hour, minute}),
            std::vector<int>({1970, 1, 2, 0, 0}));
  EXPECT_EQ(second, 0.25f);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace flotsam
