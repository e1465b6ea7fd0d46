#pragma once
// Moves every body over one flow step [t0, t1] (spec 3.5, spec 5 step 2): each body with its own
// RKF45 sub-steps (rkf45.hpp) on (M-5) (body_motion.hpp), the flow at intermediate times given
// by the FlowField (linear in time between the two states that bracket the step).
//
// Contacts (src/contact/) act between bodies, so they need the bodies at a common time. The
// choice made here: the flow step is cut into K equal *contact intervals*; within one interval
// every body takes its own adaptive sub-steps, landing exactly on the interval's end; then the
// contact hook is called once for all bodies at that common time and may change velocities and
// positions (impulses, position correction). K is chosen at the start of the step so that no
// body moves more than a quarter of its width l per interval (its fastest point, |u_p| +
// |omega| L/2), hence contacts are looked for before a body can tunnel through another. Without
// a hook K = 1. Each body's own sub-steps are also limited to a move of l/4 (spec 3.5).
//
// The loop over bodies runs in parallel (OpenMP); a body's result depends on nothing but its own
// data, and the only sums across bodies are integer counters, so results are bit-identical for
// any number of threads.
#include <functional>

#include "bodies/body_set.hpp"
#include "bodies/hydrodynamic_forces.hpp"
#include "flow/flow_field.hpp"

namespace flotsam {

/// Called after each contact interval with the common time all bodies have reached [s].
using ContactHook = std::function<void(double t, BodySet& bodies)>;

struct IntegrationStats {
  long accepted = 0;          // accepted RKF45 sub-steps, all bodies
  long rejected = 0;          // rejected (retried) sub-steps, all bodies
  int contact_intervals = 1;  // K of this flow step
};

struct IntegratorOptions {
  double min_step_fraction = 1e-6;   // h_min as a fraction of the flow step [-]
  int max_contact_intervals = 1000;  // cap on K [-]
};

class BodyIntegrator {
 public:
  explicit BodyIntegrator(const ForceModel& model, const IntegratorOptions& options = {})
      : model_(model), options_(options) {}

  /// Advances all bodies that are not gone from t0 to t1, calling `hook` (when set) at the end
  /// of each contact interval. Per-body step sizes persist in bodies.step_size; forces at the
  /// start of each body's last accepted sub-step land in drag_force, bed_force, reaction_force,
  /// torque, and state becomes floating or grounded accordingly.
  IntegrationStats advance(BodySet& bodies, const FlowField& flow, double t0, double t1,
                           const ContactHook& hook = {}) const;

  /// K for a step of length dt: the number of intervals in which no body moves more than l/4.
  int contact_intervals(const BodySet& bodies, double dt) const;

  const ForceModel& model() const { return model_; }

 private:
  /// One body over [ta, tb]; step_span is the whole flow step (for h_min).
  void advance_body(BodySet& bodies, int i, const FlowField& flow, double ta, double tb,
                    double step_span, long& accepted, long& rejected) const;

  ForceModel model_;
  IntegratorOptions options_;
};

}  // namespace flotsam
