#include "flow/fem/element_assembly.hpp"

#include <algorithm>
#include <cmath>

namespace flotsam {

namespace {

// Stabilisation parameter of SUPG (Tezduyar 1992) for the P2 element, whose node spacing is
// h = h_e / 2:  tau = ( (2/dt)^2 + (2|a|/h)^2 + (4 nu/h^2)^2 + gamma^2 )^(-1/2), and its
// derivatives for Newton's method: gamma = gamma(|u|, H) ~ |u|, so
// d tau/du = -tau^3 (4/h^2 + gamma^2/|u|^2) u and d tau/dH = -tau^3 gamma d gamma/dH.
struct Supg {
  double tau = 0.0;
  Vec2 dtau_du = Vec2::Zero();  // [s^2/m]
  double dtau_dH = 0.0;         // [s/m]
};

Supg supg_tau(double inv_dt, const Vec2& u, double nu, double gamma, double dgamma_dH, double h) {
  const double speed = u.norm();
  const double a = 2.0 * inv_dt, b = 2.0 * speed / h, c = 4.0 * nu / (h * h);
  const double sum = a * a + b * b + c * c + gamma * gamma;
  if (sum <= 0.0) return {};
  Supg s;
  s.tau = 1.0 / std::sqrt(sum);
  const double tau3 = s.tau * s.tau * s.tau;
  const double friction = speed > 0.0 ? gamma * gamma / (speed * speed) : 0.0;
  s.dtau_du = -tau3 * (4.0 / (h * h) + friction) * u;
  s.dtau_dH = -tau3 * gamma * dgamma_dH;
  return s;
}

// Eulerian = false: with characteristics, whose advection and explicit slope and Coriolis are in
// u_d; the terms of advection (2), SUPG and the explicit parts of (3) and (6) vanish and are not
// computed (a third fewer operations).
template <bool Eulerian>
void assemble(const AssemblyParameters& p, const ElementValues& ev, const ElementState& s,
              LocalMatrix& K, LocalVector& F) {
  K.setZero();
  F.setZero();
  const double th = p.theta, g = p.gravity, f = p.coriolis, nu = s.nu_e;
  const double h = 0.5 * ev.size;
  for (int q = 0; q < triangle_point_count; ++q) {
    const auto& N = ev.N2[q];
    const auto& dN = ev.dN2[q];
    const auto& M = ev.N1[q];
    const auto& dM = ev.dN1[q];
    const double JxW = ev.JxW[q];

    // The two states at the quadrature point. G(i, j) = d u_i / d x_j.
    Vec2 u_k = Vec2::Zero(), u_n = Vec2::Zero(), u_d = Vec2::Zero(), force = s.element_force,
         visc_k = Vec2::Zero(), visc_n = Vec2::Zero();
    Mat2 G_k = Mat2::Zero(), G_n = Mat2::Zero();
    double z_b = 0.0;
    for (int b = 0; b < 6; ++b) {
      const Vec2 ub_k(s.u_k[b], s.v_k[b]), ub_n(s.u_n[b], s.v_n[b]);
      u_k += N[b] * ub_k;
      u_n += N[b] * ub_n;
      u_d += N[b] * Vec2(s.u_d[b], s.v_d[b]);
      G_n += ub_n * dN[b].transpose();
      z_b += N[b] * s.z_b[b];
      force += N[b] * s.node_force[b];
      if constexpr (Eulerian) {
        G_k += ub_k * dN[b].transpose();
        // Strong viscous term div(nu (grad u + grad u^T)) = nu (Laplace u + grad div u).
        visc_k += ev.hessian2[b].trace() * ub_k + ev.hessian2[b] * ub_k;
        visc_n += ev.hessian2[b].trace() * ub_n + ev.hessian2[b] * ub_n;
      }
    }
    double eta_k = 0.0, eta_n = 0.0, eta_d = 0.0;
    Vec2 grad_eta_k = Vec2::Zero(), grad_eta_n = Vec2::Zero();
    for (int j = 0; j < 3; ++j) {
      eta_k += M[j] * s.eta_k[j];
      eta_n += M[j] * s.eta_n[j];
      eta_d += M[j] * s.eta_d[j];
      grad_eta_k += s.eta_k[j] * dM[j];
      grad_eta_n += s.eta_n[j] * dM[j];
    }
    const double H_k = eta_k - z_b, H_n = eta_n - z_b;
    const double H_f = std::max(H_k, p.friction.min_depth);
    const double speed = u_k.norm();
    const double gamma = p.friction.rate(speed, H_k);  // (M-2) friction, F = - gamma u
    const Vec2 u_hat = speed > 0.0 ? Vec2(u_k / speed) : Vec2::Zero();
    force += p.wind_stress / H_f;  // (M-2) wind
    // Newton in the depth of (5) and (7): d(gamma u - F_wind)/dH at x^k, times eta - eta^k.
    const double dgamma_dH = p.friction.rate_depth_derivative(speed, H_k);
    Vec2 depth_rate = dgamma_dH * u_k;
    if (H_k > p.friction.min_depth) depth_rate += p.wind_stress / (H_k * H_k);
    double S = 0.0;
    if (p.source) {
      const SourceTerms src = (*p.source)(ev.x[q], p.source_time);
      force += src.momentum;
      S = src.continuity;
    }
    const Supg supg =
        Eulerian && p.supg ? supg_tau(p.inv_dt, u_k, nu, gamma, dgamma_dH, h) : Supg{};
    const double tau = supg.tau;
    const Vec2 advection_k = G_k * u_k, advection_n = G_n * u_n;
    const Mat2 strain_n = G_n + G_n.transpose();
    const Vec2 coriolis_k(-u_k.y(), u_k.x()), coriolis_n(-u_n.y(), u_n.x());  // k x u
    // The strong momentum residual at x^k, which SUPG weights: Newton's derivative of the test
    // function psi = tau (u.grad) w in u and H multiplies it.
    Vec2 residual_k = Vec2::Zero();
    if (tau > 0.0)
      residual_k = (u_k - u_d) * p.inv_dt + th * advection_k + (1 - th) * advection_n +
                   g * (th * grad_eta_k + (1 - th) * grad_eta_n) + (gamma + s.drag_rate) * u_k -
                   nu * (th * visc_k + (1 - th) * visc_n) +
                   f * (th * coriolis_k + (1 - th) * coriolis_n) - force;

    // Momentum rows: test function s_a = N_a + psi_a (SUPG), component c; the 2 x 2 block of
    // rows (a, c) and columns (b, d) at once.
    const Mat2 friction_dir = gamma * u_hat * u_hat.transpose();  // (5), gamma u^ u^T
    const Mat2 rotation{{0.0, -1.0}, {1.0, 0.0}};                 // (6), k x
    for (int a = 0; a < 6; ++a) {
      const double psi = tau * u_k.dot(dN[a]);
      const double s_a = N[a] + psi;
      const Vec2 dpsi_du = tau * dN[a] + u_k.dot(dN[a]) * supg.dtau_du;
      const double dpsi_dH = u_k.dot(dN[a]) * supg.dtau_dH;
      for (int b = 0; b < 6; ++b) {
        const double sN = s_a * N[b];
        double diagonal =
            sN * (p.inv_dt + gamma + s.drag_rate) + th * nu * dN[a].dot(dN[b]);  // (1) (5) (4)
        Mat2 block = sN * (friction_dir + th * f * rotation) +                   // (5) (6)
                     th * nu * dN[b] * dN[a].transpose();                        // (4)
        if constexpr (Eulerian) {
          const double lap_b = ev.hessian2[b].trace();
          diagonal += s_a * th * u_k.dot(dN[b]) - th * psi * nu * lap_b;  // (2) (4)
          block += th * sN * G_k - th * psi * nu * ev.hessian2[b] +       // (2) (4)
                   N[b] * residual_k * dpsi_du.transpose();               // SUPG, Newton
        }
        block.diagonal().array() += diagonal;
        for (int c = 0; c < 2; ++c)
          for (int d = 0; d < 2; ++d)
            K(local_velocity(a, c), local_velocity(b, d)) += block(c, d) * JxW;
      }
      for (int c = 0; c < 2; ++c) {
        const int row = local_velocity(a, c);
        for (int j = 0; j < 3; ++j)
          K(row, local_elevation(j)) +=
              ((th * g * dM[j][c] + depth_rate[c] * M[j]) * s_a + dpsi_dH * residual_k[c] * M[j]) *
              JxW;                                          // (3) (5) (7), SUPG
        double rhs = s_a * u_d[c] * p.inv_dt;               // (1)
        rhs -= (1 - th) * nu * strain_n.row(c).dot(dN[a]);  // (4)
        rhs += s_a * gamma * u_hat[c] * u_hat.dot(u_k);     // (5)
        rhs += s_a * force[c];                              // (7)
        rhs += s_a * depth_rate[c] * eta_k;                 // (5) (7)
        if constexpr (Eulerian) {
          rhs += th * s_a * advection_k[c] - (1 - th) * s_a * advection_n[c];  // (2)
          rhs -= (1 - th) * g * s_a * grad_eta_n[c];                           // (3)
          rhs += (1 - th) * psi * nu * visc_n[c];                              // (4)
          rhs -= (1 - th) * f * s_a * coriolis_n[c];                           // (6)
          rhs += (dpsi_du.dot(u_k) + dpsi_dH * eta_k) * residual_k[c];         // SUPG
        }
        F(row) += rhs * JxW;
      }
    }

    // Continuity rows: test function q_i = M_i.
    const Vec2 flux_n = H_n * u_n;
    for (int i = 0; i < 3; ++i) {
      const int row = local_elevation(i);
      const double advect_i = dM[i].dot(u_k);
      for (int j = 0; j < 3; ++j)
        K(row, local_elevation(j)) +=
            (M[i] * M[j] * p.inv_dt - th * advect_i * M[j]) * JxW;  // (8) (9)
      for (int b = 0; b < 6; ++b)
        for (int d = 0; d < 2; ++d)
          K(row, local_velocity(b, d)) -= th * dM[i][d] * H_k * N[b] * JxW;  // (9)
      double rhs = M[i] * eta_d * p.inv_dt;                                  // (8)
      rhs += -th * advect_i * eta_k + (1 - th) * dM[i].dot(flux_n);          // (9)
      rhs += M[i] * S;                                                       // (11)
      F(row) += rhs * JxW;
    }
  }
}

}  // namespace

void assemble_element(const AssemblyParameters& p, const ElementValues& ev, const ElementState& s,
                      LocalMatrix& K, LocalVector& F) {
  if (p.characteristics)
    assemble<false>(p, ev, s, K, F);
  else
    assemble<true>(p, ev, s, K, F);
}

void assemble_explicit_momentum(const AssemblyParameters& p, const ElementValues& ev,
                                const ElementState& s, std::array<Vec2, 6>& F) {
  F.fill(Vec2::Zero());
  const double weight = 1.0 - p.theta;
  for (int q = 0; q < triangle_point_count; ++q) {
    const auto& N = ev.N2[q];
    Vec2 u_n = Vec2::Zero(), grad_eta_n = Vec2::Zero();
    for (int b = 0; b < 6; ++b) u_n += N[b] * Vec2(s.u_n[b], s.v_n[b]);
    for (int j = 0; j < 3; ++j) grad_eta_n += s.eta_n[j] * ev.dN1[q][j];
    const Vec2 acceleration = p.gravity * grad_eta_n + p.coriolis * Vec2(-u_n.y(), u_n.x());
    for (int a = 0; a < 6; ++a) F[a] -= weight * N[a] * acceleration * ev.JxW[q];  // (3) (6)
  }
}

std::array<double, 2> open_boundary_flux(double theta, const EdgeValues& ev, const EdgeState& s) {
  std::array<double, 2> flux = {0.0, 0.0};
  for (int q = 0; q < edge_point_count; ++q) {
    const auto& N = ev.N2[q];
    const auto& M = ev.N1[q];
    const double z_b = N[0] * s.z_b[0] + N[1] * s.z_b[1] + N[2] * s.z_b[2];
    const double H_k = M[0] * s.eta_k[0] + M[1] * s.eta_k[1] - z_b;
    const double H_n = M[0] * s.eta_n[0] + M[1] * s.eta_n[1] - z_b;
    const Vec2 u_new = N[0] * s.u_new[0] + N[1] * s.u_new[1] + N[2] * s.u_new[2];
    const Vec2 u_n = N[0] * s.u_n[0] + N[1] * s.u_n[1] + N[2] * s.u_n[2];
    const double qn = (theta * H_k * u_new + (1 - theta) * H_n * u_n).dot(ev.normal[q]);  // (10)
    for (int i = 0; i < 2; ++i) flux[i] += M[i] * qn * ev.ds[q];
  }
  return flux;
}

}  // namespace flotsam
