#include "bodies/incipient_motion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "bodies/bed_contact.hpp"

namespace flotsam {

double resting_weight(const BodySet& bodies, int i, double H, const ForceModel& model) {
  const double d = bodies.draft[i];
  if (H > d && bodies.density[i] < model.rho) return 0.0;  // floating (body_motion.cpp)
  const double m_f = model.rho * bodies.submerged_volume(i, std::clamp(H, 0.0, d));  // [kg]
  return effective_weight(bodies.mass[i], m_f, model.g);
}

double incipient_velocity(const BodySet& bodies, int i, const Current& current,
                          const ForceModel& model) {
  const double H = current.depth;
  const double need =
      model.physics.bed_friction * resting_weight(bodies, i, H, model) - current.other_force;
  if (need <= 0.0) return 0.0;  // [N]
  const double S_eff =
      effective_area(bodies.shape[i], bodies.length[i], bodies.width[i],
                     std::clamp(H, 0.0, bodies.draft[i]), std::abs(std::cos(current.incidence)),
                     std::abs(std::sin(current.incidence)));  // (M-6) [m^2]
  if (S_eff <= 0.0) return std::numeric_limits<double>::infinity();
  const auto drag = [&](double u) {  // (M-6) [N], increasing in u for both drag laws
    return 0.5 * model.rho * drag_coefficient(bodies, i, S_eff, u, model) * S_eff * u * u;
  };
  // Bracket u_c by doubling, then bisect to round-off.
  double lo = 0.0, hi = 1.0;  // [m/s]
  while (drag(hi) < need) {
    lo = hi;
    hi *= 2.0;
    if (hi > 1e6) return std::numeric_limits<double>::infinity();
  }
  for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (drag(mid) < need ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace flotsam
