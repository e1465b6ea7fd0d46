// ShallowWaterSolver: the time step, the steady solve, the boundary velocities, the water balance
// and the state checks (the outline's run loop; assembly is in shallow_water_solver.cpp).
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "flow/shallow_water_solver.hpp"

namespace flotsam {

namespace {

double max_abs(const std::vector<double>& a) {
  double m = 0.0;
  for (double x : a) m = std::max(m, std::abs(x));
  return m;
}

double max_abs_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0.0;
  for (size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

}  // namespace

StepReport ShallowWaterSolver::step(double dt) {
  previous_ = state_;
  const double t_new = previous_.time + dt;
  const double theta = options_.theta;
  const bool characteristics = options_.advection == Advection::characteristics;
  const Iteration it{theta, 1.0 / dt, t_new, previous_.time + theta * dt, characteristics};
  if (characteristics)  // the advection stage of the fractional step
    characteristics_->advect(previous_.u, previous_.v, dt, u_departure_, v_departure_);
  const double u_scale = 1e-3 * std::sqrt(case_.flow.gravity * H_mean_);  // [m/s]
  StepReport report;
  Eigen::VectorXd x;
  try {
    for (report.iterations = 1; report.iterations <= options_.max_iterations; ++report.iterations) {
      set_boundary_velocities(it);
      linearisation_ = state_;
      assemble_system(it);
      apply_boundary_conditions(it);
      x = solve();
      unpack(x);
      state_.time = t_new;
      check_state(state_, t_new);
      const double du = std::max(max_abs_difference(state_.u, linearisation_.u),
                                 max_abs_difference(state_.v, linearisation_.v));
      const double u_max = std::max({max_abs(state_.u), max_abs(state_.v), u_scale});
      report.last_change =
          std::max(du / u_max, max_abs_difference(state_.eta, linearisation_.eta) / H_mean_);
      if (report.last_change < options_.iteration_tolerance) break;
    }
  } catch (const RunError&) {
    state_ = previous_;
    throw;
  }
  report.iterations = std::min(report.iterations, options_.max_iterations);
  update_balance(it, dt, x);
  return report;
}

SteadyReport ShallowWaterSolver::solve_steady() {
  const auto& flow = case_.flow;
  double dt = options_.steady_initial_dt;
  if (dt <= 0.0) {
    double h_min = std::numeric_limits<double>::max(), H_max = 0.0;
    for (double a : mesh_.area) h_min = std::min(h_min, std::sqrt(2.0 * a));
    for (int j = 0; j < mesh_.vertex_count; ++j) H_max = std::max(H_max, state_.eta[j] - z_b_[j]);
    dt = 10.0 * h_min / std::sqrt(flow.gravity * H_max);
  }
  const double t = state_.time;
  SteadyReport report;
  double r0 = 0.0;
  int retries = 0;
  const double dt_0 = dt;
  // [s] cap of the pseudo step: a little time term keeps the linearised steady problem regular
  // where it is not (closed basins, whose mean level only the time term fixes; u = 0, where the
  // friction Jacobian vanishes).
  const double dt_max = options_.steady_max_dt_factor * dt_0;
  for (int k = 0; k < case_.time.steady_max_iterations; ++k) {
    // A backward-Euler pseudo step from the current state: at its first iterate the time term
    // vanishes, so b - A x is the steady residual.
    const Iteration it{1.0, 1.0 / dt, t, t, false};  // the steady equations are Eulerian
    set_boundary_velocities(it);
    previous_ = state_;
    linearisation_ = state_;
    assemble_system(it);
    apply_boundary_conditions(it);
    const double r = residual_norm(pack(state_));
    if (k == 0) r0 = r > 0.0 ? r : 1.0;
    report.residuals.push_back(r / r0);
    report.iterations = k;
    if (r / r0 < case_.time.steady_tolerance) {
      report.converged = true;
      break;
    }
    const Eigen::VectorXd x = solve();
    unpack(x);
    try {
      check_state(state_, t);
    } catch (const RunError&) {
      // Newton went too far from a state far from steady: retry with a smaller pseudo step.
      state_ = previous_;
      dt *= 0.25;
      if (++retries > 20) throw;
      continue;
    }
    record_fluxes(x);
    // Switched evolution relaxation (Mulder & van Leer 1985): dt grows as the residual falls.
    dt = std::min(dt_max, std::max(dt, dt_0 * r0 / r));
  }
  previous_ = state_;  // a steady flow: du/dt = 0
  // Pseudo time is not time: the steady state starts a new water balance.
  const std::vector<double> rates = balance_.group_rate;
  balance_ = WaterBalance{};
  balance_.initial_volume = balance_.volume = volume();
  balance_.group_outflow.assign(mesh_.group_names.size(), 0.0);
  balance_.group_rate = rates;
  return report;
}

double ShallowWaterSolver::residual_norm(const Eigen::VectorXd& x) const {
  Eigen::VectorXd r = system_.b - system_.A * x;
  // Continuity rows [m^3/s] scaled by sqrt(g / H) to the momentum rows' [m^3/s^2].
  const double scale = std::sqrt(case_.flow.gravity / H_mean_);
  for (int j = 0; j < mesh_.vertex_count; ++j) r[system_.eta_row(j)] *= scale;
  return r.norm();
}

// Boundary velocities at t^{n+1}: velocity and zero nodes take their value; discharge nodes
// u_i = -n_i c sqrt(H_i), with I = sum over the group's edges of <H^k, sum_m N_m sqrt(H_m)
// n_m . n> and c chosen so that term (10), theta c I + (1 - theta) <H^n u^n . n>, carries exactly
// the theta-weighted discharge theta Q(t^{n+1}) + (1 - theta) Q(t^n) in.
void ShallowWaterSolver::set_boundary_velocities(const Iteration& it) {
  const double t = it.t_new, th = it.theta;
  const auto& conditions = case_.flow.boundaries;
  auto node_depth = [&](int node) {
    if (node < mesh_.vertex_count) return state_.eta[node] - z_b_[node];
    const auto& ends = mid_vertices_[node];
    return 0.5 * (state_.eta[ends[0]] + state_.eta[ends[1]]) - z_b_[node];
  };
  std::vector<Vec2> normal(mesh_.node_count(), Vec2::Zero());
  for (const auto& n : bc_.velocity_nodes) normal[n.node] = n.normal;
  std::vector<double> integral(conditions.size(), 0.0), flux_n(conditions.size(), 0.0);
  EdgeValues ev;
  for (const auto& open : bc_.open_edges) {
    if (conditions[open.condition].kind != BoundaryCondition::Kind::discharge) continue;
    compute_edge_values(mesh_, mesh_.boundary[open.boundary_edge], ev);
    for (int q = 0; q < edge_point_count; ++q) {
      double H = ev.N1[q][0] * state_.eta[ev.nodes[0]] + ev.N1[q][1] * state_.eta[ev.nodes[1]];
      double U_n = 0.0;
      for (int m = 0; m < 3; ++m) {
        const int node = ev.nodes[m];
        H -= ev.N2[q][m] * z_b_[node];
        U_n += ev.N2[q][m] * std::sqrt(std::max(node_depth(node), 0.0)) *
               normal[node].dot(ev.normal[q]);
      }
      integral[open.condition] += H * U_n * ev.ds[q];
    }
    // The outflow <H^n u^n . n> of t^n, as term (10) computes it (theta = 0 selects it).
    EdgeState s;
    for (int m = 0; m < 3; ++m) {
      s.z_b[m] = z_b_[ev.nodes[m]];
      s.u_n[m] = s.u_new[m] = Vec2(previous_.u[ev.nodes[m]], previous_.v[ev.nodes[m]]);
      if (m < 2) s.eta_n[m] = s.eta_k[m] = previous_.eta[ev.nodes[m]];
    }
    const auto outflow = open_boundary_flux(0.0, ev, s);
    flux_n[open.condition] -= outflow[0] + outflow[1];  // [m^3/s] in
  }
  for (const auto& n : bc_.velocity_nodes) {
    Vec2 u_b = Vec2::Zero();
    if (n.kind == VelocityNode::Kind::velocity) {
      u_b = Vec2(conditions[n.condition].value(t), conditions[n.condition].value_y(t));
    } else if (n.kind == VelocityNode::Kind::discharge) {
      const auto& Q = conditions[n.condition];
      const double Q_in =
          th * Q.value(t) + (1 - th) * (Q.value(previous_.time) - flux_n[n.condition]);
      const double c = Q_in / (th * integral[n.condition]);
      u_b = -n.normal * c * std::sqrt(std::max(node_depth(n.node), 0.0));
    }
    state_.u[n.node] = u_b.x();
    state_.v[n.node] = u_b.y();
  }
}

void ShallowWaterSolver::record_fluxes(const Eigen::VectorXd& x) {
  balance_.group_rate.assign(mesh_.group_names.size(), 0.0);
  for (size_t g = 0; g < open_flux_.size(); ++g) balance_.group_rate[g] += open_flux_[g];
  for (size_t k = 0; k < bc_.elevation_nodes.size(); ++k)
    balance_.group_rate[elevation_group_[k]] -= system_.saved_row_residual(static_cast<int>(k), x);
}

void ShallowWaterSolver::update_balance(const Iteration& it, double dt, const Eigen::VectorXd& x) {
  record_fluxes(x);
  for (size_t g = 0; g < balance_.group_rate.size(); ++g) {
    balance_.group_outflow[g] += dt * balance_.group_rate[g];
    balance_.outflow += dt * balance_.group_rate[g];
  }
  if (options_.source) {
    ElementValues ev;
    for (int e = 0; e < mesh_.element_count(); ++e) {
      compute_element_values(mesh_, e, ev);
      for (int q = 0; q < triangle_point_count; ++q)
        balance_.source += dt * options_.source(ev.x[q], it.t_source).continuity * ev.JxW[q];
    }
  }
  balance_.volume = volume();
}

void ShallowWaterSolver::check_state(const FlowState& s, double t) const {
  auto tag = [&](int node) { return mesh_.node_tags.empty() ? long{node} : mesh_.node_tags[node]; };
  for (int i = 0; i < mesh_.node_count(); ++i) {
    const Vec2& p = mesh_.nodes[i];
    if (!std::isfinite(s.u[i]) || !std::isfinite(s.v[i]))
      throw_run_error(
          "flow: t = {:.6g} s: velocity is not finite at node {} ({:.6g}, {:.6g}) "
          "(instability: reduce the time step or refine the mesh)",
          t, tag(i), p.x(), p.y());
    const bool vertex = i < mesh_.vertex_count;
    const double eta =
        vertex ? s.eta[i] : 0.5 * (s.eta[mid_vertices_[i][0]] + s.eta[mid_vertices_[i][1]]);
    if (!std::isfinite(eta))
      throw_run_error(
          "flow: t = {:.6g} s: elevation eta is not finite at node {} ({:.6g}, "
          "{:.6g}) (instability: reduce the time step or refine the mesh)",
          t, tag(i), p.x(), p.y());
    const double H = eta - z_b_[i];
    if (H < case_.flow.dry_depth)
      throw_run_error(
          "flow: t = {:.6g} s: node {} ({:.6g}, {:.6g}) dried: depth H = {:.6g} m "
          "below the dry depth {} m (the FEM engine needs a wet domain, spec 1.5)",
          t, tag(i), p.x(), p.y(), H, case_.flow.dry_depth);
  }
}

double ShallowWaterSolver::march_to_steady(double dt, double settled, double t_max) {
  double change = 1.0;  // [-] max |u^{n+1} - u^n| / max |u^{n+1}|
  while (change > settled && state_.time < t_max) {
    const FlowState before = state_;
    step(dt);
    double du = 0.0, u_max = 0.0;
    for (std::size_t n = 0; n < before.u.size(); ++n) {
      du = std::max(du, std::hypot(state_.u[n] - before.u[n], state_.v[n] - before.v[n]));
      u_max = std::max(u_max, std::hypot(state_.u[n], state_.v[n]));
    }
    change = u_max > 0.0 ? du / u_max : 0.0;
  }
  return change;
}

}  // namespace flotsam
