#pragma once
// The equation of motion of one body (M-5), as the right-hand side y' = f(t, y) of its state
// y = (x_G, y_G, theta, u_x, u_y, omega) (spec 2):
//
//   d x_G/dt = u_p,   d theta/dt = omega
//   (m_p + C_a m_f) du_p/dt = (1 + C_a) m_f Du_f/Dt + F_drag + F_bed + F_slope
//   I_p domega/dt           = T_drag + T_rot + T_bed
//
// with Du_f/Dt = du_f/dt + (grad u_f) u_f at G, m_f = rho V_sub(min(d, H)) (= m_p when
// floating), and the bed terms only when grounded. Contacts act as impulses between sub-steps
// (src/contact/), not here.
#include <Eigen/Core>
#include <cmath>

#include "bodies/body_set.hpp"
#include "bodies/hydrodynamic_forces.hpp"
#include "flow/flow_field.hpp"

namespace flotsam {

using BodyStateVector = Eigen::Matrix<double, 6, 1>;  // (x_G [m], y_G [m], theta [rad],
                                                      //  u_x [m/s], u_y [m/s], omega [rad/s])

/// Everything that acts on one body at one instant (for output and two-way coupling).
struct BodyLoads {
  Vec2 drag = Vec2::Zero();      // F_drag [N] (M-6)
  Vec2 fluid = Vec2::Zero();     // (1 + C_a) m_f Du_f/Dt [N] (M-5)
  Vec2 bed = Vec2::Zero();       // F_bed + F_slope [N] (spec 3.4)
  Vec2 reaction = Vec2::Zero();  // F_x = F_drag + C_a m_f (Du_f/Dt - du_p/dt) [N] (spec 5)
  double drag_rate = 0.0;        // K [kg/s], F_drag = K u_rel (Drag::rate)
  double added_mass = 0.0;       // C_a m_f [kg]
  Vec2 fluid_acceleration = Vec2::Zero();  // Du_f/Dt at G [m/s^2]
  Vec2 flow_velocity = Vec2::Zero();       // u_f at G [m/s]
  double torque = 0.0;                     // T_drag + T_rot + T_bed [N m]
  bool grounded = false;                   // H(G) <= d, or denser than water
  bool outside = false;                    // G is outside the domain: no forces, the body coasts
};

/// cos d and sin d by their Taylor series to 8th order, for |d| <= 0.05 [rad] (AxisReference).
inline void small_turn(double d, double& c, double& s) {
  const double d2 = d * d;
  c = 1.0 - d2 / 2 * (1.0 - d2 / 12 * (1.0 - d2 / 30 * (1.0 - d2 / 56)));
  s = d * (1.0 - d2 / 6 * (1.0 - d2 / 20 * (1.0 - d2 / 42)));
}

/// The long axis at an angle close to a reference one whose axis is known: within a step a body
/// turns by little, so e(theta) = R(theta - theta_ref) e(theta_ref) with the rotation's Taylor
/// series (to 8th order: round-off below 0.05 rad) saves a sincos per RK stage; farther away it
/// falls back to cos and sin.
struct AxisReference {
  double theta;  // [rad]
  Vec2 axis;     // (cos theta, sin theta)
  explicit AxisReference(double angle) : theta(angle), axis(std::cos(angle), std::sin(angle)) {}
  Vec2 at(double angle) const;
};

/// The state of body i as a vector, and back.
BodyStateVector body_state(const BodySet& bodies, int i);
void set_body_state(BodySet& bodies, int i, const BodyStateVector& y);

/// What the water does to body i at one instant, before the bed's part (spec 3.4).
struct WaterLoads {
  Vec2 u_p;       // the body's velocity [m/s]
  double omega;   // its spin [rad/s]
  bool floating;  // H(G) > d and lighter than water
  double m_f;     // displaced mass [kg]
  Vec2 Du_f_Dt;   // the fluid's acceleration at G [m/s^2]
  Vec2 fluid;     // (1 + C_a) m_f Du_f/Dt [N]
  Drag drag;      // F_drag [N] and T_drag [N m] (M-6, M-7)
  double T_rot;   // rotation resistance (M-8) [N m]
  Vec2 grad_zb;   // bed slope at G [-]
  Vec2 u_f;       // the flow's velocity at G [m/s]
};

/// The rest of (M-5) once the water's forces are known: the bed's (spec 3.4) when grounded, then
/// du_p/dt and domega/dt into dy (its first three components untouched); `loads` (optional)
/// receives the forces.
void finish_derivative(const BodySet& bodies, int i, const ForceModel& model,
                       const WaterLoads& water, BodyStateVector& dy, BodyLoads* loads);

/// f(t, y) of (M-5) for body i; `hint` is the element of G (updated); `loads` (optional)
/// receives the forces; `reference` (optional) speeds up the axis.
BodyStateVector body_derivative(const BodySet& bodies, int i, double t, const BodyStateVector& y,
                                const FlowField& flow, int& hint, const ForceModel& model,
                                BodyLoads* loads = nullptr,
                                const AxisReference* reference = nullptr);

}  // namespace flotsam
