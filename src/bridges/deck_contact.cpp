#include "bridges/deck_contact.hpp"

#include <algorithm>
#include <limits>

namespace flotsam {

void add_deck_faces(BoundarySegments& walls, const std::vector<Bridge>& bridges,
                    const std::vector<std::string>& group_names) {
  bool any = false;
  for (const Bridge& bridge : bridges) {
    if (!bridge.deck) continue;
    // From the right abutment to the left one: the water, upstream, on the segment's left.
    walls.add_banded_segment(bridge.face_start(), bridge.face_end(), bridge.deck_group,
                             bridge.deck->soffit, bridge.deck->obstacle_top());
    any = true;
  }
  if (!any) return;
  walls.group_names = group_names;
  walls.build_grid();
}

BodyLevels body_levels(const BodySet& bodies, const FlowField& flow, double t) {
  BodyLevels levels;
  levels.bottom.resize(static_cast<std::size_t>(bodies.size()));
  levels.top.resize(levels.bottom.size());
  for (int i = 0; i < bodies.size(); ++i) {
    int hint = bodies.element_hint[i];
    const FlowSample s = flow.sample(bodies.position[i], t, hint);
    const double bed = s.eta - s.H;  // [m]
    levels.bottom[i] = s.inside ? std::max(bed, s.eta - bodies.draft[i]) : 0.0;
    levels.top[i] = levels.bottom[i] + bodies.height[i];
  }
  return levels;
}

double lowest_bed_on_axis(const Bridge& bridge, const FlowField& flow, double t, int samples) {
  double lowest = std::numeric_limits<double>::infinity();  // [m]
  double open = 0.0;                                        // [m] the gaps' total width
  for (const Gap& gap : bridge.gaps) open += gap.width();
  int hint = -1;
  for (const Gap& gap : bridge.gaps) {
    const int n = std::max(1, static_cast<int>(samples * gap.width() / open));
    for (int k = 0; k < n; ++k) {
      const double s = gap.lower + (k + 0.5) / n * gap.width();  // [m]
      const FlowSample w = flow.sample(bridge.start + s * bridge.along, t, hint);
      if (w.inside) lowest = std::min(lowest, w.eta - w.H);
    }
  }
  return lowest;
}

}  // namespace flotsam
