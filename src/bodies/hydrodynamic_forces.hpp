#pragma once
// The force laws of the water on one body (spec 3.1-3.3): the wetted projected area S_eff and
// the drag (M-6) with the Ganser drag coefficient (P-18, corrected) or a constant one, the
// centre of pressure (M-7), optional drag points along the body (spec 3.2), and the rotation
// resistance (M-8). Each law is a small pure function so that tests check it against hand
// computations; drag_on_body() puts them together for one body.
#include "bodies/body_set.hpp"
#include "core/vec.hpp"
#include "flow/flow_field.hpp"
#include "io/case.hpp"

namespace flotsam {

/// The parameters of the force laws for a run, gathered once at setup.
struct ForceModel {
  BodyPhysics physics;
  double rho = 1000.0;  // water density [kg m^-3]
  double nu = 1e-6;     // kinematic viscosity for the particle Reynolds number [m^2/s]
  double g = 9.81;      // gravity [m s^-2]
};

ForceModel make_force_model(const BodyPhysics& physics, const FlowConfig& flow);

/// Incidence of the relative flow on the long axis, folded into [0, pi/2] (spec 3): returns
/// (|cos alpha|, |sin alpha|); (1, 0) when u_rel = 0.
Vec2 incidence(const Vec2& u_rel, const Vec2& axis);

/// Wetted projected area normal to u_rel (M-6) [m^2]; h_s = min(d, H) is the wetted height [m],
/// cos_alpha, sin_alpha the folded incidence.
double effective_area(Shape shape, double L, double l, double h_s, double cos_alpha,
                      double sin_alpha);

/// Ganser's shape factors (P-18): K2 from the sphericity, K1 from d_n, d_v and the sphericity.
double ganser_K2_factor(double Theta);
double ganser_K1_factor(double d_n, double d_v, double Theta);

/// Ganser's drag coefficient (P-18, with the correlation's 3305) at particle Reynolds number
/// Re = |u_rel| d_v / nu.
double ganser_drag_coefficient(double Re, double K1, double K2);

/// C_d of body i for the wetted projected area S_eff [m^2] at the relative speed |u_rel| [m/s]:
/// the run's constant, or Ganser's (P-18) with d_n = sqrt(4 S_eff/pi), Re = |u_rel| d_v / nu.
double drag_coefficient(const BodySet& bodies, int i, double S_eff, double speed,
                        const ForceModel& model);

/// |GP| of (M-7) [m]: reach = 0.1 L (1 - exp(3 (1 - L/l))), times |cos alpha|^3.
inline double pressure_centre_offset(double reach, double cos_alpha) {
  return reach * cos_alpha * cos_alpha * cos_alpha;
}

/// The fluid's own spin omega_f = (dv/dx - du/dy) / 2 [rad/s] (spec 3.3).
inline double fluid_spin(const Mat2& grad_u) {
  return 0.5 * (grad_u(1, 0) - grad_u(0, 1));
}

/// Rotation resistance (M-8) [N m]: - rho C_r h_s (L^4/64) |omega - omega_f| (omega - omega_f).
double rotation_torque(double rho, double C_r, double h_s, double L, double omega, double omega_f);

/// Drag force and its moment about G on one body.
struct Drag {
  Vec2 force = Vec2::Zero();  // F_drag [N]
  double torque = 0.0;        // T_drag [N m], z component about G
  double rate = 0.0;          // K [kg/s]: F_drag = K u_rel slice by slice (M-6), summed
};

/// Where and how the body is: its pose, its velocity, and the flow sampled at G.
struct BodyPose {
  Vec2 centre;      // x_G [m]
  Vec2 axis;        // unit vector along the long axis [-]
  Vec2 velocity;    // u_p [m/s]
  double wetted;    // d_w [m], the height the water acts on (BodySet::wetted_height)
  FlowSample at_G;  // the flow at G
  int hint;         // element of G (start of the walks for the drag points)
};

/// Drag (M-6) at the centre of pressure (M-7), summed over `drag_points` slices along the body
/// (spec 3.2). Slice k, centred at s_k = (k + 1/2) L/N - L/2 on the axis, sees u_rel,k =
/// u_f(x_k) - u_p and carries 1/N of the whole body's drag law at that u_rel,k, applied at
/// x_k shifted upstream by (M-7): in uniform flow the sum is (M-6) with (M-7) exactly.
Drag drag_on_body(const BodySet& bodies, int i, const BodyPose& pose, double t,
                  const FlowField& flow, const ForceModel& model);

}  // namespace flotsam
