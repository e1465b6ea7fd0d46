#include "bodies/hydrodynamic_forces.hpp"

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"

namespace flotsam {

namespace {

// Below this particle Reynolds number the Ganser law is evaluated at it: C_d |u_rel| stays
// finite (Stokes regime, C_d ~ 24/Re) so the drag goes to zero with u_rel without a 0/0.
constexpr double minimum_reynolds = 1e-12;  // [-]

}  // namespace

ForceModel make_force_model(const BodyPhysics& physics, const FlowConfig& flow) {
  return {physics, flow.water_density, flow.viscosity, flow.gravity};
}

Vec2 incidence(const Vec2& u_rel, const Vec2& axis) {
  const double speed = u_rel.norm();
  if (speed == 0.0) return {1.0, 0.0};
  return {std::abs(u_rel.dot(axis)) / speed, std::abs(cross(axis, u_rel)) / speed};
}

double effective_area(Shape shape, double L, double l, double h_s, double cos_alpha,
                      double sin_alpha) {
  if (shape == Shape::box) return h_s * (L * sin_alpha + l * cos_alpha);  // (M-6), box
  // (M-6), log: phi_s (pi l^2/4) sqrt(cos^2 alpha + (4 L/(pi l))^2 sin^2 alpha), phi_s = h_s/l,
  // that is h_s sqrt((pi l/4)^2 cos^2 alpha + L^2 sin^2 alpha) (no division).
  const double end = 0.25 * pi * l;  // [m]
  return h_s * std::sqrt(end * end * cos_alpha * cos_alpha + L * L * sin_alpha * sin_alpha);
}

double ganser_K2_factor(double Theta) {
  return std::pow(10.0, 1.8148 * std::pow(-std::log10(Theta), 0.5743));  // (P-18)
}

double ganser_K1_factor(double d_n, double d_v, double Theta) {
  return 1.0 / (d_n / (3.0 * d_v) + 2.0 / (3.0 * std::sqrt(Theta)));  // (P-18)
}

double ganser_drag_coefficient(double Re, double K1, double K2) {
  // (P-18) corrected: C_d = K2 [24/(Re K1 K2) (1 + 0.1118 (Re K1 K2)^0.6567)
  //                             + 0.4305 / (1 + 3305/(Re K1 K2))]
  const double R = std::max(Re, minimum_reynolds) * K1 * K2;
  const double R_power = std::exp(0.6567 * std::log(R));  // R^0.6567, cheaper than std::pow
  const double inv_R = 1.0 / R;
  return K2 * (24.0 * inv_R * (1.0 + 0.1118 * R_power) + 0.4305 / (1.0 + 3305.0 * inv_R));
}

double drag_coefficient(const BodySet& bodies, int i, double S_eff, double speed,
                        const ForceModel& model) {
  if (model.physics.drag_law == DragLaw::constant) return model.physics.drag_coefficient;
  const double d_v = bodies.equal_volume_diameter[i];
  const double d_n = std::sqrt(4.0 * S_eff / pi);  // equal projected-area diameter (P-18)
  const double K1 = 1.0 / (d_n / (3.0 * d_v) + bodies.ganser_K1_term[i]);  // (P-18)
  return ganser_drag_coefficient(speed * d_v / model.nu, K1, bodies.ganser_K2[i]);
}

double rotation_torque(double rho, double C_r, double h_s, double L, double omega, double omega_f) {
  const double spin = omega - omega_f;  // (M-8)
  return -rho * C_r * h_s * (L * L * L * L / 64.0) * std::abs(spin) * spin;
}

namespace {

/// One slice of the body (spec 3.2), or the whole body when N = 1.
struct Slice {
  Vec2 point;       // slice centre x_k [m]
  Vec2 u_rel;       // u_f(x_k) - u_p [m/s]
  double h_s;       // wetted height min(d_w, H(x_k)) [m]
  double fraction;  // 1/N [-]
};

/// Drag on one slice (1/N of the body's drag law at the slice's u_rel and h_s), applied at the
/// slice centre shifted upstream by (M-7); returns the force and its moment about G.
Drag slice_drag(const BodySet& bodies, int i, const BodyPose& pose, const Slice& slice,
                const ForceModel& model) {
  const Vec2& u_rel = slice.u_rel;
  const Vec2& axis = pose.axis;
  const double h_s = slice.h_s;
  const double speed = u_rel.norm();
  if (speed == 0.0 || h_s <= 0.0) return {};
  const double along = u_rel.dot(axis);
  const double inv_speed = 1.0 / speed;  // [s/m]
  const double cos_alpha = std::abs(along) * inv_speed;
  const double sin_alpha = std::abs(cross(axis, u_rel)) * inv_speed;
  const double S_eff =
      effective_area(bodies.shape[i], bodies.length[i], bodies.width[i], h_s, cos_alpha, sin_alpha);
  const double C_d = drag_coefficient(bodies, i, S_eff, speed, model);
  Drag drag;
  drag.rate = slice.fraction * 0.5 * model.rho * C_d * S_eff * speed;  // [kg/s]
  drag.force = drag.rate * u_rel;                                      // (M-6)
  Vec2 P = slice.point;
  if (model.physics.center_of_pressure) {
    // (M-7): P on the axis, on the side u_rel meets first (upstream: against u_rel).
    const double offset = pressure_centre_offset(bodies.pressure_reach[i], cos_alpha);
    P -= (along >= 0.0 ? offset : -offset) * axis;
  }
  drag.torque = cross(P - pose.centre, drag.force);
  return drag;
}

}  // namespace

Drag drag_on_body(const BodySet& bodies, int i, const BodyPose& pose, double t,
                  const FlowField& flow, const ForceModel& model) {
  const int N = std::max(1, model.physics.drag_points);
  if (N == 1) {
    const double h_s = std::clamp(pose.at_G.H, 0.0, pose.wetted);
    return slice_drag(bodies, i, pose, {pose.centre, pose.at_G.u - pose.velocity, h_s, 1.0}, model);
  }
  Drag total;
  const double L = bodies.length[i];
  for (int k = 0; k < N; ++k) {
    const double s_k = (k + 0.5) * L / N - 0.5 * L;  // slice centre on the axis [m]
    const Vec2 x_k = pose.centre + s_k * pose.axis;
    int hint = pose.hint;
    const FlowSample at_k = flow.sample(x_k, t, hint);
    if (!at_k.inside) continue;  // that part of the body is against a wall: no water there
    const double h_s = std::clamp(at_k.H, 0.0, pose.wetted);
    const Drag d = slice_drag(bodies, i, pose, {x_k, at_k.u - pose.velocity, h_s, 1.0 / N}, model);
    total.force += d.force;
    total.torque += d.torque;
    total.rate += d.rate;
  }
  return total;
}

}  // namespace flotsam
