#include "bridges/bridge_layout.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.hpp"
#include "mesh/point_locator.hpp"

namespace flotsam {

// ---- the paper's channel --------------------------------------------------------------------

namespace {

/// Pier indices grouped into lines across the channel: sorted by centre x, a pier joins the line
/// of the previous one when their x differ by less than the smaller radius.
std::vector<std::vector<int>> group_into_lines(const std::vector<Pier>& piers) {
  std::vector<int> order(piers.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return piers[a].centre.x() < piers[b].centre.x(); });
  std::vector<std::vector<int>> lines;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Pier& p = piers[order[k]];
    const Pier* previous = k > 0 ? &piers[order[k - 1]] : nullptr;
    if (previous == nullptr ||
        p.centre.x() - previous->centre.x() >= std::min(p.radius, previous->radius))
      lines.emplace_back();
    lines.back().push_back(order[k]);
  }
  return lines;
}

/// The free gaps of one line, walked by y: bank_right (y <= 0), the piers' y-intervals
/// [y_c - r, y_c + r], bank_left (y >= width); overlapping obstacles leave no gap between them.
std::vector<Gap> line_gaps(const std::vector<Pier>& piers, std::vector<int>& line, double width,
                           int right_bank, int left_bank, const std::vector<int>& pier_solid) {
  std::sort(line.begin(), line.end(),
            [&](int a, int b) { return piers[a].centre.y() < piers[b].centre.y(); });
  std::vector<Gap> gaps;
  double cursor = 0.0;  // [m] upper end of the obstacles so far
  int cursor_solid = right_bank;
  for (const int p : line) {
    const double lower = piers[p].centre.y() - piers[p].radius;
    const double upper = piers[p].centre.y() + piers[p].radius;
    if (lower > cursor) gaps.push_back({cursor, lower, cursor_solid, pier_solid[p]});
    if (upper >= cursor) {
      cursor = upper;
      cursor_solid = pier_solid[p];
    }
  }
  if (width > cursor) gaps.push_back({cursor, width, cursor_solid, left_bank});
  return gaps;
}

}  // namespace

std::vector<Bridge> channel_bridges(const ChannelGeometry& channel,
                                    const std::vector<int>& pier_solid, int right_bank,
                                    int left_bank) {
  std::vector<Bridge> bridges;
  for (std::vector<int>& line : group_into_lines(channel.piers)) {
    Bridge bridge;
    bridge.name = fmt::format("bridge_{}", bridges.size() + 1);
    double x = 0.0;  // [m]
    for (const int p : line) {
      x += channel.piers[p].centre.x() / static_cast<double>(line.size());
      bridge.reach = std::max(bridge.reach, channel.piers[p].radius);
    }
    bridge.start = Vec2(x, 0.0);
    bridge.end = Vec2(x, channel.width);
    bridge.along = Vec2(0.0, 1.0);
    bridge.downstream = Vec2(1.0, 0.0);
    bridge.backwater_distance = 4.0 * bridge.reach;  // two diameters of the widest pier
    bridge.gaps = line_gaps(channel.piers, line, channel.width, right_bank, left_bank, pier_solid);
    for (const int p : line) bridge.piers.push_back(pier_solid[p]);
    bridges.push_back(std::move(bridge));
  }
  return bridges;
}

// ---- any mesh -------------------------------------------------------------------------------

