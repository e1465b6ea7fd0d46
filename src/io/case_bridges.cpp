// bridges (docs/case-format.md "bridges"): each bridge's name, axis and piers, written in the case
// or read from a line layer of a vector file. Where they stand on the mesh is checked when the
// mesh exists (bridges/bridge_layout.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "io/case_sections.hpp"

namespace flotsam {

namespace {

void check_axis(const BridgeConfig& bridge, const YamlValue& where) {
  if (bridge.start == bridge.end)
    where.fail(fmt::format("bridge '{}': the axis' two ends are the same point ({}, {}) m",
                           bridge.name, bridge.start.x(), bridge.start.y()));
}

DeckConfig read_deck(const YamlValue& value, const std::string& bridge) {
  const YamlMap m = value.map();
  DeckConfig deck;
  deck.soffit = m.get("soffit", "the z of the deck's underside (low chord) [m]").number();
  const YamlValue top = m.get("top", "the z of the deck's road surface (high chord) [m]");
  deck.top = top.number();
  if (!(deck.top > deck.soffit))
    top.fail(fmt::format("bridge '{}': the deck top ({} m) must stand above its soffit ({} m)",
                         bridge, deck.top, deck.soffit));
  deck.width = m.get("width", "the deck's width along the flow [m]").number(Range::positive());
  if (const auto railing = m.find("railing")) {
    const YamlMap r = railing->map();
    deck.railing_height = r.number("height", 0.0, Range::non_negative());
    deck.railing_open = r.boolean("open", deck.railing_open);
  }
  return deck;
}

BridgeConfig read_bridge(const YamlValue& item, int index) {
  const YamlMap m = item.map();
  BridgeConfig bridge;
  bridge.origin = item.origin();
  bridge.name = m.text("name", fmt::format("bridge_{}", index + 1));
  const YamlValue axis = m.get("axis",
                               "a line across the river: [[x, y], [x, y]] from the right "
                               "bank to the left bank, looking downstream");
  const std::vector<YamlValue> ends = axis.list();
  if (ends.size() != 2)
    axis.fail(
        fmt::format("expected the axis' two ends [[x, y], [x, y]], got {} points", ends.size()));
  bridge.start = ends[0].vec2();
  bridge.end = ends[1].vec2();
  check_axis(bridge, axis);
  if (const auto piers = m.find("piers"))
    for (const YamlValue& pier : piers->list()) bridge.pier_groups.push_back(pier.text());
  if (const auto deck = m.find("deck")) bridge.deck = read_deck(*deck, bridge.name);
  bridge.backwater_distance = m.number("backwater_distance", 0.0, Range::positive());
  return bridge;
}

/// A deck from a line's attributes soffit, deck_top, deck_width, railing_height (0),
/// railing_open (1): none without soffit; InputError naming the feature for a partial or
/// inconsistent one.
std::optional<DeckConfig> deck_of(const GeoLine& line, const YamlValue& where) {
  const auto number = [&](const char* key) -> std::optional<double> {
    const auto it = line.numbers.find(key);
    if (it == line.numbers.end()) return std::nullopt;
    return it->second;
  };
  const auto soffit = number("soffit");
  if (!soffit) return std::nullopt;
  const auto top = number("deck_top"), width = number("deck_width");
  if (!top || !width)
    where.fail(
        fmt::format("{}: a deck needs soffit, deck_top and deck_width; deck_top or "
                    "deck_width has no value",
                    line.name));
  DeckConfig deck{.soffit = *soffit,
                  .top = *top,
                  .width = *width,
                  .railing_height = number("railing_height").value_or(0.0),
                  .railing_open = number("railing_open").value_or(1.0) != 0.0};
  if (!(deck.top > deck.soffit) || !(deck.width > 0.0) || deck.railing_height < 0.0)
    where.fail(
        fmt::format("{}: expected deck_top ({} m) above soffit ({} m), deck_width ({} m) "
                    "> 0 and railing_height ({} m) >= 0",
                    line.name, deck.top, deck.soffit, deck.width, deck.railing_height));
  return deck;
}

}  // namespace

std::vector<BridgeConfig> read_bridges(const YamlValue& value,
                                       const std::filesystem::path& case_folder,
                                       const MeshSource& mesh, std::vector<GeodataCrs>& geodata) {
  if (mesh.kind == MeshSource::Kind::channel)
    value.fail(
        "a mesh.channel makes one bridge of each line of its piers; bridges: is for the other "
        "meshes (mesh.polygon, mesh.region, mesh.file)");
  std::vector<BridgeConfig> bridges;
  if (value.is_list()) {
    for (const YamlValue& item : value.list())
      bridges.push_back(read_bridge(item, static_cast<int>(bridges.size())));
  } else {
    const YamlMap m = value.map();
    const std::string name_field = m.text("name_field", "name");
    const VectorLayer layer = read_case_layer(value, case_folder, "", name_field);
    const double distance = m.number("backwater_distance", 0.0, Range::positive());
    geodata.push_back({layer.crs_wkt, fmt::format("the bridges' layer ({})", value.origin())});
    for (const GeoLine& line : layer.lines) {
      BridgeConfig bridge;
      bridge.origin = line.name;
      bridge.name = line.label.empty() ? fmt::format("bridge_{}", bridges.size() + 1) : line.label;
      if (line.points.size() != 2)
        value.fail(
            fmt::format("{}: expected an axis of two points (a straight line across the "
                        "river), got {} points",
                        line.name, line.points.size()));
      bridge.start = line.points.front();
      bridge.end = line.points.back();
      check_axis(bridge, value);
      bridge.deck = deck_of(line, value);
      bridge.backwater_distance = distance;
      bridges.push_back(std::move(bridge));
    }
    if (bridges.empty()) value.fail("expected lines (the bridges' axes) in the layer, found none");
  }
  for (std::size_t b = 0; b < bridges.size(); ++b)
    for (std::size_t a = 0; a < b; ++a)
      if (bridges[a].name == bridges[b].name)
        value.fail(fmt::format("two bridges are called '{}' ({} and {}); names must differ",
                               bridges[b].name, bridges[a].origin, bridges[b].origin));
  return bridges;
}

}  // namespace flotsam
