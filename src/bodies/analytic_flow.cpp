#include "bodies/analytic_flow.hpp"

#include <algorithm>

namespace flotsam {

FlowSample AnalyticFlow::sample(const Vec2& p, double t, int& hint) const {
  FlowSample s;
  hint = 0;  // a single "element"
  const Vec2& lo = spec_.domain_min;
  const Vec2& hi = spec_.domain_max;
  if (p.x() < lo.x() || p.x() > hi.x() || p.y() < lo.y() || p.y() > hi.y()) {
    s.inside = false;
    s.boundary_group = p.x() < lo.x() ? 0 : p.x() > hi.x() ? 1 : p.y() < lo.y() ? 2 : 3;
    return s;
  }
  s.u = spec_.velocity + spec_.velocity_gradient * p + spec_.acceleration * t;
  s.grad_u = spec_.velocity_gradient;
  s.du_dt = spec_.acceleration;
  s.eta = spec_.eta + spec_.eta_rate * t;
  const double z_b = spec_.bed_level + spec_.bed_gradient.dot(p);
  s.H = std::max(s.eta - z_b, 0.0);
  s.grad_zb = spec_.bed_gradient;
  return s;
}

AnalyticFlow uniform_flow(const Vec2& u, double depth) {
  AnalyticFlowSpec spec;
  spec.velocity = u;
  spec.eta = depth;
  return AnalyticFlow(spec);
}

AnalyticFlow accelerating_flow(const Vec2& u0, const Vec2& a, double depth) {
  AnalyticFlowSpec spec;
  spec.velocity = u0;
  spec.acceleration = a;
  spec.eta = depth;
  return AnalyticFlow(spec);
}

AnalyticFlow shear_flow(double U, double shear_rate, double depth) {
  AnalyticFlowSpec spec;
  spec.velocity = {U, 0.0};
  spec.velocity_gradient(0, 1) = shear_rate;  // d u / d y
  spec.eta = depth;
  return AnalyticFlow(spec);
}

AnalyticFlow still_water_on_slope(double eta, double bed_level, const Vec2& bed_gradient) {
  AnalyticFlowSpec spec;
  spec.eta = eta;
  spec.bed_level = bed_level;
  spec.bed_gradient = bed_gradient;
  return AnalyticFlow(spec);
}

AnalyticFlow rising_water(double eta0, double rate, double bed_level, const Vec2& u) {
  AnalyticFlowSpec spec;
  spec.velocity = u;
  spec.eta = eta0;
  spec.eta_rate = rate;
  spec.bed_level = bed_level;
  return AnalyticFlow(spec);
}

}  // namespace flotsam
