// flow.friction (docs/case-format.md "flow.friction"): the law, its default coefficient, and
// where the coefficient differs: a raster of it, and zones, polygons written in the case or read
// from a vector file. The zones' geometry and coefficients are checked here, so that their errors
// name the case's file, line and key (and the file's feature).
#include <fmt/format.h>

#include <cmath>

#include "core/error.hpp"
#include "io/case_sections.hpp"
#include "mesh/simple_polygon.hpp"

namespace flotsam {

namespace {

// A zone's rings must be simple polygons (mesh/simple_polygon.hpp); `where` names the zone.
void check_rings(const FrictionZone& zone, const std::string& where) {
  if (const std::string defect = polygon_defect(zone.ring); !defect.empty())
    throw_input_error("{}: {}", where, defect);
  for (std::size_t k = 0; k < zone.holes.size(); ++k)
    if (const std::string defect = polygon_defect(zone.holes[k]); !defect.empty())
      throw_input_error("{} hole {}: {}", where, k + 1, defect);
}

// `polygon: [[x, y], ...], coefficient: k` written in the case.
FrictionZone read_inline_zone(const YamlValue& item, const YamlMap& m, const char* unit) {
  FrictionZone zone;
  zone.origin = item.origin();
  const YamlValue polygon = m.get("polygon", "the zone's corners [[x, y], ...] in order");
  for (const YamlValue& corner : polygon.list()) zone.ring.push_back(corner.vec2());
  if (const std::string defect = polygon_defect(zone.ring); !defect.empty()) polygon.fail(defect);
  zone.coefficient = m.get("coefficient", unit).number(Range::positive());
  return zone;
}

// `file: f, layer: l` with `field: attribute` (each polygon's coefficient) or `coefficient: k`
// (the same for all): one zone per polygon (per part of a multi-polygon), in the layer's order.
void read_file_zones(const YamlValue& item, const YamlMap& m,
                     const std::filesystem::path& case_folder, const char* unit,
                     std::vector<FrictionZone>& zones, std::vector<GeodataCrs>& geodata) {
  const std::string given = m.only_one_of({"field", "coefficient"});
  if (given.empty())
    m.fail(
        fmt::format("expected 'field', the attribute holding each polygon's coefficient ({}), or "
                    "'coefficient' for all of them",
                    unit));
  const std::string field = given == "field" ? m.get("field").text() : "";
  const double common =
      given == "coefficient" ? m.get("coefficient").number(Range::positive()) : 0.0;
  const VectorLayer layer = read_case_layer(item, case_folder, field);
  if (layer.polygons.empty())
    item.fail(fmt::format("the layer holds no polygons{}",
                          layer.lines.empty() ? "" : " (only lines); zones are polygons"));
  if (!layer.lines.empty())
    item.fail(fmt::format("{} is a line; zones are polygons", layer.lines.front().name));
  if (!layer.crs_wkt.empty())
    geodata.push_back({layer.crs_wkt,
                       fmt::format("the friction zones' layer ({})", layer.polygons.front().name)});
  for (const GeoPolygon& p : layer.polygons) {
    FrictionZone zone{p.ring, p.holes, field.empty() ? common : *p.value,
                      fmt::format("{}: {}", item.origin(), p.name)};
    if (!(zone.coefficient > 0.0) || !std::isfinite(zone.coefficient))
      throw_input_error("{}: {} = {}; a friction coefficient ({}) must be > 0", zone.origin, field,
                        zone.coefficient, unit);
    check_rings(zone, zone.origin);
    zones.push_back(std::move(zone));
  }
}

// zones: one file {file, layer, field}, or a list whose items are inline zones or files.
std::vector<FrictionZone> read_zones(const YamlValue& value,
                                     const std::filesystem::path& case_folder, const char* unit,
                                     std::vector<GeodataCrs>& geodata) {
  std::vector<FrictionZone> zones;
  const std::vector<YamlValue> items = value.is_map() ? std::vector{value} : value.list();
  for (const YamlValue& item : items) {
    const YamlMap m = item.map();
    const std::string kind = m.only_one_of({"polygon", "file"});
    if (kind.empty()) {
      for (const char* key : {"coefficient", "layer", "field"})
        static_cast<void>(m.has(key));  // known to one kind or the other: not misspellings
      m.check_keys();                   // a misspelt 'polygon' or 'file' is reported as such
      m.fail(
          "expected a zone {polygon: [[x, y], ...], coefficient: k} or a vector file {file, "
          "layer, field}");
    }
    if (kind == "polygon") {
      zones.push_back(read_inline_zone(item, m, unit));
    } else {
      read_file_zones(item, m, case_folder, unit, zones, geodata);
    }
  }
  return zones;
}

}  // namespace

void read_friction(const YamlMap& m, const std::filesystem::path& case_folder, FlowConfig& flow,
                   std::vector<GeodataCrs>& geodata) {
  const auto law = m.get("law").choice<FrictionLaw>({{"none", FrictionLaw::none},
                                                     {"manning", FrictionLaw::manning},
                                                     {"chezy", FrictionLaw::chezy},
                                                     {"strickler", FrictionLaw::strickler}});
  flow.friction = law;
  if (law == FrictionLaw::none) {
    for (const char* key : {"coefficient", "raster", "zones"})
      m.forbid(key, "not used with law 'none'");
    return;
  }
  const char* unit = law == FrictionLaw::manning ? "Manning's n [s m^-1/3]"
                     : law == FrictionLaw::chezy ? "Chezy's C [m^1/2 s^-1]"
                                                 : "Strickler's K [m^1/3 s^-1]";
  flow.friction_coefficient = m.get("coefficient", unit).number(Range::positive());
  FrictionMapConfig& map = flow.friction_map;
  if (const auto raster = m.find("raster")) {
    map.raster_origin = raster->origin();
    map.raster = std::make_shared<const Raster>(
        Raster::read(raster->input_path(case_folder.string()), map.raster_origin));
    if (!map.raster->grid().crs_wkt.empty())
      geodata.push_back({map.raster->grid().crs_wkt,
                         fmt::format("the friction raster '{}'", map.raster->path())});
  }
  if (const auto zones = m.find("zones"))
    map.zones = read_zones(*zones, case_folder, unit, geodata);
}

}  // namespace flotsam
