#pragma once
// (M-5)-(M-8) for a batch of bodies at once: each quantity is an array with one lane per body,
// and the laws are loops over the lanes without branches or library calls, so that they compile
// to vector code (SSE2 on any x86-64, AVX2 or AVX-512 where batch_integration.cpp's run-time
// dispatch finds them). The laws are those of hydrodynamic_forces.hpp and body_motion.hpp in the
// same order of operations; only Ganser's R^0.6567 differs, branch_free_pow instead of
// std::exp(0.6567 * std::log(R)) (core/branch_free_math.hpp: within 1.2e-14 relative of it), so
// a batch's derivative is the scalar body_derivative's to about 1e-14 relative
// (tests/bodies/body_batch_test.cpp). The flow comes sampled for the batch
// (FlowField::sample_batch, flow_batch.hpp); what branches stays scalar: the displaced mass and the
// bed of a grounded body (body_motion.cpp's finish_derivative), the axis far from its reference.
#include <algorithm>

#include "bodies/body_motion.hpp"
#include "core/branch_free_math.hpp"
#include "core/constants.hpp"
#include "flow/flow_batch.hpp"

namespace flotsam {

/// The bodies of a batch: each lane's index and its constants. Unused lanes repeat the first
/// body (so that every lane computes on sane numbers); their results are dropped.
struct alignas(64) BatchBodies {
  int count = 0;                // lanes in use
  int index[batch_width];       // body of each lane
  alignas(64) Lanes length;     // L [m]
  alignas(64) Lanes width;      // l [m]
  alignas(64) Lanes draft;      // d [m]
  alignas(64) Lanes wetted;     // d_w [m], BodySet::wetted_height
  alignas(64) Lanes mass;       // m_p [kg]
  alignas(64) Lanes inertia;    // I_p [kg m^2]
  alignas(64) Lanes d_v;        // equal-volume diameter [m] (P-18)
  alignas(64) Lanes K1_term;    // 2 / (3 sqrt(Theta)) [-] (P-18)
  alignas(64) Lanes K2;         // [-] (P-18)
  alignas(64) Lanes reach;      // (M-7) at alpha = 0 [m]
  alignas(64) Lanes box;        // 1: a box, 0: a log
  alignas(64) Lanes can_float;  // 1: lighter than water

