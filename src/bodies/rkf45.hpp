#pragma once
// Runge-Kutta-Fehlberg 4(5) with adaptive step control (spec 3.5 = paper (26)-(30), Table 1
// with its dropped signs restored), generic over the state size so that tests run it on
// y' = -y and an oscillator, and the bodies on their 6-component state.
//
//   k_i = f(t + c_i h, y + h sum_j a_ij k_j),  i = 1..6
//   y5  = y + h sum b_i k_i        (5th order, the solution carried on: local extrapolation)
//   err =     h sum (b_i - b*_i) k_i
//   |err| = max_i |err_i| / (abs_tol_i + rel_tol_i max(|y_i|, |y5_i|))   (weighted norm, <= 1)
//
// Step control (spec 3.5): h_opt = 0.8 h |err|^(-1/5); |err| > 1: reject, retry with
// max(h_opt, h/2, h_min); else accept and propose min(h_opt, 1.5 h, h_max). The interval's end
// is landed on exactly. Hooks let the caller bound the step (a body moves < l/4 per step) and
// exempt from the error check what a known event sets (friction stopping a body), see NoStepHooks.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

namespace flotsam {

/// Fehlberg's coefficients (spec 3.5 Table 1, corrected signs).
struct Fehlberg {
  static constexpr double c[6] = {0.0, 1.0 / 4, 3.0 / 8, 12.0 / 13, 1.0, 1.0 / 2};
  static constexpr double a[6][5] = {{0, 0, 0, 0, 0},
                                     {1.0 / 4, 0, 0, 0, 0},
                                     {3.0 / 32, 9.0 / 32, 0, 0, 0},
                                     {1932.0 / 2197, -7200.0 / 2197, 7296.0 / 2197, 0, 0},
                                     {439.0 / 216, -8.0, 3680.0 / 513, -845.0 / 4104, 0},
                                     {-8.0 / 27, 2.0, -3544.0 / 2565, 1859.0 / 4104, -11.0 / 40}};
  static constexpr double b5[6] = {16.0 / 135,      0.0,       6656.0 / 12825,
                                   28561.0 / 56430, -9.0 / 50, 2.0 / 55};
  static constexpr double b4[6] = {25.0 / 216, 0.0, 1408.0 / 2565, 2197.0 / 4104, -1.0 / 5, 0.0};
  // b_i - b*_i = 1/360, 0, -128/4275, -2197/75240, 1/50, 2/55
  static constexpr double e[6] = {1.0 / 360,       0.0,      -128.0 / 4275,
                                  -2197.0 / 75240, 1.0 / 50, 2.0 / 55};
};

template <int N>
using RkVector = Eigen::Matrix<double, N, 1>;

/// One embedded step of size h from (t, y), given k1 = f(t, y): the 5th-order solution y5, the
/// 4th-order one y4 and the error estimate err = y5 - y4.
template <int N, class Rhs>
void rkf45_step(Rhs&& f, double t, const RkVector<N>& y, double h, const RkVector<N>& k1,
                RkVector<N>& y5, RkVector<N>& err, RkVector<N>* y4 = nullptr) {
  using F = Fehlberg;
  RkVector<N> k[6];
  k[0] = k1;
  for (int i = 1; i < 6; ++i) {
    RkVector<N> yi = y;
    for (int j = 0; j < i; ++j) yi += (h * F::a[i][j]) * k[j];
    k[i] = f(t + F::c[i] * h, yi);
  }
  RkVector<N> sum5 = RkVector<N>::Zero(), sum_e = RkVector<N>::Zero();
  for (int i = 0; i < 6; ++i) {
    sum5 += F::b5[i] * k[i];
    sum_e += F::e[i] * k[i];
  }
  y5 = y + h * sum5;
  err = h * sum_e;
  if (y4) *y4 = y5 - err;
}

template <int N>
struct Rkf45Options {
  RkVector<N> abs_tol = RkVector<N>::Constant(1e-6);  // per component, in its unit
  RkVector<N> rel_tol = RkVector<N>::Constant(1e-6);  // [-]
  double h_min = 1e-9;                                // [s]
  double h_max = 1e30;                                // [s]
};

struct Rkf45Counters {
  long accepted = 0;  // accepted steps
  long rejected = 0;  // rejected and retried steps
};

/// Weighted error norm of spec 3.5: the step is acceptable when it is <= 1.
template <int N>
double rkf45_error_norm(const RkVector<N>& err, const RkVector<N>& y, const RkVector<N>& y5,
                        const Rkf45Options<N>& options) {
  double norm = 0.0;
  for (int i = 0; i < N; ++i) {
    const double scale =
        options.abs_tol[i] + options.rel_tol[i] * std::max(std::abs(y[i]), std::abs(y5[i]));
    norm = std::max(norm, std::abs(err[i]) / scale);
  }
  return norm;
}

/// h_opt = 0.8 h (1/|err|)^(1/5) (spec 3.5), with |err| the weighted norm (tolerance 1).
double rkf45_optimal_step(double h, double error_norm);

/// The weighted error of a trial step from y to y_new after the hooks' event (which may set
/// components of y_new, e.g. zero a stopped velocity): the components the event set are exact by
/// the event and carry no error; every other component must meet its tolerance as usual. (A
/// step that ends in an event is not accepted whatever its error: a long step across a stop can
/// carry a wildly wrong velocity or position in the components the event did not set.)
template <int N, class Hooks>
double rkf45_event_error_norm(Hooks&& hooks, const RkVector<N>& y, RkVector<N>& y_new,
                              RkVector<N> err, const Rkf45Options<N>& options) {
  const RkVector<N> before = y_new;
  if (hooks.event(y, y_new))
    for (int i = 0; i < N; ++i)
      if (y_new[i] != before[i]) err[i] = 0.0;
  return rkf45_error_norm<N>(err, y, y_new, options);
}

/// The step control of spec 3.5 after a trial step of length `step` from t (h_try before the
/// landing was cut to t1 - t; `lands`: the step ends at t1) with weighted error `norm`:
/// rejected (returns false, h = the retry's step) unless norm <= 1 or step <= h_min; accepted
/// (returns true, t = the step's end, h = the next step's proposal). A norm that is not a number
/// (a state that overflowed in the trial) rejects the step like an infinite one.
inline bool rkf45_control(double& t, double& h, double t1, double h_try, double step, bool lands,
                          double norm, double h_min, double h_max, Rkf45Counters& counters) {
  if (std::isnan(norm)) norm = std::numeric_limits<double>::infinity();
  const double h_opt = rkf45_optimal_step(step, norm);
  if (norm > 1.0 && step > h_min) {  // reject, retry smaller
    ++counters.rejected;
    h = std::max({h_opt, 0.5 * step, h_min});
    return false;
  }
  ++counters.accepted;
  const double grown = std::min({h_opt, 1.5 * step, h_max});
  h = lands && step < h_try ? std::max(h_try, grown) : grown;  // a short landing step
  t = lands ? t1 : t + step;                                   // keeps the proposal
  return true;
}

/// No extra step bound and no events.
struct NoStepHooks {
  template <class Y>
  double max_step(double /*t*/, const Y& /*y*/) const {
    return 1e300;
  }
  /// Called with a step's start and end; true when an event has set components of y_new (they
  /// are then exempt from the step's error check, rkf45_event_error_norm).
  template <class Y>
  bool event(const Y& /*y*/, Y& /*y_new*/) const {
    return false;
  }
  /// Called after each accepted step with k1 of that step (e.g. to record forces).
  template <class Y>
  void accepted(double /*t*/, const Y& /*y*/) const {}
};

/// Integrates y' = f(t, y) from t0 to t1 (landing exactly on t1). `h` holds the first step to
/// try and receives the step proposed for what follows. f(t, y) returns y'; `first(t, y)`
/// evaluates k1 (the same f, or one that also records the loads at the step start).
template <int N, class Rhs, class First, class Hooks = NoStepHooks>
RkVector<N> rkf45_integrate(Rhs&& f, First&& first, double t0, double t1, RkVector<N> y, double& h,
                            const Rkf45Options<N>& options, Rkf45Counters& counters,
                            Hooks&& hooks = Hooks{}) {
  double t = t0;
  h = std::clamp(h > 0.0 ? h : t1 - t0, options.h_min, options.h_max);
  while (t < t1) {
    const RkVector<N> k1 = first(t, y);
    const double h_bound = std::max(options.h_min, hooks.max_step(t, y));
    for (;;) {
      const double h_try = std::min(h, h_bound);
      const bool lands = h_try >= t1 - t;
      const double step = lands ? t1 - t : h_try;
      RkVector<N> y5, err;
      rkf45_step<N>(f, t, y, step, k1, y5, err);
      const double norm = rkf45_event_error_norm<N>(hooks, y, y5, err, options);
      if (!rkf45_control(t, h, t1, h_try, step, lands, norm, options.h_min, options.h_max,
                         counters))
        continue;  // rejected: retry smaller
      y = y5;
      hooks.accepted(t, y);
      break;
    }
  }
  return y;
}

}  // namespace flotsam
