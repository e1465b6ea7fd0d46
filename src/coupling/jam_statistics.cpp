#include "coupling/jam_statistics.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "bridges/bridge_layout.hpp"
#include "core/error.hpp"

namespace flotsam {

// ---- geometry -------------------------------------------------------------------------------

namespace {

int require_group(const std::vector<std::string>& group_names, const std::string& name,
                  const std::string& source) {
  const auto it = std::find(group_names.begin(), group_names.end(), name);
  if (it == group_names.end())
    throw_input_error("{}: the channel's boundary group '{}' is missing from the mesh (it has: {})",
                      source, name, fmt::join(group_names, ", "));
  return static_cast<int>(it - group_names.begin());
}

/// Each bridge's piers are piers, and know their bridge.
void mark_piers(JamGeometry& g) {
  for (std::size_t b = 0; b < g.bridges.size(); ++b)
    for (const int s : g.bridges[b].piers) {
      g.solids[s].kind = SolidKind::pier;
      g.solids[s].bridge = static_cast<int>(b);
    }
}

SolidKind kind_from_name(const std::string& name) {
  if (name.starts_with("pier")) return SolidKind::pier;
  if (name.starts_with("bank")) return SolidKind::bank;
  return SolidKind::wall;
}

}  // namespace

JamGeometry jam_geometry_from_channel(const ChannelGeometry& channel,
                                      const std::vector<std::string>& group_names,
                                      const std::string& source) {
  JamGeometry g;
  g.group_names = group_names;
  const int right_bank = 0, left_bank = 1;
  for (const char* bank : {"bank_right", "bank_left"})
    g.solids.push_back({require_group(group_names, bank, source), bank, SolidKind::bank, -1});
  std::vector<int> pier_solid(channel.piers.size());
  for (std::size_t p = 0; p < channel.piers.size(); ++p) {
    const std::string name = fmt::format("pier_{}", p + 1);
    pier_solid[p] = static_cast<int>(g.solids.size());
    g.solids.push_back({require_group(group_names, name, source), name, SolidKind::pier, -1});
  }
  g.bridges = channel_bridges(channel, pier_solid, right_bank, left_bank);
  mark_piers(g);
  return g;
}

JamGeometry jam_geometry_from_channel(const ChannelGeometry& channel, const Mesh& mesh) {
  return jam_geometry_from_channel(channel, mesh.group_names, mesh.source);
}

JamGeometry jam_geometry_from_groups(const Mesh& mesh, const std::vector<int>& solid_groups,
                                     const std::vector<BridgeConfig>& bridges) {
  JamGeometry g;
  g.group_names = mesh.group_names;
  std::vector<int> solid_of_group(mesh.group_names.size(), -1);
  for (const int group : solid_groups) {
    const std::string& name = mesh.group_names.at(static_cast<std::size_t>(group));
    solid_of_group.at(static_cast<std::size_t>(group)) = static_cast<int>(g.solids.size());
    g.solids.push_back({group, name, kind_from_name(name), -1});
  }
  g.bridges = bridges_on_mesh(bridges, mesh, solid_of_group);
  mark_piers(g);
  for (std::size_t b = 0; b < g.bridges.size(); ++b) {
    Bridge& bridge = g.bridges[b];
    if (!bridge.deck) continue;
    bridge.deck_group = static_cast<int>(g.group_names.size());
    g.group_names.push_back(bridge.name + "_deck");
    g.solids.push_back(
        {bridge.deck_group, g.group_names.back(), SolidKind::deck, static_cast<int>(b)});
  }
  return g;
}

JamGeometry jam_geometry_for(const MeshSource& source, const Mesh& mesh,
                             const std::vector<int>& solid_groups,
                             const std::vector<BridgeConfig>& bridges) {
  if (source.kind == MeshSource::Kind::channel)
    return jam_geometry_from_channel(source.channel, mesh);
  return jam_geometry_from_groups(mesh, solid_groups, bridges);
}

// ---- statistics -----------------------------------------------------------------------------

int JamStatistics::largest_jam() const {
  int largest = 0;
  for (const Jam& jam : jams) largest = std::max(largest, jam.body_count());
  return largest;
}

double covered_length(std::vector<std::pair<double, double>> intervals, double lower,
                      double upper) {
  // Clip to [lower, upper], sort by start, merge overlapping runs and add their lengths.
  for (auto& [lo, hi] : intervals) {
    lo = std::max(lo, lower);
    hi = std::min(hi, upper);
  }
  std::erase_if(intervals, [](const auto& iv) { return iv.second <= iv.first; });
  std::sort(intervals.begin(), intervals.end());
  double covered = 0.0;  // [m]
  double run_lo = 0.0, run_hi = 0.0;
  bool in_run = false;
  for (const auto& [lo, hi] : intervals) {
    if (in_run && lo <= run_hi) {
      run_hi = std::max(run_hi, hi);
      continue;
    }
    if (in_run) covered += run_hi - run_lo;
    run_lo = lo;
    run_hi = hi;
    in_run = true;
  }
  if (in_run) covered += run_hi - run_lo;
  return covered;
}

std::vector<std::pair<double, double>> axis_spans(const BodySet& bodies,
                                                  const std::vector<int>& members,
                                                  const Bridge& bridge) {
  std::vector<std::pair<double, double>> spans;
  for (const int i : members) {
    const double s = bridge.along_of(bodies.position[i]);
    const double h = footprint_half_extent_along(bodies, i, bridge.along);
    spans.emplace_back(s - h, s + h);
  }
  return spans;
}

namespace {

/// Union-find roots of the body-body contact graph, ignoring gone bodies.
std::vector<int> cluster_roots(const BodySet& bodies, const ContactReport& report) {
  const int n = bodies.size();
  std::vector<int> parent(static_cast<std::size_t>(n));
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& [a, b] : report.body_body) {
    if (bodies.state[a] == BodyState::gone || bodies.state[b] == BodyState::gone) continue;
    parent[root(a)] = root(b);
  }
  for (int i = 0; i < n; ++i) parent[i] = root(i);
  return parent;
}

/// The bridge a jam sits at: the one of its anchoring piers (the nearest to the jam's mean
/// position when they belong to several); without a pier anchor, the bridge whose band
/// d(axis) +- reach meets the jam's footprint extent along d and whose axis the jam's extent
/// along s meets (nearest when several); else -1. Distances along each bridge's own d.
int bridge_of(const Jam& jam, const BodySet& bodies, const JamGeometry& geometry,
              const std::vector<int>& solid_of_group) {
  Vec2 mean = Vec2::Zero();  // [m]
  for (const int i : jam.bodies)
    mean += bodies.position[i] / static_cast<double>(jam.bodies.size());
  std::vector<int> candidates;
  for (const int group : jam.anchors) {
    const int s = group < static_cast<int>(solid_of_group.size()) ? solid_of_group[group] : -1;
    if (s >= 0 && geometry.solids[s].bridge >= 0) candidates.push_back(geometry.solids[s].bridge);
  }
  if (candidates.empty()) {
    constexpr double infinity = std::numeric_limits<double>::infinity();
    for (int b = 0; b < static_cast<int>(geometry.bridges.size()); ++b) {
      const Bridge& bridge = geometry.bridges[b];
      double d_lo = infinity, d_hi = -infinity, s_lo = infinity, s_hi = -infinity;  // [m]
      for (const int i : jam.bodies) {
        const double d = bridge.downstream_of(bodies.position[i]);
        const double hd = footprint_half_extent_along(bodies, i, bridge.downstream);
        const double s = bridge.along_of(bodies.position[i]);
        const double hs = footprint_half_extent_along(bodies, i, bridge.along);
        d_lo = std::min(d_lo, d - hd), d_hi = std::max(d_hi, d + hd);
        s_lo = std::min(s_lo, s - hs), s_hi = std::max(s_hi, s + hs);
      }
      const double axis = bridge.axis_downstream();
      if (d_lo <= axis + bridge.reach && d_hi >= axis - bridge.reach && s_hi >= 0.0 &&
          s_lo <= bridge.length())
        candidates.push_back(b);
    }
  }
  int best = -1;
  double best_distance = 0.0;  // [m]
  for (const int b : candidates) {
    const Bridge& bridge = geometry.bridges[b];
    const double distance = std::abs(bridge.axis_downstream() - bridge.downstream_of(mean));
    if (best < 0 || distance < best_distance) best = b, best_distance = distance;
  }
  return best;
}

/// Fills each jam's bridge and gap blockage, and each bridge's total blockage: the union of the
/// spans along the axis of the footprints of its jams' bodies, clipped to each gap, summed over the
/// gaps and divided by the sum of the gap widths.
void measure_blockage(JamStatistics& stats, const BodySet& bodies, const JamGeometry& geometry,
                      const std::vector<int>& solid_of_group) {
  std::vector<std::vector<std::pair<double, double>>> bridge_spans(geometry.bridges.size());
  for (Jam& jam : stats.jams) {
    jam.bridge = bridge_of(jam, bodies, geometry, solid_of_group);
    if (jam.bridge < 0) continue;
    const auto spans = axis_spans(bodies, jam.bodies, geometry.bridges[jam.bridge]);
    for (const Gap& gap : geometry.bridges[jam.bridge].gaps)
      jam.gap_blockage.push_back(covered_length(spans, gap.lower, gap.upper) / gap.width());
    auto& all = bridge_spans[jam.bridge];
    all.insert(all.end(), spans.begin(), spans.end());
  }
  for (std::size_t b = 0; b < geometry.bridges.size(); ++b) {
    double covered = 0.0, total = 0.0;  // [m]
    for (const Gap& gap : geometry.bridges[b].gaps) {
      covered += covered_length(bridge_spans[b], gap.lower, gap.upper);
      total += gap.width();
    }
    stats.bridge_blockage.push_back(total > 0.0 ? covered / total : 0.0);
  }
}

/// released, passed, left, trapped, deposited, floating (docs/model.md, "Fate of the bodies").
void count_fates(JamStatistics& stats, const BodySet& bodies, const JamGeometry& geometry,
                 const std::vector<char>& in_jam) {
  stats.released = bodies.size();
  stats.left = static_cast<int>(bodies.outflow_count);
  for (int i = 0; i < bodies.size(); ++i) {
    const bool gone = bodies.state[i] == BodyState::gone;
    const bool beyond =
        geometry.bridges.empty() ? gone : geometry.passed_every_bridge(bodies.position[i]);
    stats.passed += !in_jam[i] && beyond;
    if (gone) continue;
    if (in_jam[i])
      ++stats.trapped;
    else if (bodies.state[i] == BodyState::grounded)
      ++stats.deposited;
    else
      ++stats.floating;
  }
}

}  // namespace

