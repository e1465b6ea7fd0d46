#pragma once
// Vector geodata read with GDAL/OGR (GeoPackage, Shapefile, GeoJSON, ...): the polygons of a
// layer (a domain's outline, building footprints, roughness zones, pier outlines) and its lines
// (named boundary lines). Each feature keeps its id and layer for messages, so that bad geometry
// is reported as "buildings.gpkg, layer 'buildings', feature 17: ...".
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/vec.hpp"

namespace flotsam {

/// One polygon of a layer: its outer ring (without the closing repeat of the first point) and
/// its holes. A multi-polygon feature gives one Polygon per part.
struct GeoPolygon {
  std::vector<Vec2> ring;                // [m]
  std::vector<std::vector<Vec2>> holes;  // [m]
  std::string name;                      // "<file>, layer '<layer>', feature <fid>[ part k]"
  std::optional<double> value;           // the attribute asked for (e.g. a Manning n), if any
};

/// One line of a layer with the text of its name attribute and its numeric attributes.
struct GeoLine {
  std::vector<Vec2> points;               // [m]
  std::string label;                      // the name attribute's value
  std::string name;                       // "<file>, layer '<layer>', feature <fid>"
  std::map<std::string, double> numbers;  // every numeric attribute that holds a value
};

struct VectorLayer {
  std::vector<GeoPolygon> polygons;
  std::vector<GeoLine> lines;
  std::string crs_wkt;  // the layer's coordinate system (WKT); empty: none given
};

/// Reads the polygons and lines of `layer` in `path` (the first layer when `layer` is empty).
/// `value_field` names a numeric attribute to keep per polygon, `label_field` a text attribute
/// per line (both optional). `origin` ("case.yaml:5: mesh.region.buildings") names it in
/// messages: a missing file, no such layer (listing those there are), a missing attribute, a
/// layer in geographic coordinates (degrees), curved or 3D geometry is flattened to 2D.
VectorLayer read_vector_layer(const std::string& path, const std::string& layer,
                              const std::string& origin, const std::string& value_field = "",
                              const std::string& label_field = "");

/// Writes polygons to a GeoPackage layer (tests and the example's input scripts' counterpart in
/// C++): one feature per polygon with an integer attribute "id" = its index + 1, and, when
/// `values` is not empty, a real attribute `value_field`.
void write_polygon_layer(const std::string& path, const std::string& layer,
                         const std::vector<std::vector<Vec2>>& rings, const std::string& crs_wkt,
                         const std::string& value_field = "",
                         const std::vector<double>& values = {});

}  // namespace flotsam
