#include "geo/vector_layer.hpp"

#include <fmt/format.h>
#include <ogrsf_frmts.h>

#include <filesystem>
#include <memory>

#include "core/error.hpp"
#include "geo/gdal_support.hpp"

namespace flotsam {

namespace {

using gdal::Dataset;

std::vector<Vec2> ring_points(const OGRLinearRing& ring) {
  std::vector<Vec2> points;
  for (int k = 0; k < ring.getNumPoints(); ++k) points.emplace_back(ring.getX(k), ring.getY(k));
  if (points.size() > 1 && points.front() == points.back()) points.pop_back();  // closed ring
  return points;
}

void add_polygon(const OGRPolygon& polygon, const std::string& name, std::optional<double> value,
                 std::vector<GeoPolygon>& out) {
  GeoPolygon p;
  p.name = name;
  p.value = value;
  if (const OGRLinearRing* outer = polygon.getExteriorRing()) p.ring = ring_points(*outer);
  for (int k = 0; k < polygon.getNumInteriorRings(); ++k)
    p.holes.push_back(ring_points(*polygon.getInteriorRing(k)));
  out.push_back(std::move(p));
}

}  // namespace

VectorLayer read_vector_layer(const std::string& path, const std::string& layer,
                              const std::string& origin, const std::string& value_field,
                              const std::string& label_field) {
  const Dataset d = gdal::open_dataset(path, GDAL_OF_VECTOR, origin, "vector file");
  OGRLayer* l = layer.empty() ? d->GetLayer(0) : d->GetLayerByName(layer.c_str());
  if (!l) {
    std::vector<std::string> names;
    for (int k = 0; k < d->GetLayerCount(); ++k) names.push_back(d->GetLayer(k)->GetName());
    throw_input_error("{}: '{}' has no layer '{}'; its layers: {}", origin, path, layer,
                      names.empty() ? "none" : fmt::format("{}", fmt::join(names, ", ")));
  }
  const std::string layer_name = l->GetName();
  VectorLayer out;
  if (const OGRSpatialReference* srs = l->GetSpatialRef(); srs && !gdal::is_undefined(*srs)) {
    if (srs->IsGeographic())
      throw_input_error(
          "{}: layer '{}' of '{}' is in geographic coordinates (degrees); expected a projected "
          "coordinate system in metres (reproject it, e.g. ogr2ogr -t_srs EPSG:<utm zone>)",
          origin, layer_name, path);
    out.crs_wkt = gdal::wkt_of(*srs);
  }
  const OGRFeatureDefn* fields = l->GetLayerDefn();
  for (const std::string& field : {value_field, label_field})
    if (!field.empty() && fields->GetFieldIndex(field.c_str()) < 0)
      throw_input_error("{}: layer '{}' of '{}' has no attribute '{}'", origin, layer_name, path,
                        field);
  l->ResetReading();
  for (auto& feature : *l) {
    const std::string name =
        fmt::format("{}, layer '{}', feature {}", std::filesystem::path(path).filename().string(),
                    layer_name, feature->GetFID());
    OGRGeometry* g = feature->GetGeometryRef();
    if (!g) continue;
    std::unique_ptr<OGRGeometry> flat(g->getLinearGeometry());  // arcs as segments
    flat->flattenTo2D();
    std::optional<double> value;
    if (!value_field.empty()) {
      const int k = feature->GetFieldIndex(value_field.c_str());
      if (!feature->IsFieldSetAndNotNull(k))
        throw_input_error("{}: {} has no value for '{}'", origin, name, value_field);
      value = feature->GetFieldAsDouble(k);
    }
    switch (wkbFlatten(flat->getGeometryType())) {
      case wkbPolygon:
        add_polygon(*flat->toPolygon(), name, value, out.polygons);
        break;
      case wkbMultiPolygon: {
        int part = 0;
        for (const OGRPolygon* p : *flat->toMultiPolygon())
          add_polygon(*p, fmt::format("{} part {}", name, ++part), value, out.polygons);
        break;
      }
      case wkbLineString: {
        GeoLine line;
        for (const auto& p : *flat->toLineString()) line.points.emplace_back(p.getX(), p.getY());
        line.name = name;
        if (!label_field.empty()) {
          const int k = feature->GetFieldIndex(label_field.c_str());
          const bool set = feature->IsFieldSetAndNotNull(k);
          line.label = set ? feature->GetFieldAsString(k) : "";
          if (line.label.empty())
            throw_input_error("{}: {} has no '{}' (it is {}); each line needs one", origin, name,
                              label_field, set ? "empty" : "NULL");
        }
        for (int k = 0; k < fields->GetFieldCount(); ++k) {
          const OGRFieldType type = fields->GetFieldDefn(k)->GetType();
          if ((type == OFTReal || type == OFTInteger || type == OFTInteger64) &&
              feature->IsFieldSetAndNotNull(k))
            line.numbers[fields->GetFieldDefn(k)->GetNameRef()] = feature->GetFieldAsDouble(k);
        }
        out.lines.push_back(std::move(line));
        break;
      }
      default:
        throw_input_error("{}: {} is a {}; expected polygons or lines", origin, name,
                          flat->getGeometryName());
    }
  }
  return out;
}

void write_polygon_layer(const std::string& path, const std::string& layer,
                         const std::vector<std::vector<Vec2>>& rings, const std::string& crs_wkt,
                         const std::string& value_field, const std::vector<double>& values) {
  gdal::register_drivers();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GPKG");
  if (!driver) throw_run_error("GDAL has no GeoPackage driver: cannot write '{}'", path);
  Dataset d(driver->Create(path.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
  if (!d) throw_run_error("could not create '{}' ({})", path, CPLGetLastErrorMsg());
  OGRSpatialReference srs;
  const bool has_crs = !crs_wkt.empty() && srs.importFromWkt(crs_wkt.c_str()) == OGRERR_NONE;
  OGRLayer* l = d->CreateLayer(layer.c_str(), has_crs ? &srs : nullptr, wkbPolygon, nullptr);
  if (!l) throw_run_error("could not create layer '{}' in '{}'", layer, path);
  OGRFieldDefn id("id", OFTInteger);
  l->CreateField(&id);
  if (!value_field.empty()) {
    OGRFieldDefn value(value_field.c_str(), OFTReal);
    l->CreateField(&value);
  }
  for (std::size_t k = 0; k < rings.size(); ++k) {
    OGRFeature feature(l->GetLayerDefn());
    feature.SetField("id", static_cast<int>(k + 1));
    if (!value_field.empty()) feature.SetField(value_field.c_str(), values.at(k));
    OGRLinearRing ring;
    for (const Vec2& p : rings[k]) ring.addPoint(p.x(), p.y());
    ring.closeRings();
    OGRPolygon polygon;
    polygon.addRing(&ring);
    feature.SetGeometry(&polygon);
    if (l->CreateFeature(&feature) != OGRERR_NONE)
      throw_run_error("could not write feature {} to '{}'", k + 1, path);
  }
}

}  // namespace flotsam
