#include "bodies/body_integrator.hpp"

#include <algorithm>
#include <cmath>

#include "bodies/batch_integration.hpp"
#include "bodies/body_batch.hpp"
#include "bodies/body_step.hpp"

namespace flotsam {

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
  const Rkf45Options<6> options =
      body_step_options(bodies, i, model_, options_.min_step_fraction, ta, tb, step_span);

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
  // The bodies that move, in batches (batch_integration.hpp) unless the one-body path is asked
  // for; anchored bodies one at a time.
  std::vector<int> single, batched;
  batched.reserve(list.size());
  for (const int i : list) {
    if (bodies.state[i] == BodyState::gone) continue;
    (options_.batch && !bodies.anchored[i] ? batched : single).push_back(i);
  }
  // Threads from a few hundred bodies; below, no parallel region at all (one costs about a
  // microsecond even on one thread, and a small contact group meets two every interval).
  constexpr int parallel_bodies = 256;  // [-]
  long accepted = 0, rejected = 0;
  const int n = static_cast<int>(single.size());
  auto advance_one = [&](int k, long& acc, long& rej) {
    advance_body(bodies, single[k], flow, ta, tb, step_span, acc, rej);
  };
  if (n >= parallel_bodies) {
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : accepted, rejected)
    for (int k = 0; k < n; ++k) advance_one(k, accepted, rejected);
  } else {
    for (int k = 0; k < n; ++k) advance_one(k, accepted, rejected);
  }
  const int m = static_cast<int>(batched.size());
  const int batches = (m + batch_width - 1) / batch_width;
  auto advance_one_batch = [&](int b, long& acc, long& rej) {
    const int first = b * batch_width;
    advance_batch(bodies, batched.data() + first, std::min(batch_width, m - first), flow, ta, tb,
                  step_span, model_, options_.min_step_fraction, acc, rej);
  };
  if (m >= parallel_bodies) {
#pragma omp parallel for schedule(dynamic, 8) reduction(+ : accepted, rejected)
    for (int b = 0; b < batches; ++b) advance_one_batch(b, accepted, rejected);
  } else {
    for (int b = 0; b < batches; ++b) advance_one_batch(b, accepted, rejected);
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
  // h per body of its last interval [s], where the groups' intervals make them differ.
  std::vector<double> last_interval;
  if (!schedule.groups.empty())
    last_interval.assign(static_cast<std::size_t>(bodies.size()), t1 - t0);
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
    hook(ContactInterval{t1, t1 - t0, &schedule.at_end,
                         last_interval.empty() ? nullptr : &last_interval},
         bodies);
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