JamStatistics compute_jam_statistics(const BodySet& bodies, const ContactReport& report,
                                     const JamGeometry& geometry) {
  const int n = bodies.size();
  if (report.body_count > n)
    throw std::invalid_argument(fmt::format(
        "compute_jam_statistics: contact report of {} bodies for {} bodies", report.body_count, n));
  for (const auto& [a, b] : report.body_body)
    if (a < 0 || b >= n || a >= n || b < 0)
      throw std::invalid_argument(
          fmt::format("compute_jam_statistics: pair ({}, {}) of {} bodies", a, b, n));

  std::vector<int> solid_of_group(geometry.group_names.size(), -1);
  for (std::size_t s = 0; s < geometry.solids.size(); ++s)
    solid_of_group.at(static_cast<std::size_t>(geometry.solids[s].group)) = static_cast<int>(s);

  JamStatistics stats;
  stats.touching.assign(geometry.solids.size(), 0);
  stats.anchored.assign(geometry.solids.size(), 0);

  // Clusters of the body-body contact graph; a cluster is a jam when one of its bodies touches
  // a solid group. Jams are indexed by their root in the order of their smallest body.
  const std::vector<int> root = cluster_roots(bodies, report);
  std::vector<int> jam_of_root(static_cast<std::size_t>(n), -1);
  std::vector<std::vector<int>> anchors_of_root(static_cast<std::size_t>(n));
  for (const auto& [body, group] : report.body_group) {
    if (body < 0 || body >= n)
      throw std::invalid_argument(fmt::format("compute_jam_statistics: body {} of {}", body, n));
    if (bodies.state[body] == BodyState::gone) continue;
    anchors_of_root[root[body]].push_back(group);
    const int s = group < static_cast<int>(solid_of_group.size()) ? solid_of_group[group] : -1;
    if (s >= 0) ++stats.touching[s];
  }
  for (int i = 0; i < n; ++i) {
    auto& anchors = anchors_of_root[root[i]];
    if (anchors.empty()) continue;
    int& jam = jam_of_root[root[i]];
    if (jam < 0) {
      jam = static_cast<int>(stats.jams.size());
      std::sort(anchors.begin(), anchors.end());
      anchors.erase(std::unique(anchors.begin(), anchors.end()), anchors.end());
      stats.jams.push_back({.bodies = {},
                            .anchors = anchors,
                            .bridge = -1,
                            .gap_blockage = {},
                            .thickness = 0.0,
                            .gap_opening_closed = {}});
    }
    stats.jams[jam].bodies.push_back(i);
    stats.jams[jam].thickness = std::max(stats.jams[jam].thickness, bodies.wetted_height[i]);
  }
  for (const Jam& jam : stats.jams)
    for (const int group : jam.anchors) {
      const int s = group < static_cast<int>(solid_of_group.size()) ? solid_of_group[group] : -1;
      if (s >= 0) stats.anchored[s] += jam.body_count();
    }
  measure_blockage(stats, bodies, geometry, solid_of_group);

  std::vector<char> in_jam(static_cast<std::size_t>(n), 0);
  for (const Jam& jam : stats.jams)
    for (const int i : jam.bodies) in_jam[i] = 1;
  count_fates(stats, bodies, geometry, in_jam);
  return stats;
}

