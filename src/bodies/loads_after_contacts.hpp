#pragma once
// The loads of bodies held by contacts (spec 5 step 3, docs/model.md "The drag of a held jam").
//
// Between two contact solves a body moves free (body_integrator.hpp): one pressed against a pier,
// a deck or the bodies of a jam gathers speed with the water over the interval and is stopped at
// its end. The loads its last RKF45 sub-step recorded are those of a body partly carried along:
// less drag than at rest, and an added-mass reaction taken with (M-5)'s unconstrained
// acceleration. What the water feels over the next step is the body as the contacts left it.
// So the loads of every body whose contacts carried a normal impulse are recorded again at its
// state after the solve (time t1), with its actual acceleration over the step,
//
//   a_p = (u_p(t1) - u_p(t0)) / (t1 - t0),
//
// in the added mass's reaction F_x = F_drag + C_a m_f (Du_f/Dt - a_p) (spec 5 step 3): a body
// held at rest gives the water its whole drag, the rest going through it to what holds it.
// The bodies' motion is not changed. One body at a time, in parallel: bit-identical on any
// number of threads.
#include <vector>

#include "bodies/body_set.hpp"
#include "bodies/hydrodynamic_forces.hpp"
#include "flow/flow_field.hpp"

namespace flotsam {

/// Records the loads of the `held` bodies (indices) again at time t1 [s] as above;
/// `start_velocity` holds every body's u_p at t0 = t1 - dt [m/s], dt > 0 [s]. Anchored bodies
/// keep theirs (already at rest).
void record_loads_after_contacts(BodySet& bodies, const std::vector<int>& held,
                                 const std::vector<Vec2>& start_velocity, const FlowField& flow,
                                 const ForceModel& model, double t1, double dt);

}  // namespace flotsam
