// The case file's schema: one reader per section, in the order of docs/case-format.md. Each
// reader takes its defaults from the structures of io/case.hpp and states its ranges; the
// checked-access layer (io/yaml_reader.hpp) turns every violation into "file:line: key: ...".
#include "io/case_file.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include "core/error.hpp"
#include "core/special_file.hpp"
#include "io/case_digest.hpp"
#include "io/case_sections.hpp"
#include "io/yaml_reader.hpp"

namespace flotsam {

namespace {

// ---- mesh ---------------------------------------------------------------------------------

std::vector<Pier> read_piers(const YamlMap& channel_map, const ChannelGeometry& channel) {
  std::vector<Pier> piers;
  std::vector<int> lines;
  const auto list = channel_map.find("piers");
  if (!list) return piers;
  for (const YamlValue& item : list->list()) {
    const YamlMap m = item.map();
    const Pier pier{{m.get("x").number(), m.get("y").number()},
                    m.get("radius").number(Range::positive())};
    const Vec2 c = pier.centre;
    const double r = pier.radius;
    if (!(c.x() - r > 0.0 && c.x() + r < channel.length && c.y() - r > 0.0 &&
          c.y() + r < channel.width)) {
      item.fail(
          fmt::format("a pier at ({}, {}) of radius {} m does not fit inside the channel "
                      "[0, {}] x [0, {}] m; it must clear every bank",
                      c.x(), c.y(), r, channel.length, channel.width));
    }
    for (std::size_t j = 0; j < piers.size(); ++j) {
      if ((piers[j].centre - c).norm() <= piers[j].radius + r)
        item.fail(fmt::format("overlaps pier {} (line {})", j + 1, lines[j]));
    }
    piers.push_back(pier);
    lines.push_back(item.line());
  }
  return piers;
}

ChannelGeometry read_channel(const YamlMap& m) {
  ChannelGeometry g;
  g.length = m.number("length", g.length, Range::positive());
  g.width = m.number("width", g.width, Range::positive());
  g.mesh_size = m.number("mesh_size", g.mesh_size, Range::positive());
  g.pier_mesh_size = m.number("pier_mesh_size", g.pier_mesh_size, Range::positive());
  g.refine_distance = m.number("refine_distance", g.refine_distance, Range::non_negative());
  g.piers = read_piers(m, g);
  return g;
}

BendGeometry read_bend(const YamlMap& m) {
  BendGeometry g;
  g.centre = m.vec2("centre", g.centre);
  g.width = m.number("width", g.width, Range::positive());
  g.inner_radius = m.number("inner_radius", g.inner_radius, Range::positive());
  g.inlet_length = m.number("inlet_length", g.inlet_length, Range::positive());
  g.outlet_length = m.number("outlet_length", g.outlet_length, Range::positive());
  g.mesh_size = m.number("mesh_size", g.mesh_size, Range::positive());
  return g;
}

PolygonGeometry read_polygon(const YamlMap& m) {
  PolygonGeometry g;
  const YamlValue points = m.get("points", "the corners [[x, y], ...] in order");
  for (const YamlValue& p : points.list()) g.points.push_back(p.vec2());
  if (g.points.size() < 3)
    points.fail(fmt::format("expected at least 3 corners, got {}", g.points.size()));
  const YamlValue groups = m.get("groups", "one boundary group name per side");
  for (const YamlValue& name : groups.list()) g.groups.push_back(name.text());
  if (g.groups.size() != g.points.size()) {
    groups.fail(
        fmt::format("expected one group per side, {} (side i joins corner i to corner "
                    "i+1), got {}",
                    g.points.size(), g.groups.size()));
  }
  g.mesh_size = m.number("mesh_size", g.mesh_size, Range::positive());
  return g;
}

MeshSource read_mesh(const YamlMap& m, const std::filesystem::path& case_folder,
                     std::string& crs_wkt) {
  MeshSource mesh;
  const std::string kind = m.only_one_of({"file", "channel", "bend", "polygon", "region"});
  if (kind.empty()) {
    m.check_keys();  // a misspelt kind is reported as such
    m.fail("expected one of: file, channel, bend, polygon, region");
  }
  if (kind == "file") {
    const YamlValue file = m.get("file");
    const std::filesystem::path path = file.input_path(case_folder.string());
    if (!std::filesystem::is_regular_file(path)) {
      file.fail(
          fmt::format("no such mesh file '{}' (a relative path is read from the case "
                      "file's folder)",
                      path.string()));
    }
    mesh.kind = MeshSource::Kind::file;
    mesh.file = path.string();
  } else if (kind == "channel") {
    mesh.kind = MeshSource::Kind::channel;
    mesh.channel = read_channel(m.get("channel").map());
  } else if (kind == "bend") {
    mesh.kind = MeshSource::Kind::bend;
    mesh.bend = read_bend(m.get("bend").map());
  } else if (kind == "polygon") {
    mesh.kind = MeshSource::Kind::polygon;
    mesh.polygon = read_polygon(m.get("polygon").map());
  } else {
    mesh.kind = MeshSource::Kind::region;
    mesh.region = read_region(m.get("region").map(), case_folder, crs_wkt);
  }
  return mesh;
}

/// mesh.region.steep: where the terrain raster's slope exceeds `slope`, the element size shrinks
/// as slope / |grad z_b| down to `mesh_size` (central differences over one pixel).
void read_steep_refinement(const YamlMap& mesh, const BedConfig& bed, RegionGeometry& region) {
  const auto steep = mesh.map("region").find("steep");
  if (!steep) return;
  if (!bed.raster) steep->fail("refining where the terrain is steep needs a terrain: bed.raster");
  const YamlMap m = steep->map();
  const double slope =
      m.get("slope", "the slope [-] above which elements shrink").number(Range::positive());
  const double smallest =
      m.get("mesh_size", "the smallest element size [m]").number(Range::positive());
  const double far = region.mesh_size;
  const std::shared_ptr<const Raster> raster = bed.raster;
  const double h = std::abs(raster->grid().transform[1]);  // [m] one pixel
  region.size_at = [raster, slope, smallest, far, h](const Vec2& p) {
    const auto zx0 = raster->bilinear(p - Vec2(h, 0)), zx1 = raster->bilinear(p + Vec2(h, 0));
    const auto zy0 = raster->bilinear(p - Vec2(0, h)), zy1 = raster->bilinear(p + Vec2(0, h));
    if (!zx0 || !zx1 || !zy0 || !zy1) return far;
    const double gradient = Vec2(*zx1 - *zx0, *zy1 - *zy0).norm() / (2.0 * h);  // [-]
    return gradient > slope ? std::max(smallest, far * slope / gradient) : far;
  };
}

// ---- bed ----------------------------------------------------------------------------------

// One kind: a table in x, a formula in x and y, a terrain raster (with an optional formula that
// edits it), or a level with an optional slope.
BedConfig read_bed(const YamlMap& m, const std::filesystem::path& case_folder) {
  BedConfig bed;
  if (const auto raster = m.find("raster")) {
    const std::string why = "the bed is given by raster";
    for (const char* key : {"profile_x", "level", "slope"}) m.forbid(key, why);
    bed.kind = BedConfig::Kind::raster;
    bed.origin = raster->origin();
    bed.raster = std::make_shared<const Raster>(
        Raster::read(raster->input_path(case_folder.string()), bed.origin));
    if (const auto edit = m.find("expression")) bed.expression = edit->expression(true);
    return bed;
  }
  const std::string kind = m.only_one_of({"profile_x", "expression"});
  if (!kind.empty()) {
    const std::string why = fmt::format("the bed is given by {}", kind);
    m.forbid("level", why);
    m.forbid("slope", why);
  }
  if (kind == "profile_x") {
    const YamlValue profile = m.get("profile_x");
    bed.kind = BedConfig::Kind::table;
    bed.profile_x = profile.series("x");
    if (bed.profile_x.is_constant())
      profile.fail("expected a table [[x, z_b], ...]; for a flat bed give 'level'");
    return bed;
  }
  if (kind == "expression") {
    bed.kind = BedConfig::Kind::expression;
    bed.expression = m.get("expression").expression();
    return bed;
  }
  bed.level = m.number("level", bed.level);
  if (const auto slope = m.find("slope")) {
    bed.kind = BedConfig::Kind::slope;
    bed.slope = slope->is_list() ? slope->vec2() : Vec2(slope->number(), 0.0);
  }
  return bed;
}

// ---- time and output ----------------------------------------------------------------------

TimeConfig read_time(const YamlMap& m) {
  TimeConfig time;
  time.end = m.get("end", "the simulated time [s]").number(Range::positive());
  const auto step = m.find("step");
  time.step = step ? step->number(Range::positive()) : time.step;
  if (step && time.step > time.end)
    step->fail(fmt::format("the step {} s is longer than time.end = {} s", time.step, time.end));
  if (const auto mode = m.find("mode")) {
    time.mode = mode->choice<CouplingMode>({{"frozen", CouplingMode::frozen},
                                            {"one-way", CouplingMode::one_way},
                                            {"two-way", CouplingMode::two_way}});
  }
  if (const auto method = m.find("steady_method"))
    time.steady_method = method->choice<SteadyMethod>(
        {{"solve", SteadyMethod::solve}, {"march", SteadyMethod::march}});
  time.steady_tolerance = m.number("steady_tolerance", time.steady_tolerance, Range::positive());
  time.steady_max_iterations = static_cast<int>(
      m.integer("steady_max_iterations", time.steady_max_iterations, Range::between(1, 1e9)));
  time.spin_up_step = m.number("spin_up_step", time.spin_up_step, Range::positive());
  time.spin_up_end = m.number("spin_up_end", time.spin_up_end, Range::positive());
  if (const auto scheme = m.find("scheme"))
    time.scheme =
        scheme->choice<TimeScheme>({{"theta", TimeScheme::theta}, {"bdf2", TimeScheme::bdf2}});
  time.theta = m.number("theta", time.theta, Range::between(0.5, 1.0));
  if (const auto origin = m.find("origin")) {
    const auto parsed = parse_calendar_time(origin->text());
    if (!parsed)
      origin->fail(fmt::format(
          "'{}' is not a calendar time: expected \"YYYY-MM-DD hh:mm:ss\" (UTC) or \"YYYY-MM-DD\"",
          origin->text()));
    time.origin = *parsed;
  }
  return time;
}

// Gauges: a list of {name, x, y}; each name is unique, it heads the probe file's columns.
std::vector<Probe> read_probes(const YamlMap& output) {
  std::vector<Probe> probes;
  const auto list = output.find("probes");
  if (!list) return probes;
  for (const YamlValue& item : list->list()) {
    const YamlMap m = item.map();
    Probe probe;
    const YamlValue name = m.get("name", "the probe's name, which heads its columns");
    probe.name = name.text();
    const bool ok =
        !probe.name.empty() && std::all_of(probe.name.begin(), probe.name.end(), [](char ch) {
          return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-';
        });
    if (!ok)
      name.fail(
          fmt::format("expected a name of letters, digits, '_' and '-' (it names the "
                      "probe's columns), got '{}'",
                      probe.name));
    for (const Probe& other : probes)
      if (other.name == probe.name)
        name.fail(fmt::format("the name '{}' is already used by the probe on line {}", probe.name,
                              other.line));
    probe.position = {m.get("x", "[m]").number(), m.get("y", "[m]").number()};
    probe.line = item.line();
    probes.push_back(probe);
  }
  return probes;
}

OutputConfig read_output(const YamlMap& m) {
  OutputConfig output;
  if (const auto directory = m.find("directory")) {
    output.directory = directory->text();
    if (output.directory.empty()) directory->fail("expected a folder name, got an empty text");
  }
  output.interval = m.number("interval", output.interval, Range::positive());
  output.overwrite = m.boolean("overwrite", output.overwrite);
  output.backwater = m.boolean("backwater", output.backwater);
  output.probes = read_probes(m);
  output.probe_interval = m.number("probe_interval", output.probe_interval, Range::non_negative());
  output.wet_depth = m.number("wet_depth", output.wet_depth, Range::positive());
  if (const auto rasters = m.find("rasters"))
    output.raster_resolution =
        rasters->map().get("resolution", "the pixel size [m]").number(Range::positive());
  if (const auto formats = m.find("formats")) {
    enum class Format { vtk, ugrid, gpkg };
    output.formats = {false, false, false};
    for (const YamlValue& item : formats->list()) {
      const Format f = item.choice<Format>(
          {{"vtk", Format::vtk}, {"ugrid", Format::ugrid}, {"gpkg", Format::gpkg}});
      bool& on = f == Format::vtk     ? output.formats.vtk
                 : f == Format::ugrid ? output.formats.ugrid
                                      : output.formats.gpkg;
      if (on) item.fail("this format is listed twice");
      on = true;
    }
  }
  return output;
}

std::string read_name(const YamlMap& root, const std::string& file_name) {
  const auto value = root.find("name");
  if (!value) {
    const std::string stem = std::filesystem::path(file_name).stem().string();
    return stem.empty() ? "case" : stem;
  }
  const std::string name = value->text();
  const bool ok = !name.empty() && std::all_of(name.begin(), name.end(), [](char ch) {
    return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-' || ch == '.';
  });
  if (!ok) {
    value->fail(
        fmt::format("expected a name of letters, digits, '_', '-' and '.' (it names "
                    "the output folder), got '{}'",
                    name));
  }
  // A name of dots only ('.', '..') would be the output folder's parent or itself; a name that
  // starts with one would hide the run's files.
  if (name.front() == '.')
    value->fail(fmt::format(
        "expected a name that does not start with '.' (it names the output folder), got '{}'",
        name));
  constexpr std::size_t longest = 200;  // [characters] file names stay below 255 bytes
  if (name.size() > longest)
    value->fail(
        fmt::format("expected a name of at most {} characters (it names the output "
                    "folder and its files), got {}",
                    longest, name.size()));
  return name;
}

/// The case's coordinate system: the key crs, else that of the first geodata file that has one
/// (the terrain raster, mesh.region's outline, the friction raster and zones, the rain raster);
/// two of them that differ is an error naming the key and the files.
std::string case_coordinate_system(const std::vector<GeodataCrs>& geodata, const YamlMap& root) {
  std::string crs;
  std::string from;  // where crs came from, for messages
  if (const auto given = root.find("crs")) {
    crs = coordinate_system_wkt(given->text(), given->origin());
    from = "the key crs";
  }
  for (const auto& [other, what] : geodata) {
    if (other.empty()) continue;
    if (crs.empty()) {
      crs = other, from = what;
    } else if (!same_coordinate_system(crs, other)) {
      root.fail(
          fmt::format("{} and {} are in different coordinate systems; reproject one of "
                      "them (gdalwarp, ogr2ogr)",
                      from, what));
    }
  }
  return crs;
}

}  // namespace

SplitCaseText split_ensemble_text(const std::string& text) {
  // A top-level key starts at column 0 with a character other than space, '#', '-' or a document
  // marker; the ensemble block runs from `ensemble:` to the next such line.
  SplitCaseText split;
  // A UTF-8 byte-order mark (some editors save one) is not part of the first key.
  constexpr std::string_view bom = "\xEF\xBB\xBF";
  std::istringstream in(text.starts_with(bom) ? text.substr(bom.size()) : text);
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    const bool top_level =
        !line.empty() && line[0] != ' ' && line[0] != '\t' && line[0] != '#' && line[0] != '\r';
    if (top_level) inside = line.rfind("ensemble:", 0) == 0;
    (inside ? split.ensemble_text : split.case_text) += line;
    split.ensemble_text += "\n";
    split.case_text += "\n";
  }
  return split;
}

