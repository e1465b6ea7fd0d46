// ShallowWaterSolver's roads to a steady state: Newton's method on the steady equations with
// continuation in the viscosity (solve_steady), and marching in time (march_to_steady).
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "flow/fem/shallow_water_solver.hpp"

namespace flotsam {

namespace {

constexpr int target_iterations = 40;     // at the case's viscosity, from the initial state
constexpr double stage_tolerance = 1e-4;  // [-] relative residual that ends a continuation stage
constexpr int stage_iterations = 10;      // Newton converges in 4-6 where it converges at all
constexpr double stage_ratio = 10.0;      // [-] largest viscosity ratio between two stages
constexpr double smallest_ratio = 1.02;   // [-] below it the continuation gives up (a fold)

// True when each of the last `count` iterations at least halved the residual: Newton converging
// linearly, as it does when the eddy viscosity (M-3) is lagged in the Jacobian.
bool halving(const SteadyReport& report, size_t count) {
  const auto& r = report.residuals;
  if (r.size() <= count) return false;
  for (size_t k = r.size() - count; k < r.size(); ++k)
    if (!(r[k] <= 0.5 * r[k - 1])) return false;
  return true;
}

}  // namespace

double ShallowWaterSolver::residual_norm(const Eigen::VectorXd& x) const {
  Eigen::VectorXd r = system_.b - system_.A * x;
  // Continuity rows [m^3/s] scaled by sqrt(g / H) to the momentum rows' [m^3/s^2].
  const double scale = std::sqrt(case_.flow.gravity / H_mean_);
  for (int j = 0; j < mesh_.vertex_count; ++j) r[system_.eta_row(j)] *= scale;
  return r.norm();
}

// Assembles the pseudo step from the current state and returns its residual b - A x at x = the
// state, where the pseudo time term vanishes: the residual of the steady equations.
double ShallowWaterSolver::steady_residual(const Iteration& it) {
  previous_ = state_;
  history_ = false;  // pseudo time is not time
  set_boundary_velocities(it);
  linearisation_ = state_;
  assemble_system(it);
  apply_boundary_conditions(it);
  return residual_norm(pack(state_));
}

// Newton's method from the current state with a pseudo time term (pseudo-transient
// continuation): the pseudo step starts at dt; a step that dries a node, is not finite or
// multiplies the residual by ten is taken again with a quarter of the pseudo step, and after an
// accepted one the pseudo step grows as the residual falls (switched evolution relaxation,
// Mulder & van Leer 1985), up to dt_max. True when the residual reaches tolerance * r_ref within
// max_iterations; the state is the last accepted iterate either way.
bool ShallowWaterSolver::newton_to_steady(Iteration it, double dt, double dt_max, double r_ref,
                                          double tolerance, int max_iterations,
                                          SteadyReport& report) {
  const double nu = case_.flow.viscosity + it.added_viscosity;  // [m^2/s]
  it.inv_dt = 1.0 / dt;
  double r = steady_residual(it);
  int retries = 0;
  for (int k = 0;; ++k) {
    report.residuals.push_back(r / r_ref);
    report.viscosities.push_back(nu);
    if (r <= tolerance * r_ref) return true;
    // Newton that stagnates (the residual not halved over three full steps) has failed.
    const size_t n = report.residuals.size();
    if (k == max_iterations ||
        (dt == dt_max && k >= 3 && report.residuals[n - 1] > 0.5 * report.residuals[n - 4]))
      return false;
    const FlowState start = state_;
    double r_new = std::numeric_limits<double>::infinity();
    for (;;) {
      // Newton's matrices change too much from one iteration to the next for a reused LU: on
      // the paper's channel a Krylov solver preconditioned by it took 15 iterations per solve
      // and the solve 50 % longer.
      solver_.refactorise();
      unpack(solve());
      ++report.iterations;
      try {
        check_state(state_, state_.time);
        r_new = steady_residual(it);
      } catch (const RunError&) {  // a node dried or the state is not finite
      }
      if (r_new < 10.0 * r) break;
      state_ = start;
      if (++retries > 10) return false;
      dt *= 0.25;
      it.inv_dt = 1.0 / dt;
      steady_residual(it);
      r_new = std::numeric_limits<double>::infinity();
    }
    const double grown = std::min(dt_max, dt * std::clamp(r / r_new, 1.0, 4.0));
    r = r_new;
    if (grown != dt) {  // the next pseudo step's matrix
      dt = grown;
      it.inv_dt = 1.0 / dt;
      steady_residual(it);
    }
  }
}

SteadyReport ShallowWaterSolver::solve_steady() {
  if (!coupled_system_ready_) setup_coupled_system();  // the steady equations are coupled
  const auto& flow = case_.flow;
  double h_min = std::numeric_limits<double>::max(), h_max = 0.0, H_max = 0.0;
  for (double a : mesh_.area) {
    h_min = std::min(h_min, std::sqrt(2.0 * a));
    h_max = std::max(h_max, std::sqrt(2.0 * a));
  }
  for (int j = 0; j < mesh_.vertex_count; ++j) H_max = std::max(H_max, state_.eta[j] - z_b_[j]);
  const double dt_max = options_.steady_pseudo_dt > 0.0
                            ? options_.steady_pseudo_dt
                            : 1e5 * h_min / std::sqrt(flow.gravity * H_max);  // [s]
  const double t = state_.time, tolerance = case_.time.steady_tolerance;
  const int budget = case_.time.steady_max_iterations;
  Iteration it{1.0, 1.0 / dt_max, t, t, false};  // backward-Euler pseudo steps, Eulerian form
  const double r0 = steady_residual(it);
  const double r_ref = r0 > 0.0 ? r0 : 1.0;
  const FlowState initial = state_;
  SteadyReport report;
  // Newton (pseudo step dt_max) at the case's viscosity; when it fails, again from the initial
  // state along its transient (pseudo step from 10 h_min / sqrt(g H), growing).
  report.converged = newton_to_steady(it, dt_max, dt_max, r_ref, tolerance,
                                      std::min(budget, stage_iterations), report);
  // With an eddy viscosity Newton converges only linearly (a quarter per iteration on the
  // paper's channel with the mixing length): it goes on while it still halves the residual.
  while (!report.converged && report.iterations < budget && halving(report, 3))
    report.converged =
        newton_to_steady(it, dt_max, dt_max, r_ref, tolerance,
                         std::min(budget - report.iterations, stage_iterations), report);
  if (!report.converged) {
    state_ = initial;
    report.converged = newton_to_steady(it, 1e-4 * dt_max, dt_max, r_ref, tolerance,
                                        std::min(budget, target_iterations), report);
  }
  // When that fails, continuation in the viscosity. First stage: a viscosity of |u| h_max / 2
  // with the gravity wave speed for |u| (a cell Reynolds number of 1), from the initial state,
  // raised tenfold until the steady state is found.
  double added = 0.5 * std::sqrt(flow.gravity * H_mean_) * h_max;  // [m^2/s]
  bool found = report.converged;
  for (int attempt = 0; !found && attempt < 3 && report.iterations < budget; ++attempt) {
    state_ = initial;
    it.added_viscosity = added;
    found = newton_to_steady(it, dt_max, dt_max, r_ref, stage_tolerance, stage_iterations, report);
    if (!found) added *= 10.0;
  }
  // Down to the case's viscosity: each stage starts from the last one's steady state; the ratio
  // between stages grows back to tenfold after a quick stage and shrinks after a failed one.
  FlowState good = state_;
  double ratio = stage_ratio;
  while (found && !report.converged && report.iterations < budget && ratio > smallest_ratio) {
    const double next = std::max(0.0, (flow.viscosity + added) / ratio - flow.viscosity);
    it.added_viscosity = next;
    const int before = report.iterations;
    const bool last = next == 0.0;
    if (newton_to_steady(it, dt_max, dt_max, r_ref, last ? tolerance : stage_tolerance,
                         stage_iterations, report)) {
      good = state_;
      added = next;
      report.converged = last;
      if (report.iterations - before <= 4) ratio = std::min(ratio * ratio, stage_ratio);
    } else {  // half the step in log(viscosity)
      state_ = good;
      ratio = std::sqrt(std::min(ratio, (flow.viscosity + added) / flow.viscosity));
    }
  }
  if (!found) state_ = initial;
  report.viscosity = report.converged ? flow.viscosity : found ? flow.viscosity + added : 0.0;
  // The water balance restarts at the state found (pseudo time is not time), with its fluxes.
  it.added_viscosity = report.converged ? 0.0 : added;
  steady_residual(it);
  record_fluxes(pack(state_));
  const std::vector<double> rates = balance_.group_rate;
  restart_water_balance();
  balance_.group_rate = rates;
  return report;
}

double ShallowWaterSolver::march_to_steady(double dt, double settled, double t_max) {
  double change = 1.0;  // [-]
  while (change > settled && state_.time < t_max) {
    step(dt);  // keeps the state before it in previous_
    change = last_step_change();
  }
  return change;
}

double ShallowWaterSolver::last_step_change() const {
  double du = 0.0, u_max = 0.0;  // [m/s]
  for (std::size_t n = 0; n < state_.u.size(); ++n) {
    du = std::max(du, std::hypot(state_.u[n] - previous_.u[n], state_.v[n] - previous_.v[n]));
    u_max = std::max(u_max, std::hypot(state_.u[n], state_.v[n]));
  }
  return u_max > 0.0 ? du / u_max : 0.0;
}

}  // namespace flotsam
