#pragma once
// Stoker's exact dam break onto a wet bed (Stoker 1957, Water waves, ch. 10; SWASHES 4.1.1,
// Delestre et al. 2013): depth h_l behind the dam, h_r in front, water at rest, frictionless and
// flat. A rarefaction runs into the left, a constant state (h_m, u_m) follows, a shock runs into
// the right. h_m solves, by Newton,
//   u_m = 2 (c_l - c_m)                                    (the left rarefaction's invariant)
//   u_m = (h_m - h_r) sqrt(g (h_m + h_r) / (2 h_m h_r))    (the shock's jump conditions)
// with c = sqrt(g h); the shock moves at s = h_m u_m / (h_m - h_r).
#include <cmath>

namespace flotsam::test {

struct Stoker {
  double g, h_l, h_r;  // [m s^-2], [m], [m]
  double h_m, u_m;     // [m], [m/s] between the rarefaction and the shock
  double s;            // [m/s] shock speed

  Stoker(double gravity, double left, double right) : g(gravity), h_l(left), h_r(right) {
    const double c_l = std::sqrt(g * h_l);
    // f(h) = 2 (c_l - sqrt(g h)) - (h - h_r) k(h), k(h) = sqrt(g (h + h_r) / (2 h h_r))
    auto k = [&](double h) { return std::sqrt(g * (h + h_r) / (2.0 * h * h_r)); };
    double h = 0.5 * (h_l + h_r);
    for (int n = 0; n < 50; ++n) {
      const double f = 2.0 * (c_l - std::sqrt(g * h)) - (h - h_r) * k(h);
      const double dk = -g / (4.0 * h * h * k(h));  // k'(h) = -g / (4 h^2 k)
      const double df = -std::sqrt(g / h) - k(h) - (h - h_r) * dk;
      h -= f / df;
    }
    h_m = h;
    u_m = 2.0 * (c_l - std::sqrt(g * h));
    s = h * u_m / (h - h_r);
  }

  /// Depth [m] and unit discharge [m^2/s] at xi = (x - x_dam) / t [m/s].
  struct State {
    double h, hu;
  };
  State at(double xi) const {
    const double c_l = std::sqrt(g * h_l), c_m = std::sqrt(g * h_m);
    if (xi <= -c_l) return {h_l, 0.0};
    if (xi <= u_m - c_m) {
      const double h = (2.0 * c_l - xi) * (2.0 * c_l - xi) / (9.0 * g);
      return {h, h * 2.0 / 3.0 * (xi + c_l)};
    }
    if (xi <= s) return {h_m, h_m * u_m};
    return {h_r, 0.0};
  }
};

}  // namespace flotsam::test
