#pragma once
// The weak form of (M-1) on one element: a 15 x 15 matrix and right-hand side in the local
// unknowns (u_0..u_5, v_0..v_5, eta_0..eta_2). docs/model.md "Flow (spec 1)" derives it; in
// short, with the theta-scheme between t^n and t^{n+1}, the linearisation point x^k (last
// iterate), test functions w (P2, plus the SUPG part tau (u^k . grad) w) and q (P1):
//
//  momentum (M-1a), for all w:
//    (1) (w, (u - u_d)/dt)                                          time; u_d = u^n (BDF2:
//                                                                   a combination of u^n and
//                                                                   u^{n-1}, and 1/dt its own),
//                                                                   or the departure values of
//                                                                   the characteristics, which
//                                                                   replace (2) and SUPG and
//                                                                   hold the (1-theta) parts of
//                                                                   (3) and (6)
//    (2) theta (w, (u^k.grad)u + (u.grad)u^k - (u^k.grad)u^k)       advection, Newton
//        + (1-theta) (w, (u^n.grad)u^n)
//    (3) g (w, grad(theta eta + (1-theta) eta^n))                   surface slope (not by parts:
//                                                                   a lake at rest gives 0)
//    (4) (nu_e (grad u + grad u^T), grad w)   at theta              viscosity, by parts
//    (5) (w, gamma^k (I + u^ u^T) u - gamma^k u^ (u^ . u^k))        friction (M-2), Newton in u,
//                                                                   fully implicit
//    (6) (w, f k x u) at theta                                      Coriolis (M-2)
//    (7) = (w, F_wind + F_bodies + F_source)                        forcing (M-2)
//  continuity (M-1b), conservative, for all q:
//    (8) (q, (eta - eta_d)/dt)                                       eta_d = eta^n, or BDF2's
//                                                                   start (as u_d)
//    (9) - (grad q, theta (H^k u + (eta - eta^k) u^k) + (1-theta) H^n u^n)     flux, Newton
//   (10) + <q, H u . n> on discharge and velocity boundaries (open_boundary_flux); nothing on
//        walls (no flux), elevation boundaries carry Dirichlet rows.
//   (11) = (q, S_source)
//  on elevation boundaries (ShallowWaterSolver::assemble_inflow_stabilisation):
//   (12) + <w, - beta (u . n)_- u>, (x)_- = min(x, 0), beta = 1/2         inflow stabilisation
#include <Eigen/Dense>
#include <array>
#include <functional>

#include "core/vec.hpp"
#include "flow/fem/element_values.hpp"
#include "flow/friction.hpp"

namespace flotsam {

using LocalMatrix = Eigen::Matrix<double, 15, 15>;
using LocalVector = Eigen::Matrix<double, 15, 1>;

/// Local index of velocity component c of local node a, and of the elevation at vertex j.
constexpr int local_velocity(int a, int c) {
  return 6 * c + a;
}
constexpr int local_elevation(int j) {
  return 12 + j;
}

/// A manufactured or external source: momentum F [m s^-2] and continuity S [m/s] at (x, t).
struct SourceTerms {
  Vec2 momentum = Vec2::Zero();
  double continuity = 0.0;
};
using SourceFunction = std::function<SourceTerms(const Vec2& x, double t)>;

/// Everything the element terms need that is the same for every element.
struct AssemblyParameters {
  double theta = 0.6;               // [-] implicitness of the theta-scheme
  double inv_dt = 0.0;              // 1/dt [1/s]; 0 for the steady equations
  double gravity = 9.81;            // g [m s^-2]
  double coriolis = 0.0;            // f [1/s]
  Vec2 wind_stress = Vec2::Zero();  // (rho_air/rho) C_w |W| W [m^2 s^-2]; F_wind = this / H
  FrictionModel friction;
  bool supg = true;
  // Advection by characteristics (characteristics.hpp): terms (2) and SUPG and the explicit
  // parts of (3) and (6) are left out, and the time term (1) starts from the departure values
  // u_d instead of u^n (they hold those explicit parts, at the departure point).
  bool characteristics = false;
  double source_time = 0.0;  // t^{n+theta} [s], where the source function is evaluated
  const SourceFunction* source = nullptr;
};

/// The nodal values of one element.
struct ElementState {
  std::array<double, 6> u_k, v_k, u_n, v_n;  // [m/s] at the linearisation point, at t^n
  std::array<double, 6> u_d, v_d;            // [m/s] time term's start: u^n, or its departure
                                             // values with characteristics
  std::array<double, 3> eta_k, eta_n;        // [m]
  std::array<double, 3> eta_d;               // [m] the continuity's time term's start: eta^n,
                                             // or BDF2's combination of eta^n and eta^{n-1}
  std::array<double, 6> z_b;                 // [m] P2 bed
  std::array<Vec2, 6> node_force;            // [m s^-2] per-node body force
  Vec2 element_force = Vec2::Zero();         // [m s^-2] per-element body force
  double nu_e = 0.0;                         // nu + nu_t [m^2/s]
  double drag_rate = 0.0;  // c_e [1/s]: the bodies' drag -c_e u, implicit (its c_e v_p is in
                           // element_force; model.md "Two-way coupling")
};

/// Terms (1)-(9), (11) of the element.
void assemble_element(const AssemblyParameters& p, const ElementValues& ev, const ElementState& s,
                      LocalMatrix& K, LocalVector& F);

/// With characteristics: the explicit parts of terms (3) and (6) at t^n, per local node a,
///   F_a = -(1-theta) (N_a, g grad eta^n + f k x u^n)   [m^3 s^-2],
/// whose L2 projection onto P2 is the explicit acceleration that the characteristics carry to
/// the departure point (assemble_element then leaves these parts out). The viscous term (4)
/// stays at the arrival point: its weak form, by parts, has no pointwise projection at the
/// boundary (the projection would put the wall's shear stress into the boundary nodes).
void assemble_explicit_momentum(const AssemblyParameters& p, const ElementValues& ev,
                                const ElementState& s, std::array<Vec2, 6>& F);

/// Term (10) on one open boundary edge, as the outflow H u . n it carries:
/// flux[i] = <q_i, theta H^k u_b . n + (1-theta) H^n u^n . n> for its two vertices [m^3/s]
/// (theta = 1 on discharge boundaries: ShallowWaterSolver::boundary_flux_weight).
/// u_b is the boundary velocity at t^{n+1} (all three edge nodes are Dirichlet there).
struct EdgeState {
  std::array<double, 2> eta_k, eta_n;  // at vertices a, b [m]
  std::array<double, 3> z_b;           // a, b, mid [m]
  std::array<Vec2, 3> u_new, u_n;      // [m/s]
};
std::array<double, 2> open_boundary_flux(double theta, const EdgeValues& ev, const EdgeState& s);

}  // namespace flotsam
