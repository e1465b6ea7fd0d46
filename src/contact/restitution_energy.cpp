#include "contact/restitution_energy.hpp"

#include <algorithm>
#include <cmath>

namespace flotsam {

double solver_kinetic_energy(const Vec2& u, double omega, double inverse_mass,
                             double inverse_inertia) {
  double energy = 0.0;  // [J]
  if (inverse_mass > 0.0) energy += 0.5 * u.squaredNorm() / inverse_mass;
  if (inverse_inertia > 0.0) energy += 0.5 * omega * omega / inverse_inertia;
  return energy;
}

RestitutionTerms restitution_terms(const Vec2& u, double omega, const Vec2& u_end, double omega_end,
                                   double inverse_mass, double inverse_inertia) {
  const Vec2 du = u_end - u;
  const double dw = omega_end - omega;  // [rad/s]
  RestitutionTerms t;
  if (inverse_mass > 0.0) {
    t.linear_a = u.dot(du) / inverse_mass;
    t.linear_b = 0.5 * du.squaredNorm() / inverse_mass;
  }
  if (inverse_inertia > 0.0) {
    t.angular_a = omega * dw / inverse_inertia;
    t.angular_b = 0.5 * dw * dw / inverse_inertia;
  }
  return t;
}

double RestitutionEnergy::fraction(double before, double mid, double e) const {
  const double allowed = e * e * std::max(before - mid, 0.0);  // [J]
  if (a + b <= allowed || b <= 0.0) return 1.0;
  return std::clamp((-a + std::sqrt(a * a + 4.0 * b * allowed)) / (2.0 * b), 0.0, 1.0);
}

}  // namespace flotsam
