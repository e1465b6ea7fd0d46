// ShallowWaterSolver: the time step, the boundary velocities, the water balance and the state
// checks (the outline's run loop; assembly is in shallow_water_solver.cpp, the steady state in
// steady_state.cpp).
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "flow/fem/shallow_water_solver.hpp"

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
  if (segregated_) return segregated_->step(*this, dt);
  return step_coupled(dt);
}

StepReport ShallowWaterSolver::step_coupled(double dt) {
  if (history_) std::swap(before_, previous_);  // t^{n-1}
  previous_ = state_;
  const Iteration it = time_step(dt);
  if (it.characteristics) departure_values(it, dt);  // the advection stage of the fractional step
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
      state_.time = it.t_new;
      check_state(state_, it.t_new);
      const double du = std::max(max_abs_difference(state_.u, linearisation_.u),
                                 max_abs_difference(state_.v, linearisation_.v));
      const double u_max = std::max({max_abs(state_.u), max_abs(state_.v), u_scale});
      report.last_change =
          std::max(du / u_max, max_abs_difference(state_.eta, linearisation_.eta) / H_mean_);
      if (report.last_change < options_.iteration_tolerance) break;
    }
  } catch (const RunError&) {
    state_ = previous_;
    if (history_) previous_ = before_;
    throw;
  }
  report.iterations = std::min(report.iterations, options_.max_iterations);
  update_balance(it, dt, x);
  history_ = true;
  return report;
}

// The time term of a step of dt (docs/model.md "Time scheme"). The theta-scheme: (u - u^n)/dt.
// BDF2 with steps of any length, omega = dt / dt_before [-]:
//   (u^{n+1} - u_d) inv_dt,  inv_dt = (1 + 2 omega) / ((1 + omega) dt),
//   u_d = ((1 + omega)^2 u^n - omega^2 u^{n-1}) / (1 + 2 omega),
// which is (3 u^{n+1} - 4 u^n + u^{n-1}) / (2 dt) at equal steps; every other term at t^{n+1}.
// Without a history (the first step) u^{n-1} = u^n, omega = 1: (u^{n+1} - u^n) 3 / (2 dt).
ShallowWaterSolver::Iteration ShallowWaterSolver::time_step(double dt) const {
  const double t_n = previous_.time, t_new = t_n + dt;
  const bool characteristics = options_.advection == Advection::characteristics;
  if (case_.time.scheme == TimeScheme::theta) {
    const double th = case_.time.theta;
    return {th, 1.0 / dt, t_new, t_n + th * dt, characteristics};
  }
  Iteration it{1.0, 1.5 / dt, t_new, t_new, characteristics};
  if (!history_) return it;
  it.dt_before = t_n - before_.time;
  const double omega = dt / it.dt_before;
  it.inv_dt = (1.0 + 2.0 * omega) / ((1.0 + omega) * dt);
  it.now = (1.0 + omega) * (1.0 + omega) / (1.0 + 2.0 * omega);
  it.before = -omega * omega / (1.0 + 2.0 * omega);
  return it;
}

// The advection stage (spec 1.3), the time term's start u_d at the paths' feet.
//
// BDF2: u^n at the foot at t^n and u^{n-1} at the foot at t^{n-1}, on paths of the velocity
// linear in time through u^{n-1} and u^n (extrapolated between t^n and t^{n+1}).
//
// The theta-scheme: the field u^n + dt a^n, where a^n is the explicit part of the surface slope
// and Coriolis terms, -(1-theta) (g grad eta^n + f k x u^n), projected on P2, is carried along
// the paths of u^n to every node. The explicit terms are then taken where the water was at t^n,
// the departure point, rather than where it arrives: the steady state of the scheme then
// differs from the Eulerian one by O((theta - 1/2) dt) instead of O(dt / 2).
void ShallowWaterSolver::departure_values(const Iteration& it, double dt) {
  const FlowState& n = previous_;
  if (case_.time.scheme == TimeScheme::bdf2) {
    if (it.before == 0.0) {
      characteristics_->advect(n.u, n.v, dt, n.u, n.v, u_departure_, v_departure_);
      return;
    }
    std::vector<double> u_before, v_before;  // [m/s] u^{n-1} at the foot at t^{n-1}
    const Foot feet[2] = {{dt, n.u, n.v, u_departure_, v_departure_},
                          {dt + it.dt_before, before_.u, before_.v, u_before, v_before}};
    characteristics_->advect(PathVelocity{n.u, n.v, before_.u, before_.v, it.dt_before}, dt, feet);
    for (int i = 0; i < mesh_.node_count(); ++i) {
      u_departure_[i] = it.now * u_departure_[i] + it.before * u_before[i];
      v_departure_[i] = it.now * v_departure_[i] + it.before * v_before[i];
    }
    return;
  }
  // The nodal values at t^n only: with `characteristics` element_state would also read the
  // departure values, which this pass is computing.
  Iteration explicit_part = it;
  explicit_part.characteristics = false;
  const AssemblyParameters p = assembly_parameters(it);
  const int count = mesh_.node_count();
  std::vector<double> a_x(count, 0.0), a_y(count, 0.0);  // [m^3 s^-2] load, then [m s^-2]
  for_each_element([&](int e) {
    ElementValues ev;
    compute_element_values(mesh_, e, ev, false);
    std::array<Vec2, 6> F;
    assemble_explicit_momentum(p, ev, element_state(e, explicit_part), F);
    const auto& el = mesh_.elements[e];
    for (int a = 0; a < 6; ++a) {
      a_x[el[a]] += F[a].x();
      a_y[el[a]] += F[a].y();
    }
  });
  mass_->project(a_x);
  mass_->project(a_y);
  for (int i = 0; i < count; ++i) {
    a_x[i] = n.u[i] + dt * a_x[i];
    a_y[i] = n.v[i] + dt * a_y[i];
  }
  characteristics_->advect(n.u, n.v, dt, a_x, a_y, u_departure_, v_departure_);
}

