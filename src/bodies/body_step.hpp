#pragma once
// What every body's RKF45 sub-steps share, whichever integrator runs them (body_integrator.cpp
// one body at a time, batch_integration.cpp a batch in lockstep): the tolerances of spec 3.5,
// friction stopping a grounded body, and where the loads of the last accepted sub-step go.
#include "bodies/body_motion.hpp"
#include "bodies/rkf45.hpp"

namespace flotsam {

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

/// The RKF45 options of body i over [ta, tb]; step_span is the whole flow step (for h_min).
/// Weighted error norm (spec 3.5): positions to tol * l [m], angle to tol [rad]; velocities to
/// tol [m/s], [rad/s] plus tol relative.
inline Rkf45Options<6> body_step_options(const BodySet& bodies, int i, const ForceModel& model,
                                         double min_step_fraction, double ta, double tb,
                                         double step_span) {
  const double l = bodies.width[i];
  const double tol = model.physics.rk_tolerance;
  Rkf45Options<6> options;
  options.abs_tol << tol * l, tol * l, tol, tol, tol, tol;
  options.rel_tol << 0.0, 0.0, 0.0, tol, tol, tol;
  options.h_min = min_step_fraction * step_span;
  options.h_max = tb - ta;
  return options;
}

/// Keeps the loads of body i's last accepted sub-step, its element, and its state.
inline void record_loads(BodySet& bodies, int i, const BodyLoads& loads, int hint) {
  bodies.element_hint[i] = hint;
  bodies.drag_force[i] = loads.drag;
  bodies.bed_force[i] = loads.bed;
  bodies.reaction_force[i] = loads.reaction;
  bodies.torque[i] = loads.torque;
  bodies.drag_rate[i] = loads.drag_rate;
  bodies.added_mass[i] = loads.added_mass;
  bodies.fluid_acceleration[i] = loads.fluid_acceleration;
  bodies.flow_velocity[i] = loads.flow_velocity;
  if (!loads.outside) bodies.state[i] = loads.grounded ? BodyState::grounded : BodyState::floating;
}

}  // namespace flotsam
