#include "render/scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "bodies/body_set.hpp"
#include "core/error.hpp"

namespace flotsam {

void SceneBodies::add(const Vec2& x_G, double theta, double L, double l,
                      BodyCategory category_of_body) {
  position.push_back(x_G);
  angle.push_back(theta);
  length.push_back(L);
  width.push_back(l);
  category.push_back(category_of_body);
}

SceneBodies scene_bodies(const BodySet& bodies, std::span<const std::uint8_t> jammed) {
  SceneBodies out;
  const int n = bodies.size();
  out.position = bodies.position;
  out.angle = bodies.angle;
  out.length = bodies.length;
  out.width = bodies.width;
  out.category.resize(n);
  for (int i = 0; i < n; ++i) {
    BodyCategory c = BodyCategory::floating;
    if (bodies.state[i] == BodyState::grounded) c = BodyCategory::grounded;
    if (i < static_cast<int>(jammed.size()) && jammed[i] != 0) c = BodyCategory::jammed;
    if (bodies.state[i] == BodyState::gone) c = BodyCategory::gone;
    out.category[i] = c;
  }
  return out;
}

BoundaryKind default_boundary_kind(const std::string& group_name) {
  for (const char* word : {"inflow", "outflow", "inlet", "outlet", "open"}) {
    if (group_name.find(word) != std::string::npos) return BoundaryKind::open;
  }
  return BoundaryKind::wall;
}

std::vector<BoundaryKind> boundary_kinds(const Mesh& mesh,
                                         std::span<const BoundaryCondition> conditions) {
  std::vector<BoundaryKind> kinds;
  for (const std::string& name : mesh.group_names) kinds.push_back(default_boundary_kind(name));
  for (const BoundaryCondition& condition : conditions) {
    const int group = mesh.find_group(condition.group);
    if (group < 0) continue;
    const bool wall = condition.kind == BoundaryCondition::Kind::wall ||
                      condition.kind == BoundaryCondition::Kind::noslip;
    kinds[group] = wall ? BoundaryKind::wall : BoundaryKind::open;
  }
  return kinds;
}

ViewWindow bounding_box(const Mesh& mesh) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  ViewWindow box{inf, -inf, inf, -inf};
  for (const Vec2& p : mesh.nodes) {
    box.x_min = std::min(box.x_min, p.x());
    box.x_max = std::max(box.x_max, p.x());
    box.y_min = std::min(box.y_min, p.y());
    box.y_max = std::max(box.y_max, p.y());
  }
  return box;
}

std::pair<double, double> resolve_colour_range(const Scene& scene, const ViewWindow& window) {
  const ColourRange& range = scene.range;
  double lo = range.min, hi = range.max;
  if (range.kind != ColourRange::Kind::fixed) {
    // Extremes over the nodes in the window; over all nodes when none is.
    const auto extremes = [&](bool only_inside) {
      constexpr double inf = std::numeric_limits<double>::infinity();
      double a = inf, b = -inf;
      const auto& values = scene.field.values;
      for (std::size_t k = 0; k < values.size(); ++k) {
        const Vec2& p = scene.mesh->nodes[k];
        const bool inside = p.x() >= window.x_min && p.x() <= window.x_max &&
                            p.y() >= window.y_min && p.y() <= window.y_max;
        if (std::isnan(values[k]) || (only_inside && !inside)) continue;
        a = std::min(a, values[k]);
        b = std::max(b, values[k]);
      }
      return std::pair{a, b};
    };
    std::tie(lo, hi) = extremes(true);
    if (lo > hi) std::tie(lo, hi) = extremes(false);
    if (lo > hi) lo = hi = 0.0;  // no value at all
    if (range.kind == ColourRange::Kind::symmetric) {
      hi = std::max(std::abs(lo), std::abs(hi));
      lo = -hi;
    }
  }
  if (!(hi > lo)) {
    const double c = 0.5 * (lo + hi);
    const double d = c == 0.0 ? 1.0 : 0.05 * std::abs(c);
    lo = c - d;
    hi = c + d;
  }
  return {lo, hi};
}

std::string format_clock(double seconds) {
  const long long total = std::llround(std::abs(seconds));
  const char* sign = seconds < 0.0 && total > 0 ? "-" : "";
  return fmt::format("{}{}:{:02d}:{:02d}", sign, total / 3600, (total / 60) % 60, total % 60);
}

void validate_scene(const Scene& scene) {
  const std::string what = fmt::format("picture '{}', field '{}'", scene.title, scene.field.name);
  if (scene.mesh == nullptr) throw_input_error("{}: no mesh given", what);
  const Mesh& mesh = *scene.mesh;
  const auto n = scene.field.values.size();
  if (n != static_cast<std::size_t>(mesh.vertex_count) &&
      n != static_cast<std::size_t>(mesh.node_count())) {
    throw_input_error("{}: {} values, expected {} (P1, one per vertex) or {} (P2, one per node)",
                      what, n, mesh.vertex_count, mesh.node_count());
  }
  if (scene.u_x.size() != scene.u_y.size() ||
      (!scene.u_x.empty() && scene.u_x.size() != static_cast<std::size_t>(mesh.node_count()))) {
    throw_input_error("{}: velocity has {} and {} values, expected {} each (P2) or none", what,
                      scene.u_x.size(), scene.u_y.size(), mesh.node_count());
  }
  if (!scene.wet.empty() && scene.wet.size() != static_cast<std::size_t>(mesh.node_count())) {
    throw_input_error("{}: {} wet flags, expected {} (one per node) or none", what,
                      scene.wet.size(), mesh.node_count());
  }
  if (!scene.u_x.empty() && !(scene.arrow_spacing >= 4.0)) {
    throw_input_error("{}: arrow spacing {} px, expected at least 4 px", what, scene.arrow_spacing);
  }
  const SceneBodies& b = scene.bodies;
  const auto bodies = b.position.size();
  if (b.angle.size() != bodies || b.length.size() != bodies || b.width.size() != bodies ||
      b.category.size() != bodies) {
    throw_input_error(
        "{}: body arrays of different lengths (position {}, angle {}, length {}, "
        "width {}, category {})",
        what, bodies, b.angle.size(), b.length.size(), b.width.size(), b.category.size());
  }
  if (scene.width < 64 || scene.height < 48 || scene.width > 16384 || scene.height > 16384) {
    throw_input_error("{}: image size {} x {} px, expected 64 x 48 to 16384 x 16384", what,
                      scene.width, scene.height);
  }
  if (scene.range.kind == ColourRange::Kind::fixed && !(scene.range.max > scene.range.min)) {
    throw_input_error("{}: colour range [{}, {}], expected min < max", what, scene.range.min,
                      scene.range.max);
  }
  if (scene.view &&
      !(scene.view->x_max > scene.view->x_min && scene.view->y_max > scene.view->y_min)) {
    throw_input_error("{}: view window x [{}, {}] y [{}, {}] m, expected min < max", what,
                      scene.view->x_min, scene.view->x_max, scene.view->y_min, scene.view->y_max);
  }
  if (scene.boundary_kinds.size() != 0 && scene.boundary_kinds.size() != mesh.group_names.size()) {
    throw_input_error("{}: {} boundary kinds, expected one per mesh group ({})", what,
                      scene.boundary_kinds.size(), mesh.group_names.size());
  }
}

}  // namespace flotsam
