// The part of the explicit surface slope (and Coriolis) at t^n that a step by characteristics
// takes at the paths' feet; the rest is taken at the arriving node (docs/model.md "Why a part
// s = 3/4 - theta/2 of the slope at the feet"). Shared by the coupled step (flow_time_stepping.cpp,
// element_assembly.cpp) and the segregated step (segregated_step.cpp, (M-20), (M-21)).
#pragma once

namespace flotsam {

/// s, the part of g grad eta^n (and f k x u^n) taken at the paths' feet; the arriving node takes
/// the rest of the t^n part, (1 - theta - s), with theta g grad eta^{n+1} implicit. With s = 1/2
/// the slope's time integral along the path is centred in space, as the advection by
/// characteristics is, and a steady flow has no error O(dt); any other s leaves a steady error
/// (1/2 - s) dt g (u . grad) grad eta. s = 1 - theta (all the explicit part at the feet: the time
/// off-centring taken in space too) made the shortened paper channel's discharge 1.9 % lower at
/// dt = 1 s than at 0.1 s with the segregated step. But with theta > 1/2 the gravity waves moving
/// with the current are damped only while s < 1/2 (at 1/2 the bump of subcritical_bump.cpp does
/// not settle; at 0.48 it settles 1.2 % from Bernoulli, against 0.8 % at 0.4). Halfway,
/// s = 3/4 - theta/2 (0.45 at theta = 0.6, 1/2 at theta = 1/2), halves that error and keeps the
/// damping. [-]
inline double slope_at_feet(double theta) {
  return 0.75 - 0.5 * theta;
}

}  // namespace flotsam
