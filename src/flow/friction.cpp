#include "flow/friction.hpp"

#include <algorithm>
#include <cmath>

namespace flotsam {

FrictionModel FrictionModel::from(const FlowConfig& flow) {
  return {flow.friction, flow.friction_coefficient, flow.gravity, flow.min_depth};
}

double FrictionModel::coefficient_at(double H, double k) const {
  const double h = std::max(H, min_depth);
  switch (law) {
    case FrictionLaw::none:
      return 0.0;
    case FrictionLaw::manning:
      return gravity * k * k / std::cbrt(h);
    case FrictionLaw::strickler:
      return gravity / (k * k * std::cbrt(h));
    case FrictionLaw::chezy:
      return gravity / (k * k);
  }
  return 0.0;
}

double FrictionModel::rate(double speed, double H, double k) const {
  return coefficient_at(H, k) * speed / std::max(H, min_depth);
}

double FrictionModel::rate_depth_derivative(double speed, double H, double k) const {
  if (H <= min_depth) return 0.0;
  // gamma ~ H^-p: p = 4/3 for Manning and Strickler (c_f ~ H^-1/3), 1 for Chezy.
  const double p = law == FrictionLaw::chezy ? 1.0 : 4.0 / 3.0;
  return -p * rate(speed, H, k) / H;
}

}  // namespace flotsam
