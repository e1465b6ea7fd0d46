#pragma once
// When the water starts a grounded body sliding (spec 3.4): a body resting on a flat bed in a
// uniform current of depth H stays put while the drag (M-6) and any other force of the water
// along the current are at most the bed friction mu_bed W', and slides once they exceed it. The
// threshold speed u_c solves
//
//   1/2 rho C_d(u_c) S_eff(h_s, alpha) u_c^2 + F_other = mu_bed W',
//   W' = (m_p - rho V_sub(h_s)) g,   h_s = min(H, d)
//
// with the run's force laws (hydrodynamic_forces.hpp, bed_contact.hpp): the balance that
// body_motion.cpp strikes for a body at rest. A body that floats at that depth (H > d, lighter
// than water) has W' = 0 and any current carries it: u_c = 0. The parked-car verification case
// and the incipient-motion table of docs/validation.md are computed from these functions.
#include "bodies/body_set.hpp"
#include "bodies/hydrodynamic_forces.hpp"

namespace flotsam {

/// How the water meets a body resting on a flat bed.
struct Current {
  double depth = 0.0;        // H [m]
  double incidence = 0.0;    // alpha [rad], from the long axis to the current
  double other_force = 0.0;  // F_other [N], the water's other force along the current, such as
                             // (1 + C_a) m_f du_f/dt in a current that speeds up (M-5)
};

/// W' of body i resting on the bed in water of depth H [N] (spec 2, 3.4): zero when it floats.
double resting_weight(const BodySet& bodies, int i, double H, const ForceModel& model);

/// u_c [m/s]: the speed of the current at which body i starts to slide; 0 when it floats or
/// F_other alone overcomes the friction, +infinity on dry ground.
double incipient_velocity(const BodySet& bodies, int i, const Current& current,
                          const ForceModel& model);

}  // namespace flotsam