Case parse_case(const std::string& text, const std::string& file_name) {
  const SplitCaseText split = split_ensemble_text(text);
  if (split.ensemble_text.find_first_not_of(" \n") != std::string::npos)  // a run: as written
    spdlog::info(
        "{}: the `ensemble:` section is for `flotsam ensemble`; this is the case as written",
        file_name);
  YamlDocument document(split.case_text, file_name);
  const YamlMap root = document.root();
  Case c;
  c.file = file_name;
  c.name = read_name(root, file_name);
  const std::filesystem::path case_folder = std::filesystem::path(file_name).parent_path();
  std::string region_crs;
  c.mesh = read_mesh(root.get("mesh", "where the mesh comes from").map(), case_folder, region_crs);
  c.bed = read_bed(root.map("bed"), case_folder);
  if (c.mesh.kind == MeshSource::Kind::region)
    read_steep_refinement(root.get("mesh").map(), c.bed, c.mesh.region);
  std::vector<GeodataCrs> geodata;
  if (c.bed.raster)
    geodata.push_back({c.bed.raster->grid().crs_wkt,
                       fmt::format("the terrain raster '{}'", c.bed.raster->path())});
  geodata.push_back({region_crs, "mesh.region's outline"});
  if (const auto bridges = root.find("bridges"))
    c.bridges = read_bridges(*bridges, case_folder, c.mesh, geodata);
  c.flow = read_flow(root.get("flow", "the water, its friction and its boundaries").map(),
                     case_folder, geodata);
  if (c.flow.engine == FlowEngineKind::fv) c.mesh.element_order = 1;  // straight cells
  for (const BridgeConfig& bridge : c.bridges)
    if (bridge.deck && c.flow.engine != FlowEngineKind::fv)
      throw_input_error(
          "{}: bridge '{}' has a deck: the water under and over a deck is computed by the "
          "finite-volume engine only; set flow.engine: fv",
          bridge.origin, bridge.name);
  c.time = read_time(root.get("time", "at least time.end").map());
  c.bodies = read_bodies(root.map("bodies"));
  const bool has_bodies = !c.bodies.bodies.empty() || !c.bodies.releases.empty();
  if (has_bodies && c.bodies.physics.drag_law == DragLaw::ganser && c.flow.viscosity <= 0.0) {
    const YamlMap flow = root.get("flow").map();
    (flow.has("viscosity") ? flow.get("viscosity") : flow.get("reynolds"))
        .fail(
            "the Ganser drag of the bodies needs a viscosity > 0 (its Reynolds number divides by "
            "it); give the water's, 1e-6 m^2/s, or set bodies.physics.drag_law: constant");
  }
  c.output = read_output(root.map("output"));
  c.crs_wkt = case_coordinate_system(geodata, root);
  if (!root.map("output").has("formats") && !c.crs_wkt.empty())  // a study on geodata: QGIS too
    c.output.formats = {true, true, true};
  if (c.output.raster_resolution > 0.0 && c.flow.engine != FlowEngineKind::fv)
    root.map("output").get("rasters").fail(
        "the flood envelopes and their rasters come from the finite-volume engine; set "
        "flow.engine: fv");
  document.check_no_unknown_keys();
  for (const auto& [key, path] : document.input_files()) c.input_files.push_back({key, path});
  c.settings = case_settings(document.node(), c.input_files);
  return c;
}

