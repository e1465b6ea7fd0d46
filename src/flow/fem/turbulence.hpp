#pragma once
// Eddy viscosity per element (spec 1.2, (M-3)), from the element averages of u, H and grad u:
//   smagorinsky:    nu_t = (C_s Delta)^2 sqrt(2 D:D),  Delta = sqrt(2 A_e)
//   mixing-length:  nu_t = sqrt( (alpha_b u_star H)^2 + (l_m^2 sqrt(2 D:D))^2 ),
//                   u_star = sqrt(c_f) |u|,  l_m = kappa 0.267 H,  alpha_b = 0.0667, kappa = 0.41
// with D = (grad u + grad u^T) / 2.
#include <array>

#include "core/vec.hpp"
#include "flow/fem/element_values.hpp"
#include "flow/friction.hpp"
#include "io/case.hpp"

namespace flotsam {

struct ElementFlowAverage {
  Vec2 u = Vec2::Zero();       // [m/s]
  double H = 0.0;              // [m]
  Mat2 grad_u = Mat2::Zero();  // [1/s]
  double area = 0.0;           // A_e [m^2]
};

constexpr double elder_constant = 0.0667;  // alpha_b [-], Elder (1959)
constexpr double von_karman = 0.41;        // kappa [-]

/// The element's averages of u, grad u and H = eta - z_b from its P2 velocity (u, v [m/s]) and bed
/// (z_b [m]) and its P1 elevation (eta [m]), by the element's quadrature.
ElementFlowAverage element_flow_average(const ElementValues& ev, const std::array<double, 6>& u,
                                        const std::array<double, 6>& v,
                                        const std::array<double, 6>& z_b,
                                        const std::array<double, 3>& eta);

/// nu_t [m^2/s] of one element.
double eddy_viscosity(TurbulenceModel model, double C_s, const FrictionModel& friction,
                      const ElementFlowAverage& average);

}  // namespace flotsam
