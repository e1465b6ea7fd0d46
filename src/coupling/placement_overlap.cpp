#include "coupling/placement_overlap.hpp"

#include <fmt/format.h>

#include "contact/contact_world.hpp"

namespace flotsam {

std::vector<PlacementOverlap> placement_overlaps(const BodySet& bodies, double allowed) {
  std::vector<PlacementOverlap> overlaps;
  for (int a = 0; a < bodies.size(); ++a) {
    if (bodies.state[a] == BodyState::gone) continue;
    const Rectangle ra = body_rectangle(bodies, a);
    for (int b = a + 1; b < bodies.size(); ++b) {
      if (bodies.state[b] == BodyState::gone) continue;
      const double reach = ra.half.norm() + 0.5 * Vec2(bodies.length[b], bodies.width[b]).norm();
      if ((bodies.position[a] - bodies.position[b]).norm() >= reach) continue;
      const Manifold m = collide_rectangles(ra, body_rectangle(bodies, b), 0.0, 0.0);
      if (m.point_count > 0 && m.depth() > allowed) overlaps.push_back({a, b, m.depth()});
    }
  }
  return overlaps;
}

std::string describe_overlaps(const BodySet& bodies, const std::vector<PlacementOverlap>& overlaps,
                              const std::string& case_file) {
  std::string text;
  for (const PlacementOverlap& o : overlaps)
    text += fmt::format(
        "{}bodies {} and {} overlap by {:.3g} m where {} places them; the contacts push them "
        "apart in the first step",
        text.empty() ? "" : "\n", bodies.id[o.a], bodies.id[o.b], o.depth,
        case_file.empty() ? "the case" : case_file);
  return text;
}

}  // namespace flotsam