  /// Lanes for bodies[0..count), count <= batch_width.
  void gather(const BodySet& set, const int* bodies, int n, double rho) {
    count = n;
    for (int k = 0; k < batch_width; ++k) {
      const int i = bodies[k < n ? k : 0];
      index[k] = i;
      length[k] = set.length[i];
      width[k] = set.width[i];
      draft[k] = set.draft[i];
      wetted[k] = set.wetted_height[i];
      mass[k] = set.mass[i];
      inertia[k] = set.inertia[i];
      d_v[k] = set.equal_volume_diameter[i];
      K1_term[k] = set.ganser_K1_term[i];
      K2[k] = set.ganser_K2[i];
      reach[k] = set.pressure_reach[i];
      box[k] = set.shape[i] == Shape::box ? 1.0 : 0.0;
      can_float[k] = set.density[i] < rho ? 1.0 : 0.0;
    }
  }
};

/// A state (x_G, y_G, theta, u_x, u_y, omega) or a derivative per lane.
struct alignas(64) BatchVector {
  alignas(64) double c[6][batch_width];  // not zeroed: `BatchVector v{}` for zeros
};

/// The drag of a batch (force and moment about G), summed over drag points.
struct alignas(64) BatchDrag {
  alignas(64) Lanes fx = {}, fy = {}, torque = {};
  alignas(64) Lanes rate = {};  // K [kg/s] (Drag::rate)
};

/// Adds `fraction` of the drag law (M-6) at the flow `at` (relative to the body's velocity) and
/// the wetted height min(d, H), applied at `point` shifted upstream by (M-7), to `drag`: the
/// lanes of hydrodynamic_forces.cpp's slice_drag (zero outside the domain, at u_rel = 0 and on
/// a dry bed). Starting from a zero `drag`, one slice gives exactly slice_drag's numbers.
[[gnu::always_inline]] inline void add_slice_drag(const BatchBodies& b, const BatchFlow& at,
                                                  const Lanes& point_x, const Lanes& point_y,
                                                  const Lanes& fraction, const BatchVector& y,
                                                  const Lanes& ax, const Lanes& ay,
                                                  const ForceModel& model, BatchDrag& drag) {
  const double rho = model.rho, nu = model.nu;
  // The run's choices as 0/1 factors (GCC vectorises no select on a loop-invariant bool): the
  // product by 1 and the sum with 0 are exact.
  const double ganser = model.physics.drag_law == DragLaw::ganser ? 1.0 : 0.0;
  const double constant_cd =
      model.physics.drag_law == DragLaw::ganser ? 0.0 : model.physics.drag_coefficient;
  const double pressure_centre = model.physics.center_of_pressure ? 1.0 : 0.0;
#pragma omp simd
  for (int k = 0; k < batch_width; ++k) {
    const double H = at.H[k], d = b.wetted[k];
    const double h_s = H < 0.0 ? 0.0 : (d < H ? d : H);  // std::clamp(H, 0, d_w)
    const double urx = at.u[k] - y.c[3][k], ury = at.v[k] - y.c[4][k];
    const double speed = std::sqrt(urx * urx + ury * ury);
    const bool acts = at.inside[k] != 0.0 && speed != 0.0 && h_s > 0.0;
    const double along = urx * ax[k] + ury * ay[k];
    const double inv_speed = 1.0 / (acts ? speed : 1.0);  // [s/m]
    const double cos_alpha = std::abs(along) * inv_speed;
    const double sin_alpha = std::abs(ax[k] * ury - ay[k] * urx) * inv_speed;
    // (M-6): S_eff of a box, or of a log without division (hydrodynamic_forces.cpp).
    const double L = b.length[k], end = 0.25 * pi * b.width[k];
    const double S_box = h_s * (L * sin_alpha + b.width[k] * cos_alpha);
    const double S_log =
        h_s * std::sqrt(end * end * cos_alpha * cos_alpha + L * L * sin_alpha * sin_alpha);
    const double S_eff = b.box[k] != 0.0 ? S_box : S_log;
    // Ganser's C_d (P-18, corrected), d_n = sqrt(4 S_eff / pi), Re = |u_rel| d_v / nu.
    const double d_v = b.d_v[k];
    const double d_n = std::sqrt(4.0 * S_eff / pi);
    const double K1 = 1.0 / (d_n / (3.0 * d_v) + b.K1_term[k]);
    const double Re = speed * d_v / nu;
    const double R = (Re < 1e-12 ? 1e-12 : Re) * K1 * b.K2[k];  // minimum_reynolds
    const double R_power = branch_free_pow(R, 0.6567);
    const double inv_R = 1.0 / R;
    const double ganser_cd =
        b.K2[k] * (24.0 * inv_R * (1.0 + 0.1118 * R_power) + 0.4305 / (1.0 + 3305.0 * inv_R));
    const double C_d = ganser * ganser_cd + constant_cd;
    const double scale = fraction[k] * 0.5 * rho * C_d * S_eff * speed;
    const double fx = scale * urx, fy = scale * ury;  // (M-6)
    // (M-7): the centre of pressure upstream of the point, on the axis.
    const double offset = pressure_centre_offset(b.reach[k], cos_alpha);
    const double shift = pressure_centre * (along >= 0.0 ? offset : -offset);
    const double px = point_x[k] - shift * ax[k], py = point_y[k] - shift * ay[k];
    const double torque = (px - y.c[0][k]) * fy - (py - y.c[1][k]) * fx;
    drag.fx[k] += acts ? fx : 0.0;
    drag.fy[k] += acts ? fy : 0.0;
    drag.torque[k] += acts ? torque : 0.0;
    drag.rate[k] += acts ? scale : 0.0;
  }
}

/// The loads of each lane, for BodyLoads (spec 5) and for the bed of a grounded body.
struct alignas(64) BatchLoads {
  alignas(64) Lanes fluid_x, fluid_y;        // (1 + C_a) m_f Du_f/Dt [N]
  alignas(64) Lanes Du_x, Du_y;              // Du_f/Dt [m/s^2]
  alignas(64) Lanes m_f;                     // displaced mass [kg]
  alignas(64) Lanes T_rot;                   // (M-8) [N m]
  alignas(64) Lanes reaction_x, reaction_y;  // F_x of a floating lane [N] (spec 5)
  alignas(64) Lanes torque;                  // T of a floating lane [N m]
  alignas(64) Lanes floating;                // 1: floating, 0: grounded or outside
};

/// (M-5) for the lanes that float (dy's last three components), with `drag` from add_slice_drag
/// and each lane's displaced mass m_f (`displaced`, spec 2: m_p when floating); a lane outside
/// the domain coasts (zero accelerations); a grounded lane gets its water loads here and its
/// derivative from finish_derivative. dy's first three components (u_p, omega) are the
/// caller's.
[[gnu::always_inline]] inline void float_derivative(const BatchBodies& b, const BatchFlow& at_G,
                                                    const BatchVector& y, const BatchDrag& drag,
                                                    const Lanes& displaced, const ForceModel& model,
                                                    BatchVector& dy, BatchLoads& loads) {
  const double rho = model.rho;
  const double C_a = model.physics.added_mass_coefficient;
  const double C_r = model.physics.rotation_coefficient;
#pragma omp simd
  for (int k = 0; k < batch_width; ++k) {
    const double H = at_G.H[k], d = b.draft[k];
    const bool inside = at_G.inside[k] != 0.0;
    const bool floating = inside & (H > d) & (b.can_float[k] != 0.0);  // & : no branch
    const double d_w = b.wetted[k];
    const double h_s = H < 0.0 ? 0.0 : (d_w < H ? d_w : H);  // (M-8)'s wetted height
    const double m_p = b.mass[k];
    const double m_f = displaced[k];
    const double u = at_G.u[k], v = at_G.v[k];
    const double Du_x = at_G.du_dt[k] + (at_G.g00[k] * u + at_G.g01[k] * v);
    const double Du_y = at_G.dv_dt[k] + (at_G.g10[k] * u + at_G.g11[k] * v);
    const double L = b.length[k];
    const double omega_f = 0.5 * (at_G.g10[k] - at_G.g01[k]);  // fluid_spin
    const double spin = y.c[5][k] - omega_f;                   // (M-8)
    const double T_rot = -rho * C_r * h_s * (L * L * L * L / 64.0) * std::abs(spin) * spin;
    const double fluid = (1.0 + C_a) * m_f;
    const double fluid_x = fluid * Du_x, fluid_y = fluid * Du_y;
    const double F_x = fluid_x + drag.fx[k], F_y = fluid_y + drag.fy[k];  // [N]
    const double T = drag.torque[k] + T_rot;                              // [N m]
    const double m = m_p + C_a * m_f;
    const double du = F_x / m, dv = F_y / m;  // (M-5)
    const double added = C_a * m_f;
    loads.fluid_x[k] = fluid_x, loads.fluid_y[k] = fluid_y;
    loads.Du_x[k] = Du_x, loads.Du_y[k] = Du_y;
    loads.m_f[k] = m_f;
    loads.T_rot[k] = T_rot;
    loads.reaction_x[k] = drag.fx[k] + added * (Du_x - du);  // spec 5 step 3
    loads.reaction_y[k] = drag.fy[k] + added * (Du_y - dv);
    loads.torque[k] = T;
    loads.floating[k] = floating ? 1.0 : 0.0;
    const double in = at_G.inside[k];  // 1 or 0: the product by it is exact or zero, and
    dy.c[3][k] = in * du;              // unlike a select GCC turns it into no masked store
    dy.c[4][k] = in * dv;
    dy.c[5][k] = in * (T / b.inertia[k]);
  }
}

}  // namespace flotsam
