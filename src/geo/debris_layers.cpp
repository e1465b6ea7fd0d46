#include "geo/debris_layers.hpp"

#include <fmt/format.h>
#include <ogrsf_frmts.h>
#include <spdlog/spdlog.h>

#include <cassert>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>

#include "core/calendar_time.hpp"
#include "core/error.hpp"
#include "geo/gdal_support.hpp"

namespace flotsam {

namespace {

struct FieldSpec {
  const char* name;
  OGRFieldType type;
};

// The layers' fields in their order; a restarted run checks a file against these.
constexpr FieldSpec track_fields[] = {
    {"body", OFTInteger64}, {"t_s", OFTReal},     {"time", OFTDateTime}, {"kind", OFTString},
    {"length_m", OFTReal},  {"width_m", OFTReal}, {"speed_ms", OFTReal}, {"state", OFTString},
    {"fate", OFTString},    {"jam", OFTInteger},  {"bridge", OFTString}};
constexpr FieldSpec jam_fields[] = {
    {"jam", OFTInteger},   {"t_s", OFTReal},      {"time", OFTDateTime},   {"bodies", OFTInteger},
    {"bridge", OFTString}, {"blockage", OFTReal}, {"thickness_m", OFTReal}};

constexpr int utc = 100;  // OGR's time zone flag for UTC (ogr_core.h, OGRField.Date.TZFlag)

std::chrono::sys_seconds seconds_of(const CalendarTime& c) {
  using namespace std::chrono;
  return sys_days{year{c.year} / c.month / c.day} + hours{c.hour} + minutes{c.minute} +
         seconds{c.second};
}

/// The coordinate system of `crs_wkt`, or none when it is empty.
std::optional<OGRSpatialReference> parse_srs(const std::string& crs_wkt, const std::string& path) {
  if (crs_wkt.empty()) return std::nullopt;
  OGRSpatialReference srs;
  if (srs.importFromWkt(crs_wkt.c_str()) != OGRERR_NONE)
    throw_input_error("'{}': the coordinate system is not WKT GDAL can read: {}", path, crs_wkt);
  srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);  // x = easting, y = northing
  return srs;
}

std::string describe(std::span<const FieldSpec> fields) {
  std::string text;
  for (const FieldSpec& f : fields)
    text += fmt::format("{}{} {}", text.empty() ? "" : ", ", f.name,
                        OGRFieldDefn::GetFieldTypeName(f.type));
  return text;
}

std::string describe(const OGRFeatureDefn& definition) {
  std::string text;
  for (int k = 0; k < definition.GetFieldCount(); ++k) {
    const OGRFieldDefn* f = definition.GetFieldDefn(k);
    text += fmt::format("{}{} {}", k ? ", " : "", f->GetNameRef(),
                        OGRFieldDefn::GetFieldTypeName(f->GetType()));
  }
  return text;
}

// `srs`: none when null (GDAL 3.6's CreateLayer takes it non-const).
void create_layer(GDALDataset& dataset, const char* name, std::span<const FieldSpec> fields,
                  OGRSpatialReference* srs, const std::string& path) {
  OGRLayer* layer = dataset.CreateLayer(name, srs, wkbPolygon, nullptr);
  if (!layer)
    throw_input_error("cannot create layer '{}' in '{}' ({})", name, path, CPLGetLastErrorMsg());
  for (const FieldSpec& f : fields) {
    OGRFieldDefn definition(f.name, f.type);
    if (layer->CreateField(&definition) != OGRERR_NONE)
      throw_input_error("cannot create field '{}' of layer '{}' in '{}' ({})", f.name, name, path,
                        CPLGetLastErrorMsg());
  }
}

/// The layer `name` of a file to continue, checked against `fields` and the coordinate system.
OGRLayer* checked_layer(GDALDataset& dataset, const char* name, std::span<const FieldSpec> fields,
                        const std::optional<OGRSpatialReference>& srs, const std::string& path) {
  constexpr const char* advice =
      "the file belongs to another case or was edited; run afresh (--overwrite) or restore it";
  OGRLayer* layer = dataset.GetLayerByName(name);
  if (!layer)
    throw_input_error("cannot continue '{}': it has no layer '{}'; {}", path, name, advice);
  const std::string found = describe(*layer->GetLayerDefn()), expected = describe(fields);
  if (found != expected)
    throw_input_error(
        "cannot continue '{}': layer '{}' has the fields ({}), not the ones this run "
        "writes ({}); {}",
        path, name, found, expected, advice);
  if (wkbFlatten(layer->GetGeomType()) != wkbPolygon)
    throw_input_error("cannot continue '{}': layer '{}' holds {} geometries, not polygons; {}",
                      path, name, OGRGeometryTypeToName(layer->GetGeomType()), advice);
  const OGRSpatialReference* has = layer->GetSpatialRef();
  if (has && gdal::is_undefined(*has)) has = nullptr;
  if (bool(has) != bool(srs) || (has && !has->IsSame(&*srs)))
    throw_input_error(
        "cannot continue '{}': layer '{}' is in the coordinate system '{}', this run in '{}'; {}",
        path, name, has ? has->GetName() : "none", srs ? srs->GetName() : "none", advice);
  return layer;
}

/// Deletes the features of `layer` whose t_s is after `cut` [s]; how many.
int delete_after(OGRLayer& layer, double cut, const std::string& path) {
  layer.SetAttributeFilter(fmt::format("t_s > {:.17g}", cut).c_str());
  std::vector<GIntBig> later;
  for (const auto& feature : layer) later.push_back(feature->GetFID());
  layer.SetAttributeFilter(nullptr);
  for (const GIntBig fid : later)
    if (layer.DeleteFeature(fid) != OGRERR_NONE)
      throw_input_error("cannot continue '{}': could not delete feature {} of layer '{}' ({})",
                        path, fid, layer.GetName(), CPLGetLastErrorMsg());
  return static_cast<int>(later.size());
}

/// t_s = t and time = origin + t, rounded to the millisecond (what the field keeps).
void set_time(OGRFeature& feature, double t, std::chrono::sys_seconds origin) {
  using namespace std::chrono;
  feature.SetField("t_s", t);
  const sys_time<milliseconds> when = origin + milliseconds{std::llround(t * 1000.0)};
  const sys_days day = floor<days>(when);
  const year_month_day date{day};
  const hh_mm_ss clock{when - day};
  const double second = static_cast<double>(clock.seconds().count()) +
                        static_cast<double>(clock.subseconds().count()) / 1000.0;
  feature.SetField("time", static_cast<int>(date.year()), static_cast<int>(unsigned(date.month())),
                   static_cast<int>(unsigned(date.day())), static_cast<int>(clock.hours().count()),
                   static_cast<int>(clock.minutes().count()), static_cast<float>(second), utc);
}

/// A text field, NULL when empty.
void set_text_or_null(OGRFeature& feature, const char* name, const std::string& text) {
  if (text.empty())
    feature.SetFieldNull(feature.GetFieldIndex(name));
  else
    feature.SetField(name, text.c_str());
}

std::unique_ptr<OGRPolygon> polygon_of(const std::array<Vec2, 4>& corners) {
  auto ring = std::make_unique<OGRLinearRing>();
  for (const Vec2& p : corners) ring->addPoint(p.x(), p.y());
  ring->closeRings();
  auto polygon = std::make_unique<OGRPolygon>();
  polygon->addRingDirectly(ring.release());
  return polygon;
}

// The file is replaced: the GeoPackage driver refuses to create over an existing file.
GDALDataset* create_file(const std::string& path, const std::string& crs_wkt) {
  std::optional<OGRSpatialReference> srs = parse_srs(crs_wkt, path);
  gdal::register_drivers();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GPKG");
  if (!driver) throw_input_error("GDAL has no GeoPackage driver: cannot write '{}'", path);
  std::error_code error;
  std::filesystem::remove(path, error);
  if (error) throw_input_error("cannot replace '{}': {}", path, error.message());
  gdal::Dataset dataset(driver->Create(path.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
  if (!dataset) throw_input_error("cannot create '{}' ({})", path, CPLGetLastErrorMsg());
  create_layer(*dataset, "tracks", track_fields, srs ? &*srs : nullptr, path);
  create_layer(*dataset, "jams", jam_fields, srs ? &*srs : nullptr, path);
  dataset->FlushCache();  // the tables exist before the first output
  return dataset.release();
}

}  // namespace

void DebrisLayers::CloseDataset::operator()(GDALDataset* dataset) const {
  GDALClose(dataset);
}

DebrisLayers::DebrisLayers(const std::string& path, const std::string& crs_wkt,
                           const CalendarTime& time_origin)
    // Members are initialised in this order: a bad origin leaves an existing file as it was.
    : path_(path),
      origin_(seconds_of(time_origin)),
      dataset_(create_file(path, crs_wkt)),
      tracks_(dataset_->GetLayerByName("tracks")),
      jams_(dataset_->GetLayerByName("jams")) {}

DebrisLayers::DebrisLayers(std::string path, std::chrono::sys_seconds origin, Dataset dataset)
    : path_(std::move(path)),
      origin_(origin),
      dataset_(std::move(dataset)),
      tracks_(dataset_->GetLayerByName("tracks")),
      jams_(dataset_->GetLayerByName("jams")) {}

DebrisLayers DebrisLayers::resume(const std::string& path, const std::string& crs_wkt,
                                  const CalendarTime& time_origin, double resume_time) {
  const std::chrono::sys_seconds origin = seconds_of(time_origin);
  if (!std::filesystem::exists(path)) {
    spdlog::warn("'{}' was missing: written again from t = {} s on; the earlier outputs are lost",
                 path, resume_time);
    return DebrisLayers(path, crs_wkt, time_origin);
  }
  const std::optional<OGRSpatialReference> srs = parse_srs(crs_wkt, path);
  gdal::register_drivers();
  CPLPushErrorHandler(CPLQuietErrorHandler);
  Dataset dataset(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_UPDATE));
  CPLPopErrorHandler();
  if (!dataset)
    throw_input_error("cannot continue '{}': not a GeoPackage GDAL can open for writing ({})", path,
                      CPLGetLastErrorMsg());
  OGRLayer* tracks = checked_layer(*dataset, "tracks", track_fields, srs, path);
  OGRLayer* jams = checked_layer(*dataset, "jams", jam_fields, srs, path);
  // The features after the checkpoint, to a billionth of its time, go in one transaction.
  const double cut = resume_time + 1e-9 * std::abs(resume_time);
  if (dataset->StartTransaction() != OGRERR_NONE)
    throw_input_error("cannot continue '{}': no transaction ({})", path, CPLGetLastErrorMsg());
  int dropped = 0;
  try {
    dropped = delete_after(*tracks, cut, path) + delete_after(*jams, cut, path);
  } catch (...) {
    dataset->RollbackTransaction();
    throw;
  }
  if (dataset->CommitTransaction() != OGRERR_NONE)
    throw_input_error("cannot continue '{}': the deletion failed ({})", path, CPLGetLastErrorMsg());
  dataset->FlushCache();
  spdlog::debug("'{}': {} features after t = {} s dropped", path, dropped, resume_time);
  return DebrisLayers(path, origin, std::move(dataset));
}

void DebrisLayers::write(double t, const std::vector<TrackPoint>& tracks,
                         const std::vector<JamOutline>& jams) {
  assert(dataset_ && "DebrisLayers::write on a moved-from object");
  if (dataset_->StartTransaction() != OGRERR_NONE)
    throw_run_error("cannot write t = {} s to '{}': no transaction ({})", t, path_,
                    CPLGetLastErrorMsg());
  try {
    write_tracks(t, tracks);
    write_jams(t, jams);
  } catch (...) {
    dataset_->RollbackTransaction();
    throw;
  }
  if (dataset_->CommitTransaction() != OGRERR_NONE)
    throw_run_error("cannot write t = {} s to '{}': the commit failed ({})", t, path_,
                    CPLGetLastErrorMsg());
  dataset_->FlushCache();  // extents and feature counts: QGIS reads the file as it grows
}

void DebrisLayers::write_tracks(double t, const std::vector<TrackPoint>& tracks) {
  OGRFeature feature(tracks_->GetLayerDefn());
  for (const TrackPoint& p : tracks) {
    feature.SetFID(OGRNullFID);
    feature.SetField("body", static_cast<GIntBig>(p.body));
    set_time(feature, t, origin_);
    feature.SetField("kind", p.kind.c_str());
    feature.SetField("length_m", 2.0 * p.half_extents.x());
    feature.SetField("width_m", 2.0 * p.half_extents.y());
    feature.SetField("speed_ms", p.speed);
    feature.SetField("state", p.state.c_str());
    feature.SetField("fate", p.fate.c_str());
    feature.SetField("jam", p.jam);
    set_text_or_null(feature, "bridge", p.bridge);
    feature.SetGeometryDirectly(
        polygon_of(footprint_corners(p.centre, p.half_extents, p.angle)).release());
    if (tracks_->CreateFeature(&feature) != OGRERR_NONE)
      throw_run_error("cannot write body {} at t = {} s to layer 'tracks' of '{}' ({})", p.body, t,
                      path_, CPLGetLastErrorMsg());
  }
}

// The outline of a jam is the convex hull of its bodies' footprints (GEOS, through OGR); a jam
// without footprints, or whose hull is not a surface (bodies of zero size), has no geometry.
void DebrisLayers::write_jams(double t, const std::vector<JamOutline>& jams) {
  OGRFeature feature(jams_->GetLayerDefn());
  for (const JamOutline& j : jams) {
    feature.SetFID(OGRNullFID);
    feature.SetField("jam", j.jam);
    set_time(feature, t, origin_);
    feature.SetField("bodies", j.bodies);
    set_text_or_null(feature, "bridge", j.bridge);
    if (std::isnan(j.blockage))
      feature.SetFieldNull(feature.GetFieldIndex("blockage"));
    else
      feature.SetField("blockage", j.blockage);
    feature.SetField("thickness_m", j.thickness);
    OGRMultiPolygon footprints;
    for (const auto& corners : j.footprints)
      footprints.addGeometryDirectly(polygon_of(corners).release());
    std::unique_ptr<OGRGeometry> hull;
    if (!j.footprints.empty()) {
      hull.reset(footprints.ConvexHull());
      if (!hull)
        throw_run_error(
            "cannot write jam {} at t = {} s to layer 'jams' of '{}': no convex hull "
            "({}; GDAL needs GEOS)",
            j.jam, t, path_, CPLGetLastErrorMsg());
      if (wkbFlatten(hull->getGeometryType()) != wkbPolygon) hull.reset();
    }
    feature.SetGeometryDirectly(hull.release());
    if (jams_->CreateFeature(&feature) != OGRERR_NONE)
      throw_run_error("cannot write jam {} at t = {} s to layer 'jams' of '{}' ({})", j.jam, t,
                      path_, CPLGetLastErrorMsg());
  }
}

}  // namespace flotsam
