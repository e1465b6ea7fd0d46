#include "bodies/loads_after_contacts.hpp"

#include "bodies/body_motion.hpp"
#include "bodies/body_step.hpp"

namespace flotsam {

void record_loads_after_contacts(BodySet& bodies, const std::vector<int>& held,
                                 const std::vector<Vec2>& start_velocity, const FlowField& flow,
                                 const ForceModel& model, double t1, double dt) {
  const int n = static_cast<int>(held.size());
  constexpr int parallel_bodies = 256;  // [-] as BodyIntegrator's
#pragma omp parallel for schedule(dynamic, 64) if (n >= parallel_bodies)
  for (int k = 0; k < n; ++k) {
    const int i = held[static_cast<std::size_t>(k)];
    if (bodies.state[i] == BodyState::gone || bodies.anchored[i]) continue;
    const Vec2 a_p = (bodies.velocity[i] - start_velocity[static_cast<std::size_t>(i)]) / dt;
    int hint = bodies.element_hint[i];
    BodyLoads loads;
    body_derivative(bodies, i, t1, body_state(bodies, i), flow, hint, model, &loads, nullptr, &a_p);
    record_loads(bodies, i, loads, hint);
  }
}

}  // namespace flotsam
