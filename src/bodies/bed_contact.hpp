#pragma once
// Bed contact of a grounded body (spec 3.4): effective weight, the bed-slope force, and Coulomb
// bed friction with a true static state, for translation and for rotation.
//
// Static and sliding friction. With F the sum of the other horizontal forces on the body
// (drag, fluid acceleration, slope) and F_max = mu_bed W':
//   at rest (u_p = 0):  |F| <= F_max  ->  F_bed = -F            (held: the body does not creep)
//                       |F| >  F_max  ->  F_bed = -F_max F/|F|  (starts to slide along F)
//   sliding:                              F_bed = -F_max u_p/|u_p|
// The same holds for the yaw torque with the bound T_max = mu_bed W' L / 4 (friction spread
// along the body). That friction can stop a body but not reverse it is the integrator's job
// (body_integrator.cpp: a sub-step that would reverse the sliding ends with the body at rest).
//
// A held body's acceleration is exactly zero, not the floating-point sum F + F_bed: that sum
// leaves a residue of order 1e-16 |F|, which sets the body sliding at a speed of round-off, the
// full kinetic friction then reverses it within a sub-step, and the integrator would chatter
// between stick and slip in steps of microseconds (body_motion.cpp uses `held`).
#include "core/vec.hpp"

namespace flotsam {

/// W' = (m_p - m_f) g, never negative [N] (spec 3.4).
inline double effective_weight(double m_p, double m_f, double g) {
  const double W = (m_p - m_f) * g;
  return W > 0.0 ? W : 0.0;
}

/// F_slope = - W' grad z_b [N] (spec 3.4).
inline Vec2 slope_force(double W_eff, const Vec2& grad_zb) {
  return -W_eff * grad_zb;
}

/// Coulomb bed friction force and torque on a grounded body.
struct BedFriction {
  Vec2 force = Vec2::Zero();  // F_bed [N]
  double torque = 0.0;        // T_bed [N m]
  bool held = false;          // at rest and held: the body's acceleration is exactly zero
  bool spin_held = false;     // not spinning and held: its angular acceleration is exactly zero
};

/// Friction for velocity u_p, spin omega, other forces F_other and torques T_other, bounds
/// mu_bed W' and mu_bed W' L/4 (spec 3.4).
BedFriction bed_friction(const Vec2& u_p, double omega, const Vec2& F_other, double T_other,
                         double mu_bed, double W_eff, double L);

}  // namespace flotsam