// Boundary velocities at t^{n+1}: velocity and zero nodes take their value; discharge nodes
// u_i = -n_i c sqrt(H_i), with I = sum over the group's edges of <H^k, sum_m N_m sqrt(H_m)
// n_m . n> and c = Q(t^{n+1}) / I, so that term (10), taken at t^{n+1} on discharge boundaries
// (boundary_flux_weight), carries exactly Q(t^{n+1}) in, with either time scheme.
void ShallowWaterSolver::set_boundary_velocities(const Iteration& it) {
  const double t = it.t_new;
  const auto& conditions = case_.flow.boundaries;
  auto node_depth = [&](int node) {
    if (node < mesh_.vertex_count) return state_.eta[node] - z_b_[node];
    const auto& ends = mid_vertices_[node];
    return 0.5 * (state_.eta[ends[0]] + state_.eta[ends[1]]) - z_b_[node];
  };
  std::vector<Vec2> normal(mesh_.node_count(), Vec2::Zero());
  for (const auto& n : bc_.velocity_nodes) normal[n.node] = n.normal;
  std::vector<double> integral(conditions.size(), 0.0);
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
  }
  for (const auto& n : bc_.velocity_nodes) {
    Vec2 u_b = Vec2::Zero();
    if (n.kind == VelocityNode::Kind::velocity) {
      u_b = Vec2(conditions[n.condition].value(t), conditions[n.condition].value_y(t));
    } else if (n.kind == VelocityNode::Kind::discharge) {
      const double c = conditions[n.condition].value(t) / integral[n.condition];
      u_b = -n.normal * c * std::sqrt(std::max(node_depth(n.node), 0.0));
    }
    state_.u[n.node] = u_b.x();
    state_.v[n.node] = u_b.y();
  }
}

// The weight of t^{n+1} in term (10) on the edges of boundary condition c [-]: 1 on discharge
// boundaries, theta (the scheme's) on velocity boundaries. A discharge imposed theta-weighted,
// theta Q(t^{n+1}) + (1 - theta) Q(t^n) with the boundary's own outflow of t^n in the second
// part, feeds each step's flux error back with the factor -(1 - theta) / theta; at dt = 5 s on
// MacDonald's channel (gravity-wave Courant number 1.4, theta = 0.6) the inflow then oscillated and
// never settled (29 % off near it; docs/model.md "Discharge boundaries").
double ShallowWaterSolver::boundary_flux_weight(int c, const Iteration& it) const {
  return case_.flow.boundaries[c].kind == BoundaryCondition::Kind::discharge ? 1.0 : it.theta;
}

void ShallowWaterSolver::record_fluxes(const Eigen::VectorXd& x) {
  balance_.group_rate.assign(mesh_.group_names.size(), 0.0);
  for (size_t g = 0; g < open_flux_.size(); ++g) balance_.group_rate[g] += open_flux_[g];
  for (size_t k = 0; k < bc_.elevation_nodes.size(); ++k)
    balance_.group_rate[elevation_group_[k]] -= system_.saved_row_residual(static_cast<int>(k), x);
}

// The rows sum to inv_dt (V^{n+1} - now V^n - before V^{n-1}) = S - F (water_balance.hpp): the
// volume changes by dt (S - F) plus what BDF2 holds back in its time lag, which is zero for
// the theta-scheme (inv_dt dt = now = 1, before = 0).
void ShallowWaterSolver::update_balance(const Iteration& it, double dt, const Eigen::VectorXd& x) {
  record_fluxes(x);
  accumulate_balance(it, dt);
}

void ShallowWaterSolver::accumulate_balance(const Iteration& it, double dt) {
  const double V_new = volume(), V_n = balance_.volume;
  const double V_before = it.before != 0.0 ? volume_of(before_) : 0.0;
  balance_.lag += V_new - V_n - dt * it.inv_dt * (V_new - it.now * V_n - it.before * V_before);
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
  balance_.volume = V_new;
}

double ShallowWaterSolver::node_depth_of(const FlowState& s, int node) const {
  if (node < mesh_.vertex_count) return s.eta[node] - z_b_[node];
  const auto& ends = mid_vertices_[node];
  return 0.5 * (s.eta[ends[0]] + s.eta[ends[1]]) - z_b_[node];
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
    if (H < case_.flow.dry_depth_or_default())
      throw_run_error(
          "flow: t = {:.6g} s: node {} ({:.6g}, {:.6g}) dried: depth H = {:.6g} m "
          "below the dry depth {} m (the FEM engine needs a wet domain, spec 1.5)",
          t, tag(i), p.x(), p.y(), H, case_.flow.dry_depth_or_default());
  }
}

}  // namespace flotsam
