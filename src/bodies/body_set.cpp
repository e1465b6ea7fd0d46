#include "bodies/body_set.hpp"

#include <algorithm>
#include <cmath>

#include "bodies/hydrodynamic_forces.hpp"
#include "core/constants.hpp"

namespace flotsam {

double log_segment_area(double diameter, double depth) {
  // Circle of radius r cut at depth d below its top... measured from its lowest point:
  // A(d) = r^2 acos((r - d)/r) - (r - d) sqrt(2 r d - d^2),  0 <= d <= 2r.
  const double r = 0.5 * diameter;
  const double d = std::clamp(depth, 0.0, diameter);
  return r * r * std::acos((r - d) / r) - (r - d) * std::sqrt(std::max(0.0, 2 * r * d - d * d));
}

double floating_draft(Shape shape, double width, double height, double density,
                      double water_density) {
  const double ratio = density / water_density;  // fraction of the volume under water
  if (ratio >= 1.0) return shape == Shape::log ? width : height;
  if (shape == Shape::box) return ratio * height;
  // Log: solve A(d) = ratio * pi l^2 / 4 by bisection (A is increasing in d).
  const double target = ratio * pi * width * width / 4.0;
  double lo = 0.0, hi = width;
  for (int it = 0; it < 100 && hi - lo > 1e-14 * width; ++it) {
    const double mid = 0.5 * (lo + hi);
    (log_segment_area(width, mid) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double body_surface(Shape shape, double length, double width, double height) {
  if (shape == Shape::log) return pi * width * length + 0.5 * pi * width * width;
  return 2.0 * (length * width + length * height + width * height);
}

double BodySet::submerged_volume(int i, double depth) const {
  const double h = std::clamp(depth, 0.0, height[i]);
  if (shape[i] == Shape::log) return log_segment_area(width[i], h) * length[i];
  return length[i] * width[i] * h;
}

int BodySet::add(const BodySpec& s) {
  const double b = s.shape == Shape::log ? s.width : s.height;
  const double volume = s.shape == Shape::log ? pi / 4.0 * s.width * s.width * s.length
                                              : s.length * s.width * s.height;  // V [m^3]
  const double m = s.density * volume;
  const double I = s.shape == Shape::log
                       ? m * (s.length * s.length / 12.0 + s.width * s.width / 16.0)
                       : m * (s.length * s.length + s.width * s.width) / 12.0;  // spec 2
  shape.push_back(s.shape);
  length.push_back(s.length);
  width.push_back(s.width);
  height.push_back(b);
  density.push_back(s.density);
  mass.push_back(m);
  inertia.push_back(I);
  draft.push_back(floating_draft(s.shape, s.width, b, s.density, water_density));
  wetted_height.push_back(draft.back());
  // Shape factors of (P-18): the equal-volume sphere d_v = (6 V / pi)^(1/3) and the sphericity
  // Theta = pi d_v^2 / S (surface of that sphere over the body's surface); the centre of
  // pressure's reach at alpha = 0 (M-7).
  const double d_v = std::cbrt(6.0 * volume / pi);
  const double Theta = pi * d_v * d_v / body_surface(s.shape, s.length, s.width, b);
  equal_volume_diameter.push_back(d_v);
  sphericity.push_back(Theta);
  ganser_K2.push_back(ganser_K2_factor(Theta));
  ganser_K1_term.push_back(2.0 / (3.0 * std::sqrt(Theta)));
  pressure_reach.push_back(0.1 * s.length * (1.0 - std::exp(3.0 * (1.0 - s.length / s.width))));
  id.push_back(s.id >= 0 ? s.id : next_id);
  next_id = std::max(next_id, id.back() + 1);
  position.push_back(s.position);
  angle.push_back(s.angle);
  velocity.push_back(s.velocity);
  angular_velocity.push_back(s.angular_velocity);
  state.push_back(BodyState::floating);
  element_hint.push_back(-1);
  anchored.push_back(s.anchored ? 1 : 0);
  step_size.push_back(0.0);
  drag_force.push_back(Vec2::Zero());
  bed_force.push_back(Vec2::Zero());
  reaction_force.push_back(Vec2::Zero());
  torque.push_back(0.0);
  drag_rate.push_back(0.0);
  added_mass.push_back(0.0);
  fluid_acceleration.push_back(Vec2::Zero());
  flow_velocity.push_back(Vec2::Zero());
  mean_acceleration.push_back(Vec2::Zero());
  water_force.push_back(Vec2::Zero());
  return size() - 1;
}

}  // namespace flotsam
