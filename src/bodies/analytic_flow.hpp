#pragma once
// Flows known in closed form, as FlowField implementations: what the body tests, the verification
// cases and the benchmark move bodies in before (and besides) the flow engines.
//
//   u(x, t)   = u_0 + G x + a t            (affine in space, linear in time)
//   eta(t)    = eta_0 + r t                 (a flat free surface that may rise)
//   z_b(x)    = z_0 + s . x                 (a plane bed)
//   H         = max(eta - z_b, 0)
//
// uniform, uniformly accelerating, shear, still water over a slope and rising water are special
// cases (the factory functions below). An optional rectangular domain gives `inside` and, for
// points out of it, the side crossed as boundary group 0 (x_min), 1 (x_max), 2 (y_min),
// 3 (y_max): the order of structured_mesh.hpp's "left", "right", "bottom", "top".
#include <limits>

#include "flow/flow_field.hpp"

namespace flotsam {

struct AnalyticFlowSpec {
  Vec2 velocity = Vec2::Zero();           // u_0 at x = 0, t = 0 [m/s]
  Mat2 velocity_gradient = Mat2::Zero();  // G(i, j) = d u_i / d x_j [1/s]
  Vec2 acceleration = Vec2::Zero();       // a = d u / d t [m/s^2]
  double eta = 10.0;                      // eta_0 [m]
  double eta_rate = 0.0;                  // r = d eta / d t [m/s]
  double bed_level = 0.0;                 // z_0, bed elevation at x = 0 [m]
  Vec2 bed_gradient = Vec2::Zero();       // s = grad z_b [-]
  Vec2 domain_min = Vec2::Constant(-std::numeric_limits<double>::infinity());  // [m]
  Vec2 domain_max = Vec2::Constant(std::numeric_limits<double>::infinity());   // [m]
};

class AnalyticFlow : public FlowField {
 public:
  explicit AnalyticFlow(const AnalyticFlowSpec& spec) : spec_(spec) {}

  FlowSample sample(const Vec2& p, double t, int& hint) const override;
  double time_begin() const override { return begin_; }
  double time_end() const override { return end_; }

  /// Sets the current flow step [t0, t1] (an analytic flow is valid at any time anyway).
  void set_step(double t0, double t1) {
    begin_ = t0;
    end_ = t1;
  }
  const AnalyticFlowSpec& spec() const { return spec_; }

 private:
  AnalyticFlowSpec spec_;
  double begin_ = 0.0;                                    // [s]
  double end_ = std::numeric_limits<double>::infinity();  // [s]
};

/// Uniform flow u over a flat bed at z = 0 with depth H [m].
AnalyticFlow uniform_flow(const Vec2& u, double depth);
/// u = u_0 + a t over a flat bed, depth H.
AnalyticFlow accelerating_flow(const Vec2& u0, const Vec2& a, double depth);
/// Simple shear u = (U + shear_rate y, 0), depth H; its spin is omega_f = -shear_rate/2.
AnalyticFlow shear_flow(double U, double shear_rate, double depth);
/// Still water at level eta over the plane bed z_b = bed_level + bed_gradient . x.
AnalyticFlow still_water_on_slope(double eta, double bed_level, const Vec2& bed_gradient);
/// Water rising at `rate` [m/s] from eta_0 over a flat bed at bed_level, flowing at u.
AnalyticFlow rising_water(double eta0, double rate, double bed_level, const Vec2& u);

}  // namespace flotsam
