#include "coupling/jam_extent.hpp"

#include <algorithm>
#include <cmath>

namespace flotsam {

double accumulation_thickness(double wood_volume, double covered_width, double porosity) {
  if (covered_width <= 0.0) return 0.0;
  return std::sqrt(wood_volume / ((1.0 - porosity) * covered_width));  // (M-J1)
}

void set_wetted_heights(BodySet& bodies, const JamStatistics& statistics,
                        const JamGeometry& geometry, const JamConfig& config) {
  bodies.wetted_height = bodies.draft;
  if (config.vertical_extent != JamExtent::accumulation) return;
  for (const Jam& jam : statistics.jams) {
    if (jam.bridge < 0) continue;
    const Bridge& bridge = geometry.bridges[jam.bridge];
    double covered = 0.0;  // w_c [m]
    for (std::size_t g = 0; g < bridge.gaps.size(); ++g)
      covered += jam.gap_blockage[g] * bridge.gaps[g].width();
    double wood = 0.0;  // V_s [m^3]
    for (const int i : jam.bodies) wood += bodies.submerged_volume(i, bodies.height[i]);
    const double T = accumulation_thickness(wood, covered, config.porosity);
    for (const int i : jam.bodies) bodies.wetted_height[i] = std::max(bodies.draft[i], T);
  }
}

namespace {

/// The top of a gap's opening [m]: the surface, or the soffit below it.
double opening_top(const GapLevel& level, const Bridge& bridge) {
  return bridge.deck ? std::min(level.surface, bridge.deck->soffit) : level.surface;
}

}  // namespace

double opening_height(const GapLevel& level, const Bridge& bridge) {
  return std::max(0.0, opening_top(level, bridge) - level.bed);
}

double closed_height(const GapLevel& level, const Bridge& bridge, double thickness) {
  const double bottom = std::max(level.bed, level.surface - thickness);  // [m] of the jam's band
  return std::max(0.0, opening_top(level, bridge) - bottom);
}

void measure_opening_closure(JamStatistics& stats, const JamGeometry& geometry,
                             const std::vector<std::vector<GapLevel>>& levels) {
  // [m^2] per bridge and gap: what the jams in it close, together
  std::vector<std::vector<double>> closed(geometry.bridges.size());
  for (std::size_t b = 0; b < geometry.bridges.size(); ++b)
    closed[b].assign(geometry.bridges[b].gaps.size(), 0.0);
  for (Jam& jam : stats.jams) {
    jam.gap_opening_closed.clear();
    if (jam.bridge < 0) continue;
    const Bridge& bridge = geometry.bridges[jam.bridge];
    for (std::size_t g = 0; g < bridge.gaps.size(); ++g) {
      const GapLevel& level = levels[jam.bridge][g];
      const double width = bridge.gaps[g].width(), opening = opening_height(level, bridge);
      const double area = jam.gap_blockage[g] * width * closed_height(level, bridge, jam.thickness);
      closed[jam.bridge][g] += area;
      jam.gap_opening_closed.push_back(opening > 0.0 ? area / (width * opening) : 0.0);
    }
  }
  stats.bridge_opening_closed.assign(geometry.bridges.size(), 0.0);
  for (std::size_t b = 0; b < geometry.bridges.size(); ++b) {
    double total = 0.0, shut = 0.0;  // [m^2] the openings' area, the part of it closed
    for (std::size_t g = 0; g < geometry.bridges[b].gaps.size(); ++g) {
      const double area =
          geometry.bridges[b].gaps[g].width() * opening_height(levels[b][g], geometry.bridges[b]);
      total += area;
      shut += std::min(closed[b][g], area);  // jams one behind the other close it once
    }
    stats.bridge_opening_closed[b] = total > 0.0 ? shut / total : 0.0;
  }
}

}  // namespace flotsam
