// The case file's `bodies` section (docs/case-format.md, spec 2-5).
#include <fmt/format.h>

#include <limits>
#include <map>
#include <tuple>

#include "core/constants.hpp"
#include "io/case_sections.hpp"
#include "mesh/simple_polygon.hpp"

namespace flotsam {

namespace {

constexpr double radians_per_degree = pi / 180.0;  // [rad/deg]

// Practical ranges (docs/case-format.md "Ranges"): a log or a car is at most a few tens of
// metres; the densest solid (osmium) is 22 600 kg m^-3, the lightest wood (balsa) about 100.
const Range size_range = Range::up_to(1000.0);              // L, l, b [m]
const Range density_range = Range::between(10.0, 25000.0);  // rho_p [kg m^-3]

BodyPhysics read_physics(const YamlMap& m) {
  BodyPhysics p;
  if (const auto law = m.find("drag_law")) {
    p.drag_law =
        law->choice<DragLaw>({{"ganser", DragLaw::ganser}, {"constant", DragLaw::constant}});
  }
  if (p.drag_law == DragLaw::constant)
    p.drag_coefficient = m.number("drag_coefficient", p.drag_coefficient, Range::positive());
  else
    m.forbid("drag_coefficient", "only used with drag_law 'constant' (ganser computes C_d)");
  p.added_mass_coefficient =
      m.number("added_mass_coefficient", p.added_mass_coefficient, Range::non_negative());
  p.center_of_pressure = m.boolean("center_of_pressure", p.center_of_pressure);
  p.drag_points =
      static_cast<int>(m.integer("drag_points", p.drag_points, Range::between(1, 1000)));
  p.rotation_coefficient =
      m.number("rotation_coefficient", p.rotation_coefficient, Range::non_negative());
  p.bed_friction = m.number("bed_friction", p.bed_friction, Range::non_negative());
  p.rk_tolerance = m.number("rk_tolerance", p.rk_tolerance, Range::positive());
  return p;
}

JamConfig read_jams(const YamlMap& m) {
  JamConfig j;
  if (const auto extent = m.find("vertical_extent"))
    j.vertical_extent = extent->choice<JamExtent>(
        {{"layer", JamExtent::layer}, {"accumulation", JamExtent::accumulation}});
  if (j.vertical_extent == JamExtent::accumulation)
    j.porosity = m.number("porosity", j.porosity, Range{0.0, 1.0, false, true});
  else
    m.forbid("porosity", "only used with vertical_extent 'accumulation'");
  return j;
}

// Each solver's own settings are refused with the other (docs/case-format.md).
ContactConfig read_contact(const YamlMap& m) {
  ContactConfig c;
  if (const auto solver = m.find("solver")) {
    c.solver = solver->choice<ContactSolverKind>(
        {{"sequential_impulses", ContactSolverKind::sequential_impulses},
         {"soft_step", ContactSolverKind::soft_step}});
  }
  c.restitution = m.number("restitution", c.restitution, Range::between(0.0, 1.0));
  c.friction = m.number("friction", c.friction, Range::non_negative());
  c.added_mass_in_contact = m.boolean("added_mass_in_contact", c.added_mass_in_contact);
  c.restitution_threshold =
      m.number("restitution_threshold", c.restitution_threshold, Range::non_negative());
  c.allowed_overlap = m.number("allowed_overlap", c.allowed_overlap, Range{0.0, 1.0, false, true});
  c.sleep_time = m.number(
      "sleep_time", c.solver == ContactSolverKind::soft_step ? soft_step_sleep_time : c.sleep_time,
      Range::non_negative());
  c.sleep_speed = m.number("sleep_speed", c.sleep_speed, Range::positive());
  if (c.solver == ContactSolverKind::soft_step) {
    constexpr std::string_view why = "only used with solver 'sequential_impulses'";
    m.forbid("iterations", why);
    m.forbid("velocity_tolerance", why);
    m.forbid("position_iterations", why);
    c.substeps = static_cast<int>(m.integer("substeps", c.substeps, Range::between(1, 64)));
    c.contact_hertz = m.number("contact_hertz", c.contact_hertz, Range::positive());
    c.damping_ratio = m.number("damping_ratio", c.damping_ratio, Range::non_negative());
  } else {
    constexpr std::string_view why = "only used with solver 'soft_step'";
    m.forbid("substeps", why);
    m.forbid("contact_hertz", why);
    m.forbid("damping_ratio", why);
    c.iterations = static_cast<int>(m.integer("iterations", c.iterations, Range::between(1, 1e6)));
    c.velocity_tolerance = m.number("velocity_tolerance", c.velocity_tolerance, Range::positive());
    c.position_iterations = static_cast<int>(
        m.integer("position_iterations", c.position_iterations, Range::between(0, 1e6)));
  }
  return c;
}

Shape read_shape(const YamlMap& m) {
  const auto shape = m.find("shape");
  return shape ? shape->choice<Shape>({{"log", Shape::log}, {"box", Shape::box}}) : Shape::log;
}

// A log's height is its diameter; only a box has its own.
double read_height(const YamlMap& m, Shape shape, double width, double fallback) {
  if (shape == Shape::log) {
    m.forbid("height", "a log's height is its width (its diameter)");
    return width;
  }
  return m.number("height", fallback, size_range);
}

BodySpec read_body(const YamlValue& item) {
  const YamlMap m = item.map();
  BodySpec b;
  b.shape = read_shape(m);
  const auto length = m.find("length"), width = m.find("width");
  b.length = length ? length->number(size_range) : b.length;
  b.width = width ? width->number(size_range) : b.width;
  if (b.width > b.length) {  // blame the key the user gave
    (width    ? *width
     : length ? *length
              : item)
        .fail(fmt::format("the width {} m exceeds the length {} m; length is the long side",
                          b.width, b.length));
  }
  b.height = read_height(m, b.shape, b.width, b.height);
  b.density = m.number("density", b.density, density_range);
  b.position = {m.get("x", "x_G [m]").number(), m.get("y", "y_G [m]").number()};
  b.angle = m.number("angle_deg", 0.0) * radians_per_degree;
  b.velocity = {m.number("u", 0.0), m.number("v", 0.0)};
  b.angular_velocity = m.number("omega", 0.0);
  b.id = m.integer("id", b.id, Range::non_negative());
  b.anchored = m.boolean("anchored", b.anchored);
  return b;
}

// `key: value` or `key: [min, max]` with min <= max.
std::pair<double, double> read_span(const YamlMap& m, std::string_view key,
                                    std::pair<double, double> fallback, Range range) {
  const auto value = m.find(key);
  if (!value) return fallback;
  if (!value->is_list()) {
    const double x = value->number(range);
    return {x, x};
  }
  const auto items = value->list();
  if (items.size() != 2)
    value->fail(
        fmt::format("expected a number or a range [min, max], got a list of {}", items.size()));
  const double lo = items[0].number(range), hi = items[1].number(range);
  if (lo > hi)
    value->fail(fmt::format("expected [min, max] with min <= max, got [{}, {}]", lo, hi));
  return {lo, hi};
}

// Where a release puts its bodies: `line: [[x0, y0], [x1, y1]]` or `zone: [[x, y], ...]`, a
// simple polygon (mesh/simple_polygon.hpp).
void read_release_place(const YamlValue& item, Release& r) {
  const YamlMap m = item.map();
  const std::string place = m.only_one_of({"line", "zone"});
  if (place.empty()) {
    m.check_keys();  // a misspelt 'line' or 'zone' is reported as such
    m.fail("expected a release line 'line: [[x0, y0], [x1, y1]]' or a zone 'zone: [[x, y], ...]'");
  }
  if (place == "line") {
    const YamlValue line = m.get("line");
    const auto ends = line.list();
    if (ends.size() != 2)
      line.fail(fmt::format("expected two points [[x0, y0], [x1, y1]], got {}", ends.size()));
    r.line_start = ends[0].vec2();
    r.line_end = ends[1].vec2();
    r.source_line = item.line();
    return;
  }
  const YamlValue zone = m.get("zone");
  for (const YamlValue& corner : zone.list()) r.zone.push_back(corner.vec2());
  if (const std::string defect = polygon_defect(r.zone); !defect.empty()) zone.fail(defect);
  r.source_line = zone.line();
}

// When: `count` bodies at once at `start`, or `rate` bodies per minute from `start` to `end`.
void read_release_times(const YamlMap& m, Release& r) {
  r.start_time = m.number("start", r.start_time, Range::non_negative());
  if (const auto count = m.find("count")) {
    r.count = count->integer(Range::between(1, 1e6));
    m.forbid("rate", "a release with a count puts all its bodies at once at 'start'");
    m.forbid("end", "a release with a count puts all its bodies at once at 'start'");
    return;
  }
  const YamlValue end =
      m.get("end", "the time the release stops [s] (or give a 'count' of bodies at once)");
  r.end_time = end.number(Range{r.start_time, std::numeric_limits<double>::infinity(), true});
  r.rate = m.get("rate", "bodies per minute").number(Range::positive());
}

Release read_release(const YamlValue& item) {
  const YamlMap m = item.map();
  Release r;
  read_release_times(m, r);
  r.shape = read_shape(m);
  std::tie(r.length_min, r.length_max) =
      read_span(m, "length", {r.length_min, r.length_max}, size_range);
  std::tie(r.width_min, r.width_max) =
      read_span(m, "width", {r.width_min, r.width_max}, size_range);
  if (r.width_max > r.length_min) {
    item.fail(
        fmt::format("the widest body ({} m) would exceed the shortest ({} m); length is "
                    "the long side",
                    r.width_max, r.length_min));
  }
  r.height = read_height(m, r.shape, r.width_max, r.height);
  std::tie(r.density_min, r.density_max) =
      read_span(m, "density", {r.density_min, r.density_max}, density_range);
  std::tie(r.angle_min_deg, r.angle_max_deg) =
      read_span(m, "angle_deg", {r.angle_min_deg, r.angle_max_deg}, Range::any());
  r.seed = static_cast<unsigned long>(
      m.integer("seed", static_cast<long>(r.seed), Range::non_negative()));
  read_release_place(item, r);  // last: with every other key read, a misspelt one is reported
  return r;
}

}  // namespace

BodiesConfig read_bodies(const YamlMap& m) {
  BodiesConfig bodies;
  bodies.physics = read_physics(m.map("physics"));
  bodies.contact = read_contact(m.map("contact"));
  bodies.jams = read_jams(m.map("jams"));
  std::map<long, int> id_lines;  // id -> line where given
  if (const auto list = m.find("list")) {
    for (const YamlValue& item : list->list()) {
      bodies.bodies.push_back(read_body(item));
      const long id = bodies.bodies.back().id;
      if (id < 0) continue;
      const YamlValue id_value = item.map().get("id");
      if (const auto [it, inserted] = id_lines.emplace(id, id_value.line()); !inserted)
        id_value.fail(fmt::format("id {} is already used by the body on line {}", id, it->second));
    }
  }
  if (const auto releases = m.find("release")) {
    for (const YamlValue& item : releases->list()) bodies.releases.push_back(read_release(item));
  }
  return bodies;
}

}  // namespace flotsam
