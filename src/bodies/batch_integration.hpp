#pragma once
// A batch of up to batch_width bodies over one interval with their RKF45 sub-steps in lockstep
// (spec 3.5): every body keeps its own time, step, error and acceptance exactly as
// rkf45_integrate would give it (the same control, rkf45_control), but each Runge-Kutta stage is
// evaluated for all the batch's bodies at once by the lanes of body_batch.hpp, the flow sampled
// once per body and stage for the whole batch (FlowField::sample_batch). A body that has reached
// the interval's end, or that only redoes the stages of a rejected sub-step, leaves its lane idle
// until the batch is done.
//
// The bodies' lanes never mix, so a body's result does not depend on the bodies it is batched
// with; the vector code is built for SSE2 (any x86-64), AVX2 and AVX-512 and picked at run time
// (GCC's target_clones), all compiled without contracting a * b + c into an FMA (CMakeLists.txt:
// -ffp-contract=off), so every clone gives the same bits.
#include "bodies/body_batch.hpp"
#include "flow/flow_field.hpp"

namespace flotsam {

/// Advances the bodies list[0..n) (n <= batch_width; none gone or anchored) from ta to tb;
/// step_span is the whole flow step (h_min = min_step_fraction step_span). Updates their
/// states, step_size, loads, element_hint and state as BodyIntegrator's one-body path does, and
/// adds the accepted and rejected sub-steps to the counters.
void advance_batch(BodySet& bodies, const int* list, int n, const FlowField& flow, double ta,
                   double tb, double step_span, const ForceModel& model, double min_step_fraction,
                   long& accepted, long& rejected);

/// f(t, y) of (M-5) for the bodies list[0..n) (n <= batch_width) at each lane's time and
/// state, the axis referred to each body's angle in `bodies`: body_derivative for a batch (what
/// advance_batch evaluates at every stage). `hints` per lane (updated); `loads` (optional, one
/// per lane) receives the forces.
void batch_derivative(const BodySet& bodies, const int* list, int n, const FlowField& flow,
                      const ForceModel& model, const Lanes& t, const BatchVector& y, int* hints,
                      BatchVector& dy, BodyLoads* loads = nullptr);

}  // namespace flotsam
