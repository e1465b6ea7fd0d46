#include "bodies/batch_integration.hpp"

#include <cmath>

#include "bodies/body_step.hpp"
#include "core/vector_clones.hpp"

#define FLOTSAM_INLINE [[gnu::always_inline]] inline

namespace flotsam {

namespace {

constexpr int W = batch_width;

/// A batch in flight: its bodies, the flow at them, and each lane's axis reference.
struct Batch {
  BatchBodies bodies;
  BatchFlow at_G, at_point;
  alignas(64) Lanes ref_theta, ref_x, ref_y;  // AxisReference per lane
  alignas(64) Lanes axis_x, axis_y;
  alignas(64) Lanes point_x, point_y, fraction;  // a drag point and its share
  alignas(64) Lanes displaced;                   // m_f [kg]
  int hint[W];

  void set_reference(int k, double theta) {
    const AxisReference r(theta);
    ref_theta[k] = r.theta, ref_x[k] = r.axis.x(), ref_y[k] = r.axis.y();
  }
};

/// f(t, y) of (M-5) for the lanes in `active` into dy (other lanes' dy: anything), and their
/// loads when `loads` is given: body_motion.cpp's body_derivative lane by lane.
FLOTSAM_INLINE void evaluate(Batch& B, const BodySet& set, const FlowField& flow,
                             const ForceModel& model, const Lanes& t, const BatchVector& y,
                             const bool* active, BatchVector& dy, BodyLoads* loads) {
  // The axis from each lane's reference (AxisReference::at).
#pragma omp simd
  for (int k = 0; k < W; ++k) {
    const double d = y.c[2][k] - B.ref_theta[k];
    double c, s;
    small_turn(d, c, s);
    const bool same = d == 0.0;
    B.axis_x[k] = same ? B.ref_x[k] : c * B.ref_x[k] - s * B.ref_y[k];
    B.axis_y[k] = same ? B.ref_y[k] : s * B.ref_x[k] + c * B.ref_y[k];
  }
  for (int k = 0; k < W; ++k)
    if (std::abs(y.c[2][k] - B.ref_theta[k]) > 0.05) {
      B.axis_x[k] = std::cos(y.c[2][k]);
      B.axis_y[k] = std::sin(y.c[2][k]);
    }

  // The flow, once per lane at G; the displaced mass (spec 2; any for a lane that is idle or
  // outside, whose derivative is dropped or zero).
  flow.sample_batch(y.c[0], y.c[1], t, active, B.hint, B.at_G);
  for (int k = 0; k < W; ++k) {
    const double H = B.at_G.H[k], d = B.bodies.draft[k];
    const bool floating = H > d && B.bodies.can_float[k] != 0.0;
    B.displaced[k] =
        floating || B.at_G.inside[k] == 0.0
            ? B.bodies.mass[k]
            : model.rho * set.submerged_volume(B.bodies.index[k], std::clamp(H, 0.0, d));
  }

  // Drag (M-6, M-7): at G with the flow there, or summed over the drag points, each with its
  // own flow (drag_on_body). One call site of the kernel, in the loop: GCC vectorised it there
  // but not in a branch of its own.
  BatchDrag drag;
  const int N = std::max(1, model.physics.drag_points);
  for (int slice = 0; slice < N; ++slice) {
    if (N == 1) {
      for (int k = 0; k < W; ++k) {
        B.point_x[k] = y.c[0][k], B.point_y[k] = y.c[1][k];
        B.fraction[k] = 1.0;
      }
    } else {
      bool sampled[W];
      int hints[W];  // each point walks from G's element, which keeps it
      for (int k = 0; k < W; ++k) {
        const double L = B.bodies.length[k];
        const double s_k = (slice + 0.5) * L / N - 0.5 * L;  // slice centre on the axis [m]
        const Vec2 x_k = Vec2(y.c[0][k], y.c[1][k]) + s_k * Vec2(B.axis_x[k], B.axis_y[k]);
        sampled[k] = active[k] && B.at_G.inside[k] != 0.0;
        hints[k] = B.hint[k];
        B.point_x[k] = x_k.x(), B.point_y[k] = x_k.y();
        B.fraction[k] = 1.0 / N;
      }
      flow.sample_batch(B.point_x, B.point_y, t, sampled, hints, B.at_point);
    }
    add_slice_drag(B.bodies, N == 1 ? B.at_G : B.at_point, B.point_x, B.point_y, B.fraction, y,
                   B.axis_x, B.axis_y, model, drag);
  }

  // (M-5): the floating lanes here, the grounded ones in body_motion.cpp's finish_derivative.
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < W; ++k) dy.c[c][k] = y.c[c + 3][k];
  BatchLoads water;
  float_derivative(B.bodies, B.at_G, y, drag, B.displaced, model, dy, water);
  for (int k = 0; k < W; ++k) {
    if (!active[k]) continue;
    const bool inside = B.at_G.inside[k] != 0.0;
    if (inside && water.floating[k] == 0.0) {
      const Vec2 u_p(y.c[3][k], y.c[4][k]);
      const WaterLoads w{u_p,
                         y.c[5][k],
                         false,
                         water.m_f[k],
                         {water.Du_x[k], water.Du_y[k]},
                         {water.fluid_x[k], water.fluid_y[k]},
                         {{drag.fx[k], drag.fy[k]}, drag.torque[k], drag.rate[k]},
                         water.T_rot[k],
                         {B.at_G.zb_x[k], B.at_G.zb_y[k]},
                         {B.at_G.u[k], B.at_G.v[k]}};
      BodyStateVector dy_k;
      finish_derivative(set, B.bodies.index[k], model, w, dy_k, loads ? &loads[k] : nullptr);
      for (int c = 3; c < 6; ++c) dy.c[c][k] = dy_k[c];
    } else if (loads) {
      BodyLoads& l = loads[k];
      l = BodyLoads{};
      l.outside = !inside;
      if (inside) {
        l.drag = {drag.fx[k], drag.fy[k]};
        l.fluid = {water.fluid_x[k], water.fluid_y[k]};
        l.reaction = {water.reaction_x[k], water.reaction_y[k]};
        l.drag_rate = drag.rate[k];
        l.added_mass = model.physics.added_mass_coefficient * water.m_f[k];
        l.fluid_acceleration = {water.Du_x[k], water.Du_y[k]};
        l.flow_velocity = {B.at_G.u[k], B.at_G.v[k]};
        l.torque = water.torque[k];
      }
    }
  }
}

/// Lane k of a batch vector as a state vector, and back.
BodyStateVector lane(const BatchVector& v, int k) {
  BodyStateVector y;
  for (int c = 0; c < 6; ++c) y[c] = v.c[c][k];
  return y;
}
void set_lane(BatchVector& v, int k, const BodyStateVector& y) {
  for (int c = 0; c < 6; ++c) v.c[c][k] = y[c];
}

}  // namespace