// ---- output ---------------------------------------------------------------------------------

std::vector<std::string> JamStatisticsWriter::columns(const JamGeometry& geometry,
                                                      bool with_backwater) {
  std::vector<std::string> names = {"time [s]",  "released", "passed", "left",       "trapped",
                                    "deposited", "floating", "jams",   "largest jam"};
  for (const Bridge& b : geometry.bridges) names.push_back("blockage " + b.name + " [-]");
  for (const Bridge& b : geometry.bridges) names.push_back("opening closed " + b.name + " [-]");
  if (with_backwater)
    for (const Bridge& b : geometry.bridges) names.push_back("backwater rise " + b.name + " [m]");
  for (const SolidGroup& s : geometry.solids) names.push_back("touching " + s.name);
  for (const SolidGroup& s : geometry.solids) names.push_back("anchored " + s.name);
  return names;
}

JamStatisticsWriter::JamStatisticsWriter(const std::string& path, const JamGeometry& geometry,
                                         bool with_backwater, std::optional<CsvResume> resume)
    : csv_(path, columns(geometry, with_backwater), resume),
      with_backwater_(with_backwater),
      bridge_count_(geometry.bridges.size()) {}

void JamStatisticsWriter::write(double t, const JamStatistics& s,
                                std::span<const double> backwater_rise) {
  const std::size_t expected = with_backwater_ ? bridge_count_ : 0;
  if (backwater_rise.size() != expected || s.bridge_blockage.size() != bridge_count_ ||
      s.bridge_opening_closed.size() != bridge_count_)
    throw std::invalid_argument(fmt::format(
        "JamStatisticsWriter '{}': {} backwater values, {} blockages and {} closed openings for "
        "{} bridges (backwater columns: {})",
        csv_.path(), backwater_rise.size(), s.bridge_blockage.size(),
        s.bridge_opening_closed.size(), bridge_count_, with_backwater_));
  std::vector<double> row = {t,
                             double(s.released),
                             double(s.passed),
                             double(s.left),
                             double(s.trapped),
                             double(s.deposited),
                             double(s.floating),
                             double(s.jams.size()),
                             double(s.largest_jam())};
  row.insert(row.end(), s.bridge_blockage.begin(), s.bridge_blockage.end());
  row.insert(row.end(), s.bridge_opening_closed.begin(), s.bridge_opening_closed.end());
  row.insert(row.end(), backwater_rise.begin(), backwater_rise.end());
  for (const int c : s.touching) row.push_back(c);
  for (const int c : s.anchored) row.push_back(c);
  csv_.row(row);
}

