#include "flow/fem/turbulence.hpp"

#include <algorithm>
#include <cmath>

namespace flotsam {

ElementFlowAverage element_flow_average(const ElementValues& ev, const std::array<double, 6>& u,
                                        const std::array<double, 6>& v,
                                        const std::array<double, 6>& z_b,
                                        const std::array<double, 3>& eta) {
  ElementFlowAverage avg;
  for (int q = 0; q < triangle_point_count; ++q) {
    const double w = ev.JxW[q];
    avg.area += w;
    for (int b = 0; b < 6; ++b) {
      const Vec2 ub(u[b], v[b]);
      avg.u += w * ev.N2[q][b] * ub;
      avg.grad_u += w * ub * ev.dN2[q][b].transpose();
      avg.H -= w * ev.N2[q][b] * z_b[b];
    }
    for (int j = 0; j < 3; ++j) avg.H += w * ev.N1[q][j] * eta[j];
  }
  avg.u /= avg.area;
  avg.grad_u /= avg.area;
  avg.H /= avg.area;
  return avg;
}

double eddy_viscosity(TurbulenceModel model, double C_s, const FrictionModel& friction,
                      const ElementFlowAverage& a) {
  if (model == TurbulenceModel::none) return 0.0;
  const Mat2 D = 0.5 * (a.grad_u + a.grad_u.transpose());
  const double strain = std::sqrt(2.0 * D.cwiseProduct(D).sum());  // sqrt(2 D:D) [1/s]
  if (model == TurbulenceModel::smagorinsky) {
    const double Delta = std::sqrt(2.0 * a.area);  // [m]
    return C_s * Delta * C_s * Delta * strain;     // (M-3), smagorinsky
  }
  const double H = std::max(a.H, friction.min_depth);
  const double u_star = std::sqrt(friction.coefficient_at(H)) * a.u.norm();  // [m/s]
  const double l_m = von_karman * 0.267 * H;                                 // [m]
  const double bed_part = elder_constant * u_star * H;
  const double shear_part = l_m * l_m * strain;
  return std::sqrt(bed_part * bed_part + shear_part * shear_part);  // (M-3), mixing-length
}

}  // namespace flotsam
