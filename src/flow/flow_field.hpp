#pragma once
// What the debris asks of a flow engine (spec 3, 4.4, 5; issue 3 item 3). The FEM engine, the
// finite-volume engine (spec 7) and analytic test flows all implement it, so that bodies never
// know which one carries them.
#include <vector>

#include "core/vec.hpp"

namespace flotsam {

/// The flow at one point and time.
struct FlowSample {
  double eta = 0.0;             // free-surface elevation [m]
  double H = 0.0;               // water depth eta - z_b [m]
  Vec2 u = Vec2::Zero();        // depth-averaged velocity u_f [m/s]
  Mat2 grad_u = Mat2::Zero();   // velocity gradient, grad_u(i, j) = d u_i / d x_j [1/s]
  Vec2 du_dt = Vec2::Zero();    // local time derivative d u_f / d t [m/s^2]
  Vec2 grad_zb = Vec2::Zero();  // bed slope [-]
  bool inside = true;       // false: the point is outside the domain (the other fields are unset)
  int boundary_group = -1;  // when outside: the boundary group of the edge the walk left through
};

/// Where a body lies: its rectangle.
struct BodyFootprint {
  Vec2 centre;        // [m]
  Vec2 half_extents;  // [m] (L/2, l/2)
  double angle;       // theta [rad]
};

/// A body's reaction on the flow (spec 5, two-way), applied on its footprint: the water takes
/// -F_x = -F_drag - C_a m_f (Du_f/Dt - du_p/dt). The drag is handed over as its law, so that an
/// engine may apply it implicitly at the water's own velocity (model.md "Two-way coupling").
struct BodyReaction : BodyFootprint {
  Vec2 force;              // -C_a m_f (Du_f/Dt - du_p/dt): the added mass's part, on the water [N]
  double drag_rate = 0.0;  // K [kg/s]: F_drag = K (u_f - u_p) on the body
  Vec2 velocity = Vec2::Zero();  // u_p [m/s]
};

struct BatchFlow;  // flow_batch.hpp

class FlowField {
 public:
  virtual ~FlowField() = default;

  /// The flow at point p and time t, where t lies within the current flow step
  /// [time_begin(), time_end()] (states linearly interpolated in between, spec 5 step 2).
  /// `hint` is an element index from the last call for this point (-1: unknown); it is updated.
  virtual FlowSample sample(const Vec2& p, double t, int& hint) const = 0;

  /// The flow at the batch_width (flow_batch.hpp) points (x[k], y[k]) at times t[k]: lane k is
  /// sample({x[k], y[k]}, t[k], hints[k]) to the bit where active[k] (hints[k] updated the same
  /// way), outside with every field zero elsewhere. This one samples point by point; the
  /// engines' fields locate the points and interpolate for the whole batch at once.
  virtual void sample_batch(const double* x, const double* y, const double* t, const bool* active,
                            int* hints, BatchFlow& out) const;

  /// The interval of the current flow step: samples are valid for t in [begin, end].
  virtual double time_begin() const = 0;
  virtual double time_end() const = 0;

  /// Body reactions to apply as a source during the next flow step (two-way coupling). Engines
  /// without coupling ignore them.
  virtual void set_body_reactions(const std::vector<BodyReaction>& /*reactions*/) {}
  /// Per reaction of the last set_body_reactions, the force the water exchanged with that body
  /// over the last flow step, on the body [N] (its mean over the step); empty without coupling.
  virtual std::vector<Vec2> exchanged_forces() const { return {}; }
};

}  // namespace flotsam
