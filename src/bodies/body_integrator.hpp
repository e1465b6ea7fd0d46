#pragma once
// Moves every body over one flow step [t0, t1] (spec 3.5, spec 5 step 2): each body with its own
// RKF45 sub-steps (rkf45.hpp) on (M-5) (body_motion.hpp), the flow at intermediate times given
// by the FlowField (linear in time between the two states that bracket the step).
//
// Contacts (src/contact/) act between bodies, so they need the bodies that may touch at a common
// time. The contact stage plans each flow step (ContactWorld::plan): it links the bodies that may
// touch one another or a wall within the step, and gives each link the count K of equal *contact
// intervals* within which its bodies close on each other (or on the wall) by at most a quarter
// of the thinner width. Links with K > 1 bind their bodies into *contact groups*, each stepped in
// its own K intervals (every body landing exactly on each interval's end, the contact hook called
// for the group after each but the last). Every other body crosses the whole step in the
// sub-steps its forces need. At the step's end the hook is called once more for every linked
// body, each with the length of the last interval it was moved over: contacts of links with
// K = 1 (logs drifting side by side, a resting jam) are resolved there, once per step. Groups
// never touch one another before the step's end, so each is stepped through it in turn. Without
// a hook nothing is linked.
//
// The loop over bodies (or batches of them) runs in parallel (OpenMP); a body's result depends on
// nothing but its own data (a batch's lanes never mix), and the only sums across bodies are integer
// counters, so results are bit-identical for any number of threads.
#include <functional>
#include <vector>

#include "bodies/body_set.hpp"
#include "bodies/hydrodynamic_forces.hpp"
#include "flow/flow_field.hpp"

namespace flotsam {

/// Bodies that may touch within a flow step, stepped together in `intervals` equal intervals.
struct ContactGroup {
  std::vector<int> bodies;  // indices, ascending
  int intervals = 1;        // K [-]
};

/// A flow step's plan: the contact groups, in the order they are stepped, the bodies that cross
/// the step in one go, and the bodies whose contacts are resolved at the step's end.
struct ContactSchedule {
  std::vector<ContactGroup> groups;
  std::vector<int> free;    // in no group: one interval, the whole step (indices, ascending)
  std::vector<int> at_end;  // every linked body (indices, ascending)

  /// Every body that is not gone in one group of K intervals, all resolved at the end.
  static ContactSchedule one_group(const BodySet& bodies, int intervals = 1);
};

/// One contact interval ended: its bodies have all reached `end`.
struct ContactInterval {
  double end = 0.0;                              // [s]
  double length = 0.0;                           // h [s], the time the bodies were just moved over
  const std::vector<int>* bodies = nullptr;      // the bodies
  const std::vector<double>* lengths = nullptr;  // h per body [s] (indexed by body), when they
                                                 // differ (at the step's end); else `length`
};

/// Called after each contact interval of each group but its last, then at the step's end.
using ContactHook = std::function<void(const ContactInterval& interval, BodySet& bodies)>;

struct IntegrationStats {
  long accepted = 0;          // accepted RKF45 sub-steps, all bodies
  long rejected = 0;          // rejected (retried) sub-steps, all bodies
  int contact_intervals = 1;  // the largest K of this flow step's groups
  int grouped = 0;            // bodies in contact groups this step
  int linked = 0;             // bodies whose contacts were resolved at the step's end
};

struct IntegratorOptions {
  double min_step_fraction = 1e-6;  // h_min as a fraction of the flow step [-]
  // true: the bodies that move are integrated batch_width at a time, each stage's forces in
  // vector code (batch_integration.hpp); false: one body at a time with the scalar laws of
  // hydrodynamic_forces.hpp (the reference the batches are tested against). Anchored bodies
  // always take the one-body path.
  bool batch = true;
};

class BodyIntegrator {
 public:
  explicit BodyIntegrator(const ForceModel& model, const IntegratorOptions& options = {})
      : model_(model), options_(options) {}

  /// Advances all bodies that are not gone from t0 to t1: the free bodies of `schedule` over the
  /// whole step, then each group in its intervals, calling `hook` at the end of each but the
  /// last, then `hook` for the bodies `at_end`. Per-body step
  /// sizes persist in bodies.step_size; forces at the start of each body's last accepted sub-step
  /// land in drag_force, bed_force, reaction_force, torque, and state becomes floating or grounded
  /// accordingly.
  IntegrationStats advance(BodySet& bodies, const FlowField& flow, double t0, double t1,
                           const ContactSchedule& schedule, const ContactHook& hook) const;

  /// Advances all bodies that are not gone from t0 to t1, with no contacts.
  IntegrationStats advance(BodySet& bodies, const FlowField& flow, double t0, double t1) const;

  const ForceModel& model() const { return model_; }

 private:
  /// One body over [ta, tb]; step_span is the whole flow step (for h_min).
  void advance_body(BodySet& bodies, int i, const FlowField& flow, double ta, double tb,
                    double step_span, long& accepted, long& rejected) const;
  /// The listed bodies over [ta, tb], in parallel.
  void advance_bodies(BodySet& bodies, const std::vector<int>& list, const FlowField& flow,
                      double ta, double tb, double step_span, IntegrationStats& stats) const;

  ForceModel model_;
  IntegratorOptions options_;
};

}  // namespace flotsam