namespace {

template <class... Args>
void append_line(fmt::memory_buffer& out, fmt::format_string<Args...> format, Args&&... args) {
  fmt::format_to(std::back_inserter(out), format, std::forward<Args>(args)...);
  out.push_back('\n');
}

}  // namespace

std::string format_jam_summary(const JamStatistics& s, const JamGeometry& geometry,
                               std::span<const double> backwater_rise) {
  fmt::memory_buffer out;
  // Name columns as wide as the longest name (at least the paper's channel's widths).
  std::size_t bridge_width = 10, group_width = 12;
  for (const Bridge& b : geometry.bridges) bridge_width = std::max(bridge_width, b.name.size());
  for (const SolidGroup& g : geometry.solids) group_width = std::max(group_width, g.name.size());
  append_line(out, "bodies: {} released, {} passed, {} left, {} trapped, {} deposited, {} floating",
              s.released, s.passed, s.left, s.trapped, s.deposited, s.floating);
  if (!geometry.bridges.empty()) {
    append_line(out, "  {:<{}} {:>24} {:>5} {:>9} {:>14}{}", "bridge", bridge_width,
                "axis centre (x, y) [m]", "gaps", "blockage", "opening closed",
                backwater_rise.empty() ? "" : "  backwater rise [m]");
    for (std::size_t b = 0; b < geometry.bridges.size(); ++b) {
      const Bridge& bridge = geometry.bridges[b];
      const Vec2 centre = 0.5 * (bridge.start + bridge.end);
      const std::string rise =
          b < backwater_rise.size() ? fmt::format("  {:>18.4f}", backwater_rise[b]) : "";
      const std::string closed = b < s.bridge_opening_closed.size()
                                     ? fmt::format("{:.3f}", s.bridge_opening_closed[b])
                                     : "-";
      append_line(out, "  {:<{}} {:>24} {:>5} {:>9.3f} {:>14}{}", bridge.name, bridge_width,
                  fmt::format("({:.1f}, {:.1f})", centre.x(), centre.y()), bridge.gaps.size(),
                  s.bridge_blockage.at(b), closed, rise);
    }
  }
  append_line(out, "  {} jam{}, largest {} bodies", s.jams.size(), s.jams.size() == 1 ? "" : "s",
              s.largest_jam());
  if (!s.jams.empty()) {
    append_line(out, "  {:<4} {:>6} {:>13}  {:<24} {:<{}} {}", "jam", "bodies", "thickness [m]",
                "anchored on", "bridge", bridge_width, "gap blockage");
    for (std::size_t j = 0; j < s.jams.size(); ++j) {
      const Jam& jam = s.jams[j];
      std::vector<std::string> anchors;
      for (const int g : jam.anchors) anchors.push_back(geometry.group_names.at(g));
      append_line(out, "  {:<4} {:>6} {:>13.3f}  {:<24} {:<{}} {}", j + 1, jam.body_count(),
                  jam.thickness, fmt::format("{}", fmt::join(anchors, ", ")),
                  jam.bridge >= 0 ? geometry.bridges[jam.bridge].name : std::string("-"),
                  bridge_width, fmt::format("{:.3f}", fmt::join(jam.gap_blockage, " ")));
    }
  }
  if (!geometry.solids.empty()) {
    append_line(out, "  {:<{}} {:>8} {:>8}", "group", group_width, "touching", "anchored");
    for (std::size_t k = 0; k < geometry.solids.size(); ++k)
      append_line(out, "  {:<{}} {:>8} {:>8}", geometry.solids[k].name, group_width, s.touching[k],
                  s.anchored[k]);
  }
  return fmt::to_string(out);
}

}  // namespace flotsam