FLOTSAM_VECTOR_CLONES
void batch_derivative(const BodySet& bodies, const int* list, int n, const FlowField& flow,
                      const ForceModel& model, const Lanes& t, const BatchVector& y, int* hints,
                      BatchVector& dy, BodyLoads* loads) {
  Batch B;
  B.bodies.gather(bodies, list, n, model.rho);
  bool active[W];
  for (int k = 0; k < W; ++k) {
    B.set_reference(k, bodies.angle[B.bodies.index[k]]);
    B.hint[k] = hints[k];
    active[k] = k < n;
  }
  evaluate(B, bodies, flow, model, t, y, active, dy, loads);
  for (int k = 0; k < n; ++k) hints[k] = B.hint[k];
}

FLOTSAM_VECTOR_CLONES
void advance_batch(BodySet& bodies, const int* list, int n, const FlowField& flow, double ta,
                   double tb, double step_span, const ForceModel& model, double min_step_fraction,
                   long& accepted, long& rejected) {
  using F = Fehlberg;
  Batch B;
  B.bodies.gather(bodies, list, n, model.rho);
  Rkf45Options<6> options[W];
  Rkf45Counters counters[W];
  BodyLoads loads[W];
  alignas(64) Lanes t = {}, h = {}, t_stage = {}, step = {}, h_try = {};
  bool done[W], need_k1[W], active[W], lands[W];
  // Written lane by lane before they are read, but for k1 in the lanes past n, which are never
  // active: zero, so that every lane computes on numbers.
  BatchVector y, k[6], y_stage, dy, y5, err;
  k[0] = BatchVector{};
  for (int j = 0; j < W; ++j) {
    const int i = B.bodies.index[j];
    options[j] = body_step_options(bodies, i, model, min_step_fraction, ta, tb, step_span);
    set_lane(y, j, body_state(bodies, i));
    B.set_reference(j, bodies.angle[i]);  // the axis at the current step's start
    B.hint[j] = bodies.element_hint[i];
    const double h0 = bodies.step_size[i];
    h[j] = std::clamp(h0 > 0.0 ? h0 : tb - ta, options[j].h_min, options[j].h_max);
    t[j] = ta;
    done[j] = j >= n || !(ta < tb);
    need_k1[j] = true;
  }
  for (;;) {
    // k1 where a sub-step starts (rkf45_integrate's `first`: the loads, a new axis reference).
    bool any = false;
    for (int j = 0; j < W; ++j) {
      active[j] = !done[j] && need_k1[j];
      any = any || active[j];
      if (active[j] && y.c[2][j] != B.ref_theta[j]) B.set_reference(j, y.c[2][j]);
    }
    if (any) {
      evaluate(B, bodies, flow, model, t, y, active, dy, loads);
      for (int c = 0; c < 6; ++c)
        for (int j = 0; j < W; ++j)
          if (active[j]) k[0].c[c][j] = dy.c[c][j];
    }
    // The trial step of every body not done (rkf45_integrate: no step bound but h_min).
    any = false;
    for (int j = 0; j < W; ++j) {
      active[j] = !done[j];
      any = any || active[j];
      h_try[j] = std::min(h[j], std::max(options[j].h_min, 1e300));
      lands[j] = h_try[j] >= tb - t[j];
      step[j] = lands[j] ? tb - t[j] : h_try[j];
    }
    if (!any) break;
    for (int i = 1; i < 6; ++i) {  // rkf45_step's stages
      for (int c = 0; c < 6; ++c) {
#pragma omp simd
        for (int j = 0; j < W; ++j) {
          double yi = y.c[c][j];
          for (int m = 0; m < i; ++m) yi += (step[j] * F::a[i][m]) * k[m].c[c][j];
          y_stage.c[c][j] = yi;
        }
      }
#pragma omp simd
      for (int j = 0; j < W; ++j) t_stage[j] = t[j] + F::c[i] * step[j];
      evaluate(B, bodies, flow, model, t_stage, y_stage, active, k[i], nullptr);
    }
    for (int c = 0; c < 6; ++c) {
#pragma omp simd
      for (int j = 0; j < W; ++j) {
        double sum5 = 0.0, sum_e = 0.0;
        for (int i = 0; i < 6; ++i) {
          sum5 += F::b5[i] * k[i].c[c][j];
          sum_e += F::e[i] * k[i].c[c][j];
        }
        y5.c[c][j] = y.c[c][j] + step[j] * sum5;
        err.c[c][j] = step[j] * sum_e;
      }
    }
    // Each body's control (rkf45_integrate).
    for (int j = 0; j < W; ++j) {
      if (!active[j]) continue;
      const BodyStateVector y_j = lane(y, j);
      BodyStateVector y5_j = lane(y5, j);
      const double norm =
          rkf45_event_error_norm<6>(BodyStepHooks{loads[j]}, y_j, y5_j, lane(err, j), options[j]);
      if (rkf45_control(t[j], h[j], tb, h_try[j], step[j], lands[j], norm, options[j].h_min,
                        options[j].h_max, counters[j])) {
        set_lane(y, j, y5_j);
        need_k1[j] = true;
        done[j] = !(t[j] < tb);
      } else {
        need_k1[j] = false;  // retried from the same start: k1 stays
      }
    }
  }
  for (int j = 0; j < n; ++j) {
    const int i = B.bodies.index[j];
    set_body_state(bodies, i, lane(y, j));
    bodies.step_size[i] = h[j];
    record_loads(bodies, i, loads[j], B.hint[j]);
    accepted += counters[j].accepted;
    rejected += counters[j].rejected;
  }
}

}  // namespace flotsam
