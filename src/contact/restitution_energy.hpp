#pragma once
// The energy bound of restitution (docs/model.md "Restitution energy"). Newton's law v_n -> -e
// v_n^0 (M-9) with Coulomb friction is not energy-consistent (Kane & Levinson 1985, Stronge 1991):
// at a point far from a long log's centre the normal and tangential velocities are coupled through
// the spin, the friction stopping the sliding can do positive work, and a log thrown at a wall with
// e = 1 can leave faster than it came. The bound is Stronge's energetic coefficient: restitution
// gives back at most e^2 of the kinetic energy the compression (the inelastic, frictional solve)
// took,
//
//   E_end <= E_mid + e^2 (E_0 - E_mid),
//
// E_0 before the contacts, E_mid after the compression, E_end after the restitution (each
// 1/2 sum m |u|^2 + I omega^2 with the solver's masses). When the restitution's velocity change
// du would break it, only the fraction s of du is kept, the root of E(s) = E_mid + s a + s^2 b
// = bound, a = sum m u_mid . du + I omega_mid d omega, b = 1/2 sum m |du|^2 + I d omega^2.
#include "core/vec.hpp"

namespace flotsam {

/// 1/2 (|u|^2 / w + omega^2 / w_I), w and w_I the inverse mass and inertia (0: the body does not
/// move and counts nothing) [J].
double solver_kinetic_energy(const Vec2& u, double omega, double inverse_mass,
                             double inverse_inertia);

/// One body's share of a and b below, its translation's and its turn's (0 where the body does
/// not move), from its velocities after the compression (u, omega) and after the restitution
/// (u', omega') [J].
struct RestitutionTerms {
  double linear_a = 0.0, angular_a = 0.0, linear_b = 0.0, angular_b = 0.0;
};
RestitutionTerms restitution_terms(const Vec2& u, double omega, const Vec2& u_end, double omega_end,
                                   double inverse_mass, double inverse_inertia);

/// E(s) = E_mid + s a + s^2 b, gathered body by body.
struct RestitutionEnergy {
  double a = 0.0, b = 0.0;  // [J]
  void add(const RestitutionTerms& t) {
    a += t.linear_a, a += t.angular_a;
    b += t.linear_b, b += t.angular_b;
  }
  void add(const Vec2& u, double omega, const Vec2& u_end, double omega_end, double inverse_mass,
           double inverse_inertia) {
    add(restitution_terms(u, omega, u_end, omega_end, inverse_mass, inverse_inertia));
  }
  /// The fraction s in [0, 1] of the restitution's change that keeps E_end within the bound, from
  /// E_0 `before` and E_mid `mid` [J], e [-].
  double fraction(double before, double mid, double e) const;
};

}  // namespace flotsam
