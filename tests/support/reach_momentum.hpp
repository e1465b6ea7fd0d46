#pragma once
// The momentum balance of a straight, flat, frictionless reach (Chow 1959, ch. 3) that the
// jam-at-a-bridge verification cases check: the momentum function of a cross-section, and the
// 1D depth upstream of an obstacle that takes a given force.
#include "core/constants.hpp"
#include "flow/flow_field.hpp"

namespace flotsam::test {

/// rho * integral across the section x of (h u^2 + g h^2 / 2) dy [N] on a channel y in [0, width]
/// over a flat bed at 0 (h = eta), by the midpoint rule over 200 points; `depth` gets the
/// section's mean depth [m].
inline double section_momentum(const FlowField& flow, double x, double width, double t,
                               double& depth) {
  constexpr int samples = 200;
  double sum = 0.0, h_sum = 0.0;
  int hint = -1;
  for (int k = 0; k < samples; ++k) {
    const FlowSample f = flow.sample(Vec2(x, width * (k + 0.5) / samples), t, hint);
    sum += f.H * f.u.x() * f.u.x() + 0.5 * gravity * f.H * f.H;
    h_sum += f.H;
  }
  depth = h_sum / samples;
  return water_density_default * sum * width / samples;
}

/// The depth [m] upstream whose momentum function per width, q^2 / h + g h^2 / 2, exceeds that
/// of depth h2 by `excess` [m^3/s^2] (the subcritical root, by Newton from h2).
inline double depth_upstream(double q, double h2, double excess) {
  const double target = q * q / h2 + 0.5 * gravity * h2 * h2 + excess;
  double h = h2;
  for (int k = 0; k < 50; ++k)
    h -= (q * q / h + 0.5 * gravity * h * h - target) / (gravity * h - q * q / (h * h));
  return h;
}

}  // namespace flotsam::test
