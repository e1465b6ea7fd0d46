#pragma once
// The flow at a batch of points laid out flat, one lane per point, as the bodies' vector loops
// read it (bodies/body_batch.hpp): what FlowField::sample_batch fills.
#include "flow/flow_field.hpp"

namespace flotsam {

/// Points per batch: one AVX-512 register of doubles, two AVX2, four SSE2 ones.
inline constexpr int batch_width = 8;

using Lanes = double[batch_width];

/// The flow at one point per lane (FlowSample's fields as lanes, but eta and boundary_group).
struct alignas(64) BatchFlow {
  alignas(64) Lanes inside;  // 1 inside the domain, 0 outside (then the rest is zero)
  alignas(64) Lanes H, u, v;
  alignas(64) Lanes g00, g01, g10, g11;  // grad_u(i, j)
  alignas(64) Lanes du_dt, dv_dt;
  alignas(64) Lanes zb_x, zb_y;

  void set(int k, const FlowSample& s) {
    inside[k] = s.inside ? 1.0 : 0.0;
    H[k] = s.H, u[k] = s.u.x(), v[k] = s.u.y();
    g00[k] = s.grad_u(0, 0), g01[k] = s.grad_u(0, 1), g10[k] = s.grad_u(1, 0);
    g11[k] = s.grad_u(1, 1);
    du_dt[k] = s.du_dt.x(), dv_dt[k] = s.du_dt.y();
    zb_x[k] = s.grad_zb.x(), zb_y[k] = s.grad_zb.y();
  }
};

/// The weight of the step's end state at time t in a step [t0, t0 + span], as the engines'
/// sample computes it, span > 0 ? std::clamp((t - t0) / span, 0.0, 1.0) : 1.0, but with
/// selects a vector loop can take (std::clamp(v, lo, hi) is v < lo ? lo : hi < v ? hi : v).
[[gnu::always_inline]] inline double time_weight(double t, double t0, double span) {
  const double v = (t - t0) / (span > 0.0 ? span : 1.0);
  const double clamped = v < 0.0 ? 0.0 : (1.0 < v ? 1.0 : v);
  return span > 0.0 ? clamped : 1.0;
}

}  // namespace flotsam
