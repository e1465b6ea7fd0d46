#include "ensemble/blocking_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace flotsam {

namespace {
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
}

std::vector<double> gap_cover(const JamStatistics& statistics, const BodySet& bodies,
                              const JamGeometry& geometry, int bridge) {
  // The intervals [s_G - h_s, s_G + h_s] along the axis of every body of every jam at the
  // bridge, their union clipped to each gap (covered_length), over the gap's width.
  const Bridge& b = geometry.bridges[bridge];
  std::vector<std::pair<double, double>> spans;
  for (const Jam& jam : statistics.jams) {
    if (jam.bridge != bridge) continue;
    const auto jam_spans = axis_spans(bodies, jam.bodies, b);
    spans.insert(spans.end(), jam_spans.begin(), jam_spans.end());
  }
  std::vector<double> cover;
  for (const Gap& gap : b.gaps)
    cover.push_back(covered_length(spans, gap.lower, gap.upper) / gap.width());
  return cover;
}

BlockingMonitor::BlockingMonitor(const JamGeometry& geometry, const BlockingCriterion& criterion)
    : geometry_(&geometry), criterion_(criterion) {
  bridges_.resize(geometry.bridges.size());
  for (const Bridge& line : geometry.bridges) {
    gaps_.emplace_back(line.gaps.size());
    streak_start_.emplace_back(line.gaps.size(), nan);
  }
}

void BlockingMonitor::note_new_bodies(const BodySet& bodies) {
  for (int i = static_cast<int>(start_.size()); i < bodies.size(); ++i)
    start_.push_back(bodies.position[i]);
}

void BlockingMonitor::sample(double t, const JamStatistics& statistics, const BodySet& bodies,
                             std::span<const double> rise) {
  for (std::size_t b = 0; b < bridges_.size(); ++b) {
    BridgeOutcome& bridge = bridges_[b];
    int bodies_at_bridge = 0;
    // [-] per gap: the jams' shares add up, to the whole opening at most (jams one behind the
    // other close it once; measure_opening_closure)
    std::vector<double> closed(gaps_[b].size(), 0.0);
    for (const Jam& jam : statistics.jams)
      if (jam.bridge == static_cast<int>(b)) {
        bodies_at_bridge += jam.body_count();
        bridge.largest_jam = std::max(bridge.largest_jam, jam.body_count());
        for (std::size_t g = 0; g < jam.gap_opening_closed.size(); ++g)
          closed[g] += jam.gap_opening_closed[g];
      }
    bridge.max_blockage = std::max(bridge.max_blockage, statistics.bridge_blockage[b]);
    if (b < statistics.bridge_opening_closed.size())
      bridge.max_opening_closed =
          std::max(bridge.max_opening_closed, statistics.bridge_opening_closed[b]);
    if (b < rise.size())
      bridge.max_rise = std::isnan(bridge.max_rise) ? rise[b] : std::max(bridge.max_rise, rise[b]);
    const std::vector<double> cover =
        gap_cover(statistics, bodies, *geometry_, static_cast<int>(b));
    for (std::size_t g = 0; g < cover.size(); ++g) {
      GapOutcome& gap = gaps_[b][g];
      double& streak = streak_start_[b][g];
      gap.max_cover = std::max(gap.max_cover, cover[g]);
      gap.max_opening_closed = std::max(gap.max_opening_closed, std::min(1.0, closed[g]));
      if (cover[g] < criterion_.fraction) {
        streak = nan;
        continue;
      }
      if (std::isnan(streak)) streak = t;
      if (gap.blocked || t - streak < criterion_.duration) continue;
      gap.blocked = true;
      gap.blocking_time = streak;
      if (!bridge.blocked || streak < bridge.blocking_time) {
        if (!bridge.blocked) bridge.blocking_bodies = bodies_at_bridge;
        bridge.blocked = true;
        bridge.blocking_time =
            std::isnan(bridge.blocking_time) ? streak : std::min(bridge.blocking_time, streak);
      }
    }
  }
}

void BlockingMonitor::finish(const JamStatistics& statistics, const BodySet& bodies,
                             MemberResult& result) const {
  result.bridges = bridges_;
  result.gaps = gaps_;
  result.released = statistics.released;
  result.passed = statistics.passed;
  result.left = statistics.left;
  result.trapped = statistics.trapped;
  result.stranded = statistics.deposited;
  result.floating = statistics.floating;
  std::vector<std::uint8_t> jammed(static_cast<std::size_t>(bodies.size()), 0);
  for (const Jam& jam : statistics.jams)
    for (int i : jam.bodies) jammed[i] = 1;
  result.bodies.clear();
  for (int i = 0; i < bodies.size(); ++i) {
    BodyOutcome body;
    body.id = bodies.id[i];
    body.start = i < static_cast<int>(start_.size()) ? start_[i] : bodies.position[i];
    body.end = bodies.position[i];
    if (bodies.state[i] == BodyState::gone)
      body.fate = BodyFate::left;
    else if (jammed[i])
      body.fate = BodyFate::trapped;
    else if (bodies.state[i] == BodyState::grounded)
      body.fate = BodyFate::stranded;
    body.passed =
        !jammed[i] && (geometry_->bridges.empty() ? bodies.state[i] == BodyState::gone
                                                  : geometry_->passed_every_bridge(body.end));
    result.bodies.push_back(body);
  }
}

}  // namespace flotsam
