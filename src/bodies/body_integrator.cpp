#include "bodies/body_integrator.hpp"

#include <algorithm>
#include <cmath>

#include "bodies/body_motion.hpp"
#include "bodies/rkf45.hpp"

namespace flotsam {

namespace {

/// Speed of a body's fastest point, |u_p| + |omega| L/2 [m/s].
double fastest_point_speed(double L, const BodyStateVector& y) {
  return y.segment<2>(3).norm() + std::abs(y[5]) * 0.5 * L;
}

/// The per-body hooks of rkf45_integrate: the l/4 step bound, friction stopping a grounded body
/// (spec 3.4: friction may stop a body within a step but not reverse it), and recording.
struct BodyStepHooks {
  const BodyLoads& loads;  // loads at the start of the current step
  double L, l;             // [m]

  double max_step(double /*t*/, const BodyStateVector& y) const {
    const double speed = fastest_point_speed(L, y);
    return speed > 0.0 ? 0.25 * l / speed : 1e300;  // moves < l/4 (spec 3.5)
  }

  bool event(const BodyStateVector& y, BodyStateVector& y_new) const {
    if (!loads.grounded) return false;
    bool stopped = false;
    if (y.segment<2>(3).squaredNorm() > 0.0 && y.segment<2>(3).dot(y_new.segment<2>(3)) < 0.0) {
      y_new.segment<2>(3).setZero();  // sliding would reverse: the body stops
      stopped = true;
    }
    if (y[5] != 0.0 && y[5] * y_new[5] < 0.0) {
      y_new[5] = 0.0;
      stopped = true;
    }
    return stopped;
  }

  void accepted(double /*t*/, const BodyStateVector& /*y*/) const {}
};

/// Keeps the loads of body i's last accepted sub-step, its element, and its state.
void record_loads(BodySet& bodies, int i, const BodyLoads& loads, int hint) {
  bodies.element_hint[i] = hint;
  bodies.drag_force[i] = loads.drag;
  bodies.bed_force[i] = loads.bed;
  bodies.reaction_force[i] = loads.reaction;
  bodies.torque[i] = loads.torque;
  if (!loads.outside) bodies.state[i] = loads.grounded ? BodyState::grounded : BodyState::floating;
}

}  // namespace

int BodyIntegrator::contact_intervals(const BodySet& bodies, double dt) const {
  double most = 0.0;  // largest (distance moved in dt) / (l/4); max is exact in any order
  for (int i = 0; i < bodies.size(); ++i) {
    if (bodies.state[i] == BodyState::gone) continue;
    const double speed =
        bodies.velocity[i].norm() + std::abs(bodies.angular_velocity[i]) * 0.5 * bodies.length[i];
    most = std::max(most, speed * dt / (0.25 * bodies.width[i]));
  }
  return std::clamp(static_cast<int>(std::ceil(most)), 1, options_.max_contact_intervals);
}

void BodyIntegrator::advance_body(BodySet& bodies, int i, const FlowField& flow, double ta,
                                  double tb, double step_span, long& accepted,
                                  long& rejected) const {
  int hint = bodies.element_hint[i];
  BodyLoads loads;
  if (bodies.anchored[i]) {  // held in place: the loads at rest at the interval's end, no motion
    AxisReference reference(bodies.angle[i]);
    BodyStateVector y = body_state(bodies, i);
    y.segment<3>(3).setZero();
    body_derivative(bodies, i, tb, y, flow, hint, model_, &loads, &reference);
    set_body_state(bodies, i, y);
    record_loads(bodies, i, loads, hint);
    return;
  }
  const double l = bodies.width[i];
  const double tol = model_.physics.rk_tolerance;

  // Weighted error norm (spec 3.5): positions to tol * l [m], angle to tol [rad]; velocities to
  // tol [m/s], [rad/s] plus tol relative.
  Rkf45Options<6> options;
  options.abs_tol << tol * l, tol * l, tol, tol, tol, tol;
  options.rel_tol << 0.0, 0.0, 0.0, tol, tol, tol;
  options.h_min = options_.min_step_fraction * step_span;
  options.h_max = tb - ta;

  AxisReference reference(bodies.angle[i]);  // the axis at the current step's start
  const auto f = [&](double t, const BodyStateVector& y) {
    return body_derivative(bodies, i, t, y, flow, hint, model_, nullptr, &reference);
  };
  const auto first = [&](double t, const BodyStateVector& y) {
    if (y[2] != reference.theta) reference = AxisReference(y[2]);
    return body_derivative(bodies, i, t, y, flow, hint, model_, &loads, &reference);
  };
  Rkf45Counters counters;
  double h = bodies.step_size[i];
  const BodyStateVector y = rkf45_integrate<6>(f, first, ta, tb, body_state(bodies, i), h, options,
                                               counters, BodyStepHooks{loads, bodies.length[i], l});
  set_body_state(bodies, i, y);
  bodies.step_size[i] = h;
  record_loads(bodies, i, loads, hint);
  accepted += counters.accepted;
  rejected += counters.rejected;
}

IntegrationStats BodyIntegrator::advance(BodySet& bodies, const FlowField& flow, double t0,
                                         double t1, const ContactHook& hook) const {
  IntegrationStats stats;
  const int K = hook ? contact_intervals(bodies, t1 - t0) : 1;
  stats.contact_intervals = K;
  const int n = bodies.size();
  for (int k = 0; k < K; ++k) {
    const double ta = t0 + (t1 - t0) * k / K;
    const double tb = k + 1 == K ? t1 : t0 + (t1 - t0) * (k + 1) / K;
    long accepted = 0, rejected = 0;
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : accepted, rejected) if (n >= 256)
    for (int i = 0; i < n; ++i) {
      if (bodies.state[i] == BodyState::gone) continue;
      advance_body(bodies, i, flow, ta, tb, t1 - t0, accepted, rejected);
    }
    stats.accepted += accepted;
    stats.rejected += rejected;
    if (hook) hook(tb, bodies);
  }
  return stats;
}

}  // namespace flotsam
