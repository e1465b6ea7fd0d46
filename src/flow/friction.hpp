#pragma once
// Bed friction (spec 1.1, (M-2)): F_friction = - c_f |u| u / H, with the dimensionless friction
// coefficient c_f of the chosen law:
//   Manning n [s m^-1/3]:   c_f = g n^2 / H^(1/3)     (F = - g n^2 |u| u / H^(4/3))
//   Strickler K = 1/n:      as Manning
//   Chezy C [m^1/2 s^-1]:   c_f = g / C^2             (F = - g |u| u / (C^2 H))
//   none:                   c_f = 0
// H is bounded below by H_min before it is used (spec 1.1). The law's coefficient (n, K or C) is
// the case's default, or the one of a place where it varies (flow/friction_map.hpp): each
// function takes it explicitly, or uses the default.
#include "io/case.hpp"

namespace flotsam {

struct FrictionModel {
  FrictionLaw law = FrictionLaw::none;
  double coefficient = 0.0;  // n, C or K as the law says: the default
  double gravity = 9.81;     // g [m s^-2]
  double min_depth = 1e-3;   // H_min [m]

  static FrictionModel from(const FlowConfig& flow);

  /// c_f [-] at depth H [m] (H bounded below by H_min), with the law's coefficient `k`.
  double coefficient_at(double H, double k) const;
  double coefficient_at(double H) const { return coefficient_at(H, coefficient); }

  /// gamma = c_f |u| / H [1/s]: F_friction = - gamma u.
  double rate(double speed, double H, double k) const;
  double rate(double speed, double H) const { return rate(speed, H, coefficient); }
  /// d gamma / d H [1/(m s)] (Newton's linearisation in the depth); 0 below H_min.
  double rate_depth_derivative(double speed, double H, double k) const;
  double rate_depth_derivative(double speed, double H) const {
    return rate_depth_derivative(speed, H, coefficient);
  }
};

}  // namespace flotsam
