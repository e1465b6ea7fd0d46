// mesh.region (docs/case-format.md "mesh.region"): the domain from geodata files or points.
// Vector files are read here (geo/vector_layer.hpp) so that their errors name the case's key;
// the geometry's own checks (simple rings, holes apart) run when the mesh is generated.
#include <filesystem>

#include "core/error.hpp"
#include "geo/vector_layer.hpp"
#include "io/case_sections.hpp"

namespace flotsam {

namespace {

/// A vector layer given as a path, or as {file, layer} (and `name_field` for the lines' name
/// attribute, `label_field` unless given).
VectorLayer read_layer(const YamlValue& value, const std::filesystem::path& case_folder,
                       const std::string& label_field = "") {
  const std::string label = value.is_map() && !label_field.empty()
                                ? value.map().text("name_field", label_field)
                                : label_field;
  return read_case_layer(value, case_folder, "", label);
}

std::vector<Vec2> read_points(const YamlValue& value) {
  std::vector<Vec2> points;
  for (const YamlValue& p : value.list()) points.push_back(p.vec2());
  return points;
}

/// Rings of all polygons of a layer (and their holes, when asked) with their feature names; a
/// line in it (a closed LineString drawn for a footprint) is an error naming `value` and the
/// feature, not a polygon left out.
std::vector<NamedRing> rings_of(const YamlValue& value, const VectorLayer& layer,
                                std::vector<NamedRing>* holes) {
  if (!layer.lines.empty())
    value.fail(
        fmt::format("{} is a line; expected polygons (a closed line is not an area: "
                    "save it as a polygon, e.g. ogr2ogr -nlt POLYGON)",
                    layer.lines.front().name));
  std::vector<NamedRing> rings;
  for (const GeoPolygon& p : layer.polygons) {
    rings.push_back({p.ring, p.name});
    if (holes)
      for (std::size_t k = 0; k < p.holes.size(); ++k)
        holes->push_back({p.holes[k], fmt::format("{} hole {}", p.name, k + 1)});
  }
  return rings;
}

}  // namespace

RegionGeometry read_region(const YamlMap& m, const std::filesystem::path& case_folder,
                           std::string& crs_wkt) {
  RegionGeometry g;
  const YamlValue outline =
      m.get("outline", "the domain's outline: a vector file or [[x, y], ...]");
  if (outline.is_list()) {
    g.outline = {read_points(outline), outline.origin()};
    if (g.outline.points.size() < 3)
      outline.fail(fmt::format("expected at least 3 corners, got {}", g.outline.points.size()));
  } else {
    const VectorLayer layer = read_layer(outline, case_folder);
    std::vector<NamedRing> rings = rings_of(outline, layer, &g.islands);
    if (rings.size() != 1)
      outline.fail(
          fmt::format("expected one polygon in the outline's layer, got {}", rings.size()));
    g.outline = rings.front();
    crs_wkt = layer.crs_wkt;
  }
  if (const auto lines = m.find("boundaries")) {
    const YamlMap b = lines->map();
    if (b.has("file")) {
      const VectorLayer layer = read_layer(*lines, case_folder, "name");
      for (const GeoLine& line : layer.lines)
        g.lines.push_back({line.label, line.points, line.name});
      if (g.lines.empty()) lines->fail("expected lines in the layer, found none");
    } else {
      for (const auto& [group, points] : b.entries()) {
        g.lines.push_back({group, read_points(points), points.origin()});
        if (g.lines.back().points.size() < 2)
          points.fail("expected a line of at least 2 points [[x, y], ...]");
      }
    }
  }
  g.default_group = m.text("default_group", g.default_group);
  if (const auto buildings = m.find("buildings"))
    g.buildings = rings_of(*buildings, read_layer(*buildings, case_folder), nullptr);
  if (const auto piers = m.find("piers"))
    for (const YamlValue& item : piers->list()) {
      const YamlMap p = item.map();
      g.piers.push_back(
          {{p.get("x").number(), p.get("y").number()}, p.get("radius").number(Range::positive())});
    }
  if (const auto outlines = m.find("pier_outlines"))
    g.pier_outlines = rings_of(*outlines, read_layer(*outlines, case_folder), nullptr);
  g.mesh_size = m.number("mesh_size", g.mesh_size, Range::positive());
  g.building_mesh_size = m.number("building_mesh_size", g.building_mesh_size, Range::positive());
  g.pier_mesh_size = m.number("pier_mesh_size", g.pier_mesh_size, Range::positive());
  g.refine_distance = m.number("refine_distance", g.refine_distance, Range::non_negative());
  if (m.has("merge_distance"))
    g.merge_distance = m.number("merge_distance", 0.0, Range::non_negative());
  if (m.has("min_building_area"))
    g.min_building_area = m.number("min_building_area", 0.0, Range::non_negative());
  return g;
}

}  // namespace flotsam
