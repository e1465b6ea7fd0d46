#pragma once
// The HLLC approximate Riemann solver for the shallow-water equations (Toro 2001, "Shock-
// capturing methods for free-surface shallow flows", ch. 10; docs/model.md (M-11)), in the
// frame of an edge: normal velocity u_n, tangential u_t, depths h >= 0 on the two sides.
//
//   wave speeds (Toro's two-rarefaction estimate, dry-bed speeds when a side is dry):
//     u* = (u_L + u_R)/2 + c_L - c_R,   c* = (c_L + c_R)/2 + (u_L - u_R)/4,   c = sqrt(g h)
//     s_L = min(u_L - c_L, u* - c*),    s_R = max(u_R + c_R, u* + c*)
//     h_L = 0:  s_L = u_R - 2 c_R, s_R = u_R + c_R;   h_R = 0:  s_L = u_L - c_L, s_R = u_L + 2 c_L
//   mass and normal momentum: HLL,
//     F = F_L + s_L (s_R (U_R - U_L) - (F_R - F_L)) / (s_R - s_L)   (0 <= s_L: F_L; s_R <= 0: F_R)
//   written so that equal states give F_L exactly (a lake at rest stays at rest to round-off);
//   tangential momentum: the mass flux times u_t of the side the contact wave s* leaves,
//     s* = (s_L h_R (u_R - s_R) - s_R h_L (u_L - s_L)) / (h_R (u_R - s_R) - h_L (u_L - s_L));
//   except across a compression (u_L - u_R > shock_sensor max(c_L, c_R)), where the tangential
//   momentum takes HLL's flux too: HLLC's undamped shear wave lets a shock running along a
//   mesh grow a transverse instability (the "carbuncle"; measured on the Stoker dam break:
//   |hv| at the shock 20 % of hu and the L1 error rising with refinement; docs/model.md).
#include <algorithm>
#include <cmath>

namespace flotsam {

constexpr double shock_sensor = 0.1;  // [-] normal-velocity jump / wave celerity

struct EdgeState {
  double h;    // [m]
  double u_n;  // [m/s] along the edge normal
  double u_t;  // [m/s] along the tangent
};

struct EdgeFlux {
  double mass;        // [m^2/s] h u_n
  double momentum_n;  // [m^3/s^2] h u_n^2 + g h^2 / 2
  double momentum_t;  // [m^3/s^2] h u_n u_t
  double max_speed;   // [m/s] max(|s_L|, |s_R|)
};

inline EdgeFlux hllc_flux(const EdgeState& L, const EdgeState& R, double g) {
  if (L.h <= 0.0 && R.h <= 0.0) return {0.0, 0.0, 0.0, 0.0};
  const double c_L = std::sqrt(g * L.h), c_R = std::sqrt(g * R.h);
  double s_L, s_R;
  if (L.h <= 0.0) {
    s_L = R.u_n - 2.0 * c_R;
    s_R = R.u_n + c_R;
  } else if (R.h <= 0.0) {
    s_L = L.u_n - c_L;
    s_R = L.u_n + 2.0 * c_L;
  } else {
    const double u_star = 0.5 * (L.u_n + R.u_n) + c_L - c_R;
    const double c_star = 0.5 * (c_L + c_R) + 0.25 * (L.u_n - R.u_n);
    s_L = std::min(L.u_n - c_L, u_star - c_star);
    s_R = std::max(R.u_n + c_R, u_star + c_star);
  }
  const double q_L = L.h * L.u_n, q_R = R.h * R.u_n;  // [m^2/s]
  const double p_L = q_L * L.u_n + 0.5 * g * L.h * L.h, p_R = q_R * R.u_n + 0.5 * g * R.h * R.h;
  EdgeFlux f;
  f.max_speed = std::max(std::abs(s_L), std::abs(s_R));
  if (s_L >= 0.0) {
    f.mass = q_L, f.momentum_n = p_L;
  } else if (s_R <= 0.0) {
    f.mass = q_R, f.momentum_n = p_R;
  } else {
    const double w = s_L / (s_R - s_L);
    f.mass = q_L + w * (s_R * (R.h - L.h) - (q_R - q_L));
    f.momentum_n = p_L + w * (s_R * (q_R - q_L) - (p_R - p_L));
  }
  if (s_L < 0.0 && s_R > 0.0 && L.u_n - R.u_n > shock_sensor * std::max(c_L, c_R)) {
    const double w = s_L / (s_R - s_L);
    const double m_L = q_L * L.u_t, m_R = q_R * R.u_t;  // [m^3/s^2]
    f.momentum_t = m_L + w * (s_R * (R.h * R.u_t - L.h * L.u_t) - (m_R - m_L));
    return f;
  }
  const double denominator = R.h * (R.u_n - s_R) - L.h * (L.u_n - s_L);
  const double s_star = denominator != 0.0
                            ? (s_L * R.h * (R.u_n - s_R) - s_R * L.h * (L.u_n - s_L)) / denominator
                            : 0.0;
  f.momentum_t = f.mass * (s_star >= 0.0 ? L.u_t : R.u_t);
  return f;
}

}  // namespace flotsam
