#include "bodies/body_motion.hpp"

#include <algorithm>
#include <cmath>

#include "bodies/bed_contact.hpp"

namespace flotsam {

Vec2 AxisReference::at(double angle) const {
  const double d = angle - theta;  // [rad]
  if (d == 0.0) return axis;
  if (std::abs(d) > 0.05) return {std::cos(angle), std::sin(angle)};
  double c, s;
  small_turn(d, c, s);
  return {c * axis.x() - s * axis.y(), s * axis.x() + c * axis.y()};
}

BodyStateVector body_state(const BodySet& bodies, int i) {
  BodyStateVector y;
  y << bodies.position[i], bodies.angle[i], bodies.velocity[i], bodies.angular_velocity[i];
  return y;
}

void set_body_state(BodySet& bodies, int i, const BodyStateVector& y) {
  bodies.position[i] = y.head<2>();
  bodies.angle[i] = y[2];
  bodies.velocity[i] = y.segment<2>(3);
  bodies.angular_velocity[i] = y[5];
}

void finish_derivative(const BodySet& bodies, int i, const ForceModel& model,
                       const WaterLoads& water, BodyStateVector& dy, BodyLoads* loads) {
  const double m_p = bodies.mass[i];
  const double m_f = water.m_f;
  const double C_a = model.physics.added_mass_coefficient;
  Vec2 F = water.fluid + water.drag.force;     // [N]
  double T = water.drag.torque + water.T_rot;  // [N m]

  // Bed contact of a grounded body (spec 3.4).
  Vec2 F_bed = Vec2::Zero();
  bool held = false, spin_held = false;
  if (!water.floating) {
    const double W_eff = effective_weight(m_p, m_f, model.g);
    F_bed = slope_force(W_eff, water.grad_zb);
    const BedFriction friction = bed_friction(water.u_p, water.omega, F + F_bed, T,
                                              model.physics.bed_friction, W_eff, bodies.length[i]);
    F_bed += friction.force;
    T += friction.torque;
    held = friction.held;
    spin_held = friction.spin_held;
  }
  F += F_bed;

  // (M-5); a held body does not move, exactly (bed_contact.hpp says why not F / m).
  const Vec2 du_p_dt = held ? Vec2::Zero() : Vec2(F / (m_p + C_a * m_f));
  dy.segment<2>(3) = du_p_dt;
  dy[5] = spin_held ? 0.0 : T / bodies.inertia[i];
  if (loads) {
    loads->drag = water.drag.force;
    loads->fluid = water.fluid;
    loads->bed = F_bed;
    loads->reaction = water.drag.force + C_a * m_f * (water.Du_f_Dt - du_p_dt);  // spec 5 step 3
    loads->drag_rate = water.drag.rate;
    loads->added_mass = C_a * m_f;
    loads->fluid_acceleration = water.Du_f_Dt;
    loads->flow_velocity = water.u_f;
    loads->torque = T;
    loads->grounded = !water.floating;
    loads->outside = false;
  }
}

BodyStateVector body_derivative(const BodySet& bodies, int i, double t, const BodyStateVector& y,
                                const FlowField& flow, int& hint, const ForceModel& model,
                                BodyLoads* loads, const AxisReference* reference) {
  BodyStateVector dy;
  const Vec2 G = y.head<2>();
  const Vec2 u_p = y.segment<2>(3);
  const double omega = y[5];
  dy.head<2>() = u_p;
  dy[2] = omega;
  dy.tail<3>().setZero();

  const FlowSample at_G = flow.sample(G, t, hint);
  if (!at_G.inside) {  // coasts until the caller removes it (outflow) or reports it
    if (loads) {
      *loads = BodyLoads{};
      loads->outside = true;
    }
    return dy;
  }

  // Immersion and displaced mass (spec 2).
  const double d = bodies.draft[i];
  const double m_p = bodies.mass[i];
  const bool floating = at_G.H > d && bodies.density[i] < model.rho;
  const double h_s = std::clamp(at_G.H, 0.0, d);
  const double m_f = floating ? m_p : model.rho * bodies.submerged_volume(i, h_s);
  const double C_a = model.physics.added_mass_coefficient;

  // Fluid acceleration and the forces of the water (M-5, M-6, M-7, M-8).
  const Vec2 Du_f_Dt = at_G.du_dt + at_G.grad_u * at_G.u;
  const Vec2 axis = reference ? reference->at(y[2]) : Vec2(std::cos(y[2]), std::sin(y[2]));
  const double d_w = bodies.wetted_height[i];
  const Drag drag =
      drag_on_body(bodies, i, BodyPose{G, axis, u_p, d_w, at_G, hint}, t, flow, model);
  const double T_rot =
      rotation_torque(model.rho, model.physics.rotation_coefficient, std::clamp(at_G.H, 0.0, d_w),
                      bodies.length[i], omega, fluid_spin(at_G.grad_u));
  const Vec2 F_fluid = (1.0 + C_a) * m_f * Du_f_Dt;
  finish_derivative(
      bodies, i, model,
      {u_p, omega, floating, m_f, Du_f_Dt, F_fluid, drag, T_rot, at_G.grad_zb, at_G.u}, dy, loads);
  return dy;
}

}  // namespace flotsam
