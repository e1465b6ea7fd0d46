#include "bodies/body_integrator.hpp"

#include <algorithm>
#include <cmath>

#include "bodies/body_motion.hpp"
#include "bodies/rkf45.hpp"

namespace flotsam {

namespace {

/// The per-body hooks of rkf45_integrate: friction stopping a grounded body (spec 3.4: friction
/// may stop a body within a step but not reverse it), and recording. The step has no bound of its
/// own: the contact intervals (ContactWorld::plan) keep bodies that may touch from tunnelling.
struct BodyStepHooks {
  const BodyLoads& loads;  // loads at the start of the current step

  double max_step(double /*t*/, const BodyStateVector& /*y*/) const { return 1e300; }

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

ContactSchedule ContactSchedule::one_group(const BodySet& bodies, int intervals) {
  ContactSchedule schedule;
  ContactGroup& group = schedule.groups.emplace_back();
  group.intervals = intervals;
  for (int i = 0; i < bodies.size(); ++i)
    if (bodies.state[i] != BodyState::gone) group.bodies.push_back(i);
  schedule.at_end = group.bodies;
  return schedule;
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
                                               counters, BodyStepHooks{loads});
  set_body_state(bodies, i, y);
  bodies.step_size[i] = h;
  record_loads(bodies, i, loads, hint);
  accepted += counters.accepted;
  rejected += counters.rejected;
}

void BodyIntegrator::advance_bodies(BodySet& bodies, const std::vector<int>& list,
                                    const FlowField& flow, double ta, double tb, double step_span,
                                    IntegrationStats& stats) const {
  const int n = static_cast<int>(list.size());
  long accepted = 0, rejected = 0;
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : accepted, rejected) if (n >= 256)
  for (int k = 0; k < n; ++k) {
    const int i = list[k];
    if (bodies.state[i] == BodyState::gone) continue;
    advance_body(bodies, i, flow, ta, tb, step_span, accepted, rejected);
  }
  stats.accepted += accepted;
  stats.rejected += rejected;
}

IntegrationStats BodyIntegrator::advance(BodySet& bodies, const FlowField& flow, double t0,
                                         double t1, const ContactSchedule& schedule,
                                         const ContactHook& hook) const {
  IntegrationStats stats;
  stats.contact_intervals = 1;
  advance_bodies(bodies, schedule.free, flow, t0, t1, t1 - t0, stats);
  std::vector<double> last_interval(static_cast<std::size_t>(bodies.size()), t1 - t0);  // [s]
  for (const ContactGroup& group : schedule.groups) {
    const int K = group.intervals;
    stats.contact_intervals = std::max(stats.contact_intervals, K);
    stats.grouped += static_cast<int>(group.bodies.size());
    for (int k = 0; k < K; ++k) {
      const double ta = t0 + (t1 - t0) * k / K;
      const double tb = k + 1 == K ? t1 : t0 + (t1 - t0) * (k + 1) / K;
      advance_bodies(bodies, group.bodies, flow, ta, tb, t1 - t0, stats);
      if (k + 1 < K && hook) hook(ContactInterval{tb, tb - ta, &group.bodies}, bodies);
      if (k + 1 == K)
        for (const int i : group.bodies) last_interval[i] = tb - ta;
    }
  }
  stats.linked = static_cast<int>(schedule.at_end.size());
  if (hook && !schedule.at_end.empty())
    hook(ContactInterval{t1, t1 - t0, &schedule.at_end, &last_interval}, bodies);
  return stats;
}

IntegrationStats BodyIntegrator::advance(BodySet& bodies, const FlowField& flow, double t0,
                                         double t1) const {
  ContactSchedule schedule;
  for (int i = 0; i < bodies.size(); ++i)
    if (bodies.state[i] != BodyState::gone) schedule.free.push_back(i);
  return advance(bodies, flow, t0, t1, schedule, {});
}

}  // namespace flotsam
