#include "bodies/bed_contact.hpp"

#include <cmath>

namespace flotsam {

namespace {

/// One friction component: x the sliding rate (velocity or spin), F the other loads along it,
/// F_max the bound. Static when x = 0 and |F| <= F_max (see the header's table); `held` says so.
template <class T>
T coulomb(const T& x, double x_norm, const T& F, double F_norm, double F_max, bool& held) {
  held = x_norm == 0.0 && F_norm <= F_max;
  if (x_norm > 0.0) return -(F_max / x_norm) * x;  // sliding
  if (held) return -F;
  return -(F_max / F_norm) * F;  // starts to slide
}

}  // namespace

BedFriction bed_friction(const Vec2& u_p, double omega, const Vec2& F_other, double T_other,
                         double mu_bed, double W_eff, double L) {
  BedFriction f;
  const double F_max = mu_bed * W_eff;    // [N]
  const double T_max = 0.25 * F_max * L;  // [N m], spec 3.4
  f.force = coulomb(u_p, u_p.norm(), F_other, F_other.norm(), F_max, f.held);
  f.torque = coulomb(omega, std::abs(omega), T_other, std::abs(T_other), T_max, f.spin_held);
  return f;
}

}  // namespace flotsam