namespace {

/// Where the axis meets the boundary: s along it [m], the group crossed (-1: an end of the axis),
/// and the order among crossings at the same s (the axis' start first, its end last).
struct Crossing {
  double s = 0.0;
  int group = -1;
  int rank = 0;
};

/// Parameter t in [0, 1] along p0 -> p1 where it meets q0 -> q1, or -1 when they do not meet
/// (parallel segments never do).
double segment_meets(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1) {
  const Vec2 r = p1 - p0, e = q1 - q0;
  const double denominator = cross(r, e);
  if (std::abs(denominator) <= 1e-14 * r.norm() * e.norm()) return -1.0;
  const double t = cross(q0 - p0, e) / denominator;
  const double u = cross(q0 - p0, r) / denominator;
  return t >= 0.0 && t <= 1.0 && u >= 0.0 && u <= 1.0 ? t : -1.0;
}

std::vector<Crossing> axis_crossings(const Bridge& bridge, const Mesh& mesh) {
  const double length = bridge.length();
  std::vector<Crossing> crossings = {{0.0, -1, -1}, {length, -1, 1}};
  for (const BoundaryEdge& edge : mesh.boundary) {
    const auto nodes = mesh.edge_nodes(edge.element, edge.local_edge);
    const double t =
        segment_meets(bridge.start, bridge.end, mesh.nodes[nodes[0]], mesh.nodes[nodes[1]]);
    if (t >= 0.0) crossings.push_back({t * length, edge.group, 0});
  }
  std::sort(crossings.begin(), crossings.end(), [](const Crossing& a, const Crossing& b) {
    return a.s != b.s ? a.s < b.s : a.rank < b.rank;
  });
  return crossings;
}

/// The largest distance from the axis of a node on the boundary of the groups marked in
/// `pier_group` [m].
double reach_of(const Bridge& bridge, const Mesh& mesh, const std::vector<char>& pier_group) {
  double reach = 0.0;
  for (const BoundaryEdge& edge : mesh.boundary) {
    if (!pier_group[edge.group]) continue;
    for (const int n : mesh.edge_nodes(edge.element, edge.local_edge))
      reach = std::max(reach, std::abs(bridge.downstream.dot(mesh.nodes[n] - bridge.start)));
  }
  return reach;
}

Bridge bridge_on_mesh(const BridgeConfig& config, const Mesh& mesh,
                      const std::vector<int>& solid_of_group, const PointLocator& locator) {
  Bridge bridge;
  bridge.name = config.name;
  bridge.start = config.start;
  bridge.end = config.end;
  bridge.along = config.along();
  bridge.downstream = config.downstream();
  const auto solid = [&](int group) {
    return group >= 0 && group < static_cast<int>(solid_of_group.size()) ? solid_of_group[group]
                                                                         : -1;
  };
  const std::vector<Crossing> crossings = axis_crossings(bridge, mesh);
  const double tiny = 1e-9 * bridge.length();  // [m] shorter pieces are a vertex crossed twice
  std::vector<int> crossed_groups;
  for (std::size_t k = 0; k + 1 < crossings.size(); ++k) {
    const Crossing &a = crossings[k], &b = crossings[k + 1];
    if (a.group >= 0) crossed_groups.push_back(a.group);
    if (b.s - a.s <= tiny) continue;
    if (!locator.locate(bridge.start + 0.5 * (a.s + b.s) * bridge.along).inside) continue;
    bridge.gaps.push_back({a.s, b.s, solid(a.group), solid(b.group)});
  }
  if (bridge.gaps.empty())
    throw_input_error(
        "{}: the axis of bridge '{}' from ({}, {}) to ({}, {}) m crosses no water of the mesh "
        "'{}'; draw it across the river, from bank to bank",
        config.origin, config.name, config.start.x(), config.start.y(), config.end.x(),
        config.end.y(), mesh.source);
  // Piers: the obstacles between two gaps, then the groups the case names.
  const auto add_pier = [&](int s) {
    if (s >= 0 && std::find(bridge.piers.begin(), bridge.piers.end(), s) == bridge.piers.end())
      bridge.piers.push_back(s);
  };
  for (std::size_t k = 1; k < bridge.gaps.size(); ++k) {
    add_pier(bridge.gaps[k - 1].upper_solid);
    add_pier(bridge.gaps[k].lower_solid);
  }
  std::vector<char> pier_group(mesh.group_names.size(), 0);
  for (std::size_t g = 0; g < pier_group.size(); ++g)
    pier_group[g] = std::find(bridge.piers.begin(), bridge.piers.end(),
                              solid(static_cast<int>(g))) != bridge.piers.end();
  for (const std::string& name : config.pier_groups) {
    const int group = mesh.find_group(name);
    if (group < 0)
      throw_input_error("{}: bridge '{}': the mesh '{}' has no pier group '{}' (its groups: {})",
                        config.origin, config.name, mesh.source, name,
                        fmt::join(mesh.group_names, ", "));
    if (std::find(crossed_groups.begin(), crossed_groups.end(), group) == crossed_groups.end())
      throw_input_error(
          "{}: bridge '{}': its pier '{}' is off its axis, from ({}, {}) to ({}, {}) m; the "
          "axis must pass through every pier of the bridge",
          config.origin, config.name, name, config.start.x(), config.start.y(), config.end.x(),
          config.end.y());
    pier_group[group] = 1;
    add_pier(solid(group));
  }
  bridge.reach = reach_of(bridge, mesh, pier_group);
  bridge.deck = config.deck;
  if (bridge.deck) bridge.reach = std::max(bridge.reach, 0.5 * bridge.deck->width);
  bridge.backwater_distance =
      config.backwater_distance > 0.0 ? config.backwater_distance : 4.0 * bridge.reach;
  return bridge;
}

}  // namespace

std::vector<Bridge> bridges_on_mesh(const std::vector<BridgeConfig>& configs, const Mesh& mesh,
                                    const std::vector<int>& solid_of_group) {
  std::vector<Bridge> bridges;
  if (configs.empty()) return bridges;
  const PointLocator locator(mesh);
  for (std::size_t b = 0; b < configs.size(); ++b) {
    for (std::size_t a = 0; a < b; ++a)
      if (segment_meets(configs[a].start, configs[a].end, configs[b].start, configs[b].end) >= 0.0)
        throw_input_error("{}: the axis of bridge '{}' crosses that of bridge '{}' ({})",
                          configs[b].origin, configs[b].name, configs[a].name, configs[a].origin);
    bridges.push_back(bridge_on_mesh(configs[b], mesh, solid_of_group, locator));
  }
  return bridges;
}

}  // namespace flotsam