std::string read_case_text(const std::string& path) {
  if (const std::string kind = special_file_kind(path); !kind.empty())
    throw_input_error("the case file '{}' is {}, not a file: flotsam reads it whole", path, kind);
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw_input_error("cannot open the case file '{}': {}", path,
                      std::filesystem::exists(path) ? "not readable" : "no such file");
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

Case read_case(const std::string& path) {
  return parse_case(read_case_text(path), path);
}

void check_case_against_mesh(const Case& c, const std::vector<std::string>& mesh_groups) {
  const std::string where = c.file.empty() ? "case" : c.file;
  const std::string listed =
      mesh_groups.empty() ? "none" : fmt::format("{}", fmt::join(mesh_groups, ", "));
  for (const BoundaryCondition& bc : c.flow.boundaries) {
    if (std::find(mesh_groups.begin(), mesh_groups.end(), bc.group) != mesh_groups.end()) continue;
    const std::string at = bc.line > 0 ? fmt::format("{}:{}", where, bc.line) : where;
    throw_input_error(
        "{}: flow.boundaries.{}: the mesh has no boundary group '{}'; its groups "
        "are: {}",
        at, bc.group, bc.group, listed);
  }
  for (const std::string& group : mesh_groups) {
    const auto has_condition = [&](const BoundaryCondition& bc) { return bc.group == group; };
    if (std::any_of(c.flow.boundaries.begin(), c.flow.boundaries.end(), has_condition)) continue;
    throw_input_error(
        "{}: flow.boundaries: the mesh's boundary group '{}' has no condition; "
        "every group needs one (a bank or a pier: '{}: {{type: wall}}'); the "
        "mesh's groups are: {}",
        where, group, group, listed);
  }
}

}  // namespace flotsam
