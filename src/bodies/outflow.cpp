#include "bodies/outflow.hpp"

#include <algorithm>

namespace flotsam {

OutflowResult remove_outflowing_bodies(BodySet& bodies, const FlowField& flow, double t,
                                       const std::vector<int>& outflow_groups) {
  OutflowResult result;
  for (int i = 0; i < bodies.size(); ++i) {
    if (bodies.state[i] == BodyState::gone) continue;
    const FlowSample s = flow.sample(bodies.position[i], t, bodies.element_hint[i]);
    if (s.inside) continue;
    const bool outflow = std::find(outflow_groups.begin(), outflow_groups.end(),
                                   s.boundary_group) != outflow_groups.end();
    if (!outflow) {
      result.stray.push_back(i);
      continue;
    }
    bodies.state[i] = BodyState::gone;
    bodies.velocity[i] = Vec2::Zero();
    bodies.angular_velocity[i] = 0.0;
    ++result.left;
  }
  bodies.outflow_count += result.left;
  return result;
}

}  // namespace flotsam
