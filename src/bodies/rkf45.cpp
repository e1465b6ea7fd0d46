#include "bodies/rkf45.hpp"

#include <limits>

namespace flotsam {

namespace {

constexpr double safety = 0.8;  // the paper's factor in h_opt [-] (spec 3.5)

}  // namespace

double rkf45_optimal_step(double h, double error_norm) {
  // h_opt = 0.8 h (tol / |err|)^(1/5), tol = 1 for the weighted norm. An exact step (err = 0)
  // may grow without bound here; the caller caps growth at 1.5 h and h_max.
  if (error_norm <= 0.0) return std::numeric_limits<double>::max();
  return safety * h * std::pow(error_norm, -0.2);
}

}  // namespace flotsam
