#include "flow/fem/shallow_water_solver.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "flow/fem/turbulence.hpp"
#include "flow/friction_map.hpp"

namespace flotsam {

ShallowWaterSolver::ShallowWaterSolver(const Mesh& mesh, const Case& flow_case,
                                       FlowSolverOptions options)
    : mesh_(mesh),
      case_(flow_case),
      options_(std::move(options)),
      bc_(resolve_boundary_conditions(mesh, flow_case.flow, flow_case.file)),
      solver_(
          {.kind = options_.linear_solver, .reuse_factorisation = options_.reuse_factorisation}) {
  const RainConfig& rain = flow_case.flow.rain;
  if (rain.enabled) {
    const std::string where = flow_case.file.empty() ? "case" : flow_case.file;
    const std::string at = rain.line > 0 ? fmt::format("{}:{}", where, rain.line) : where;
    throw_input_error(
        "{}: flow.rain: rain is supported by 'engine: fv' only; the FEM engine (engine: fem) "
        "has no rain or infiltration source",
        at);
  }
  if (flow_case.flow.scheme == FlowScheme::segregated &&
      options_.advection != Advection::characteristics)
    throw_input_error("{}: flow.scheme: segregated takes advection by characteristics",
                      flow_case.file.empty() ? "case" : flow_case.file);
  if (flow_case.flow.friction != FrictionLaw::none) {  // (M-19) at each element's centroid
    std::vector<Vec2> centroids(mesh.element_count());
    for (int e = 0; e < mesh.element_count(); ++e) {
      const auto& el = mesh.elements[e];
      centroids[e] = (mesh.nodes[el[0]] + mesh.nodes[el[1]] + mesh.nodes[el[2]]) / 3.0;
    }
    FrictionCoefficients k =
        flotsam::friction_coefficients(flow_case.flow, centroids, [&mesh](int e) {
          return fmt::format("element {}", static_cast<std::size_t>(e) < mesh.element_tags.size()
                                               ? mesh.element_tags[e]
                                               : static_cast<long>(e));
        });
    log_friction_map(flow_case.flow.friction_map, k, "elements");
    friction_coefficient_ = std::move(k.coefficient);
  }
}

// ---- setup ----------------------------------------------------------------------------------

void ShallowWaterSolver::initialize() {
  if (options_.bed) {
    z_b_.resize(mesh_.node_count());
    for (int i = 0; i < mesh_.node_count(); ++i) z_b_[i] = options_.bed(mesh_.nodes[i]);
  } else {
    z_b_ = bed_at_nodes(mesh_, case_.bed);
  }

  // eta per P1 vertex: the case's formula, or still water linear in x between the two initial
  // values (spec 8.2); u, v per P2 node: the case's formulas, or at rest. set_state rejects a
  // vertex below the dry depth: the FEM engine cannot start dry.
  const auto& flow = case_.flow;
  double x_min = std::numeric_limits<double>::max(), x_max = -x_min;
  for (const Vec2& p : mesh_.nodes) {
    x_min = std::min(x_min, p.x());
    x_max = std::max(x_max, p.x());
  }
  FlowState initial;
  initial.eta.resize(mesh_.vertex_count);
  for (int j = 0; j < mesh_.vertex_count; ++j) {
    const Vec2& p = mesh_.nodes[j];
    const double f = (p.x() - x_min) / std::max(x_max - x_min, 1e-300);
    initial.eta[j] =
        flow.initial_eta.empty()
            ? flow.initial_eta_start + f * (flow.initial_eta_end - flow.initial_eta_start)
            : flow.initial_eta(p.x(), p.y());
  }
  const auto nodal_values = [&](const Expression& formula) {
    std::vector<double> values(mesh_.node_count(), 0.0);
    if (!formula.empty())
      for (int i = 0; i < mesh_.node_count(); ++i)
        values[i] = formula(mesh_.nodes[i].x(), mesh_.nodes[i].y());
    return values;
  };
  initial.u = nodal_values(flow.initial_u);
  initial.v = nodal_values(flow.initial_v);
  setup_system();
  set_state(initial);
}

// The coupled system's pattern and the P2 mass of its explicit part: for the coupled step, and
// for the steady solve whichever the step (set up when it first runs).
void ShallowWaterSolver::setup_coupled_system() {
  std::vector<int> dirichlet_rows, slip_nodes;
  const int eta_offset = 2 * mesh_.node_count();  // LinearSystem::eta_row before setup
  for (const auto& n : bc_.elevation_nodes) dirichlet_rows.push_back(eta_offset + n.vertex);
  for (const auto& n : bc_.velocity_nodes) {
    dirichlet_rows.push_back(LinearSystem::u_row(n.node));
    dirichlet_rows.push_back(LinearSystem::v_row(n.node));
  }
  for (const auto& n : bc_.slip_nodes) slip_nodes.push_back(n.node);
  system_.setup(mesh_, dirichlet_rows, slip_nodes);
  // The theta-scheme's explicit slope and Coriolis are projected on P2 (departure_values); BDF2
  // has no explicit part.
  if (options_.advection == Advection::characteristics && case_.time.scheme == TimeScheme::theta)
    mass_.emplace(mesh_);
  coupled_system_ready_ = true;
}

void ShallowWaterSolver::setup_system() {
  blocks_ = element_blocks(mesh_);
  if (options_.advection == Advection::characteristics) characteristics_.emplace(mesh_);
  coupled_system_ready_ = false;
  segregated_.reset();
  if (case_.flow.scheme == FlowScheme::coupled) setup_coupled_system();
  open_flux_.assign(mesh_.group_names.size(), 0.0);
  elevation_group_.clear();
  for (const auto& n : bc_.elevation_nodes)
    elevation_group_.push_back(mesh_.find_group(case_.flow.boundaries[n.condition].group));
  elevation_edges_.clear();
  for (int b = 0; b < static_cast<int>(mesh_.boundary.size()); ++b) {
    const int condition = bc_.group_condition[mesh_.boundary[b].group];
    if (condition >= 0 &&
        case_.flow.boundaries[condition].kind == BoundaryCondition::Kind::elevation)
      elevation_edges_.push_back(b);
  }
  mid_vertices_.assign(mesh_.node_count(), {-1, -1});
  for (const auto& el : mesh_.elements)
    for (int k = 0; k < 3; ++k) mid_vertices_[el[3 + k]] = {el[k], el[(k + 1) % 3]};
  if (case_.flow.scheme == FlowScheme::segregated)
    segregated_ = std::make_unique<SegregatedStep>(*this);

  // Integrals of the P1 basis and of the bed, with the assembly's quadrature.
  lumped_p1_.assign(mesh_.vertex_count, 0.0);
  bed_volume_ = 0.0;
  ElementValues ev;
  for (int e = 0; e < mesh_.element_count(); ++e) {
    compute_element_values(mesh_, e, ev);
    const auto& el = mesh_.elements[e];
    for (int q = 0; q < triangle_point_count; ++q) {
      for (int j = 0; j < 3; ++j) lumped_p1_[el[j]] += ev.N1[q][j] * ev.JxW[q];
      for (int k = 0; k < 6; ++k) bed_volume_ += ev.N2[q][k] * z_b_[el[k]] * ev.JxW[q];
    }
  }
}

void ShallowWaterSolver::set_state(const FlowState& s, const FlowState* before) {
  const auto depth_at = [&](int node, const FlowState& st) {
    if (node < mesh_.vertex_count) return st.eta[node] - z_b_[node];
    return 0.0;  // mid nodes are checked through check_state
  };
  const double H_dry = case_.flow.dry_depth_or_default();
  for (int j = 0; j < mesh_.vertex_count; ++j)
    if (!(depth_at(j, s) >= H_dry))
      throw_input_error(
          "{}: initial depth H = {:.6g} m at node {} ({:.6g}, {:.6g}) of mesh {} is "
          "below the dry depth {} m: the FEM engine needs the domain wet at start "
          "(eta = {:.6g} m, z_b = {:.6g} m)",
          case_.file.empty() ? "case" : case_.file, depth_at(j, s),
          mesh_.node_tags.empty() ? j : mesh_.node_tags[j], mesh_.nodes[j].x(), mesh_.nodes[j].y(),
          mesh_.source, H_dry, s.eta[j], z_b_[j]);
  state_ = s;
  history_ = before && before->time < s.time;
  previous_ = history_ ? *before : s;
  linearisation_ = s;
  start_fresh_factorisation();
  double H_sum = 0.0, A_sum = 0.0;
  for (int j = 0; j < mesh_.vertex_count; ++j) {
    H_sum += lumped_p1_[j] * (s.eta[j] - z_b_[j]);
    A_sum += lumped_p1_[j];
  }
  H_mean_ = H_sum / A_sum;
  restart_water_balance();
}

void ShallowWaterSolver::restart_water_balance() {
  balance_ = WaterBalance{};
  balance_.initial_volume = balance_.volume = volume();
  balance_.group_outflow.assign(mesh_.group_names.size(), 0.0);
}

double ShallowWaterSolver::volume() const {
  return volume_of(state_);
}

double ShallowWaterSolver::volume_of(const FlowState& s) const {
  double v = -bed_volume_;
  for (int j = 0; j < mesh_.vertex_count; ++j) v += lumped_p1_[j] * s.eta[j];
  return v;
}

// ---- one linearised problem -------------------------------------------------------------------

AssemblyParameters ShallowWaterSolver::assembly_parameters(const Iteration& it) const {
  const auto& flow = case_.flow;
  AssemblyParameters p;
  p.theta = it.theta;
  p.inv_dt = it.inv_dt;
  p.gravity = flow.gravity;
  p.coriolis =
      flow.coriolis ? 2.0 * earth_rotation_rate * std::sin(flow.latitude_deg * pi / 180.0) : 0.0;
  p.wind_stress = air_density / flow.water_density * wind_drag_coefficient * flow.wind.norm() *
                  flow.wind;  // (M-2) wind, times H
  p.friction = FrictionModel::from(flow);
  p.supg = options_.supg;
  p.characteristics = it.characteristics;
  p.source_time = it.t_source;
  p.source = options_.source ? &options_.source : nullptr;
  return p;
}

ElementState ShallowWaterSolver::element_state(int e, const Iteration& it) const {
  const auto& el = mesh_.elements[e];
  const FlowState& k = linearisation_;
  const FlowState& n = previous_;
  const bool history = it.before != 0.0;  // BDF2: before_ holds t^{n-1}
  ElementState s;
  for (int a = 0; a < 6; ++a) {
    const int node = el[a];
    s.u_k[a] = k.u[node];
    s.v_k[a] = k.v[node];
    s.u_n[a] = n.u[node];
    s.v_n[a] = n.v[node];
    if (it.characteristics) {
      s.u_d[a] = u_departure_[node];
      s.v_d[a] = v_departure_[node];
    } else {
      s.u_d[a] = it.now * n.u[node] + (history ? it.before * before_.u[node] : 0.0);
      s.v_d[a] = it.now * n.v[node] + (history ? it.before * before_.v[node] : 0.0);
    }
    s.z_b[a] = z_b_[node];
    s.node_force[a] = node_forces_.empty() ? Vec2::Zero() : node_forces_[node];
  }
  for (int j = 0; j < 3; ++j) {
    s.eta_k[j] = k.eta[el[j]];
    s.eta_n[j] = n.eta[el[j]];
    s.eta_d[j] = it.now * n.eta[el[j]] + (history ? it.before * before_.eta[el[j]] : 0.0);
  }
  if (!element_forces_.empty()) s.element_force = element_forces_[e];
  if (!element_drag_rates_.empty()) s.drag_rate = element_drag_rates_[e];
  return s;
}

// Small colours run serially outside any OpenMP construct: even a parallel region with a false
// if-clause keeps the idle threads spinning, which on a loaded machine slowed small cases 10-20x.
void ShallowWaterSolver::for_each_element(const std::function<void(int)>& visit) const {
  const size_t parallel_threshold = static_cast<size_t>(std::max(options_.parallel_min_colour, 1));
  for (size_t c = 0; c < blocks_.colours.size(); ++c) {
    const auto& colour = blocks_.colours[c];
    const int count = static_cast<int>(colour.size());
    if (static_cast<size_t>(blocks_.element_count[c]) >= parallel_threshold) {
#pragma omp parallel for schedule(static)
      for (int b = 0; b < count; ++b)
        for (int e = colour[b][0]; e < colour[b][1]; ++e) visit(e);
    } else {
      for (int b = 0; b < count; ++b)
        for (int e = colour[b][0]; e < colour[b][1]; ++e) visit(e);
    }
  }
}

std::vector<double> ShallowWaterSolver::eddy_viscosity() const {
  const FlowConfig& flow = case_.flow;
  std::vector<double> nu_t(mesh_.element_count(), 0.0);
  if (flow.turbulence == TurbulenceModel::none) return nu_t;
  const FrictionModel law = FrictionModel::from(flow);
  for_each_element([&](int e) {
    FrictionModel friction = law;
    if (!friction_coefficient_.empty()) friction.coefficient = friction_coefficient_[e];
    ElementValues ev;
    compute_element_values(mesh_, e, ev, false);
    const auto& el = mesh_.elements[e];
    std::array<double, 6> u, v, z_b;
    std::array<double, 3> eta;
    for (int a = 0; a < 6; ++a) {
      u[a] = state_.u[el[a]];
      v[a] = state_.v[el[a]];
      z_b[a] = z_b_[el[a]];
    }
    for (int j = 0; j < 3; ++j) eta[j] = state_.eta[el[j]];
    nu_t[e] = flotsam::eddy_viscosity(flow.turbulence, flow.smagorinsky_constant, friction,
                                      element_flow_average(ev, u, v, z_b, eta));  // (M-3)
  });
  return nu_t;
}

void ShallowWaterSolver::assemble_system(const Iteration& it) {
  const auto& flow = case_.flow;
  const AssemblyParameters p = assembly_parameters(it);
  system_.set_zero();
  for_each_element([&](int e) {
    AssemblyParameters p_e = p;  // with the element's own friction coefficient
    if (!friction_coefficient_.empty()) p_e.friction.coefficient = friction_coefficient_[e];
    ElementValues ev;
    compute_element_values(mesh_, e, ev, !it.characteristics);
    ElementState s = element_state(e, it);
    const double nu_t =
        flow.turbulence == TurbulenceModel::none
            ? 0.0
            : flotsam::eddy_viscosity(flow.turbulence, flow.smagorinsky_constant, p_e.friction,
                                      element_flow_average(ev, s.u_k, s.v_k, s.z_b,
                                                           s.eta_k));  // (M-3)
    s.nu_e = flow.viscosity + it.added_viscosity + nu_t;               // (M-3)
    LocalMatrix K;
    LocalVector F;
    assemble_element(p_e, ev, s, K, F);
    system_.add(e, system_.element_rows(mesh_, e), K, F);
  });

  if (!it.characteristics) assemble_inflow_stabilisation();

  // Term (10) on discharge and velocity boundaries: the outflow, known, to the right-hand side.
  const FlowState& k = linearisation_;
  const FlowState& n = previous_;
  std::fill(open_flux_.begin(), open_flux_.end(), 0.0);
  EdgeValues ev;
  for (const auto& open : bc_.open_edges) {
    const auto& edge = mesh_.boundary[open.boundary_edge];
    compute_edge_values(mesh_, edge, ev);
    EdgeState s;
    for (int m = 0; m < 3; ++m) {
      const int node = ev.nodes[m];
      s.z_b[m] = z_b_[node];
      s.u_new[m] = Vec2(state_.u[node], state_.v[node]);  // the boundary values, set before
      s.u_n[m] = Vec2(n.u[node], n.v[node]);
      if (m < 2) {
        s.eta_k[m] = k.eta[node];
        s.eta_n[m] = n.eta[node];
      }
    }
    const auto flux = open_boundary_flux(boundary_flux_weight(open.condition, it), ev, s);
    for (int m = 0; m < 2; ++m) {
      open_flux_[edge.group] += flux[m];
      system_.b[system_.eta_row(ev.nodes[m])] -= flux[m];  // (10)
    }
  }
}

// Term (12), inflow (backflow) stabilisation on elevation boundaries, where the velocity is free:
//   + <w, f(u)>,  f(u) = - beta (u . n)_- u,  (x)_- = min(x, 0), beta = 1/2,
// on the momentum rows, Newton-linearised about u^k like the other terms:
//   f(u) ~ f(u^k) + f'(u^k) (u - u^k),  f'(u^k) = - beta ((u^k . n)_- I + u^k n^T) (inflow).
// Where water enters through a natural boundary, the advection term carries kinetic energy
// (1/2) |u|^2 (u . n) in that no boundary data controls, and the inflow velocity grows node by
// node until the run fails; this term takes that energy flux out (Bazilevs et al. 2009;
// Moghadam et al. 2011). It vanishes for outflow and at rest (well balanced), and acts on
// momentum only (the water balance is unchanged).
void ShallowWaterSolver::assemble_inflow_stabilisation() {
  constexpr double beta = 0.5;  // [-]
  EdgeValues ev;
  for (int b : elevation_edges_) {
    compute_edge_values(mesh_, mesh_.boundary[b], ev);
    for (int q = 0; q < edge_point_count; ++q) {
      Vec2 u_k = Vec2::Zero();
      for (int m = 0; m < 3; ++m)
        u_k += ev.N2[q][m] * Vec2(linearisation_.u[ev.nodes[m]], linearisation_.v[ev.nodes[m]]);
      const Vec2& n = ev.normal[q];
      const double inflow = u_k.dot(n);  // [m/s]
      if (inflow >= 0.0) continue;
      const Mat2 jacobian = -beta * (inflow * Mat2::Identity() + u_k * n.transpose());  // f'
      const Vec2 rhs = -beta * inflow * u_k;  // f'(u^k) u^k - f(u^k) [m^2 s^-2]
      for (int a = 0; a < 3; ++a) {
        const double w = ev.N2[q][a] * ev.ds[q];
        const int ra[2] = {LinearSystem::u_row(ev.nodes[a]), LinearSystem::v_row(ev.nodes[a])};
        system_.b[ra[0]] += w * rhs.x();
        system_.b[ra[1]] += w * rhs.y();
        for (int c = 0; c < 3; ++c) {
          const int rc[2] = {LinearSystem::u_row(ev.nodes[c]), LinearSystem::v_row(ev.nodes[c])};
          for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j)
              system_.add_entry(ra[i], rc[j], w * ev.N2[q][c] * jacobian(i, j));  // (12)
        }
      }
    }
  }
}

// The level held at elevation vertex k at t^{n+1} [m]: the boundary's eta, except where water
// flows back in through a boundary that lets water out (its outflow in the last step was
// positive): that water comes from the still water beyond at the given level, so the level
// held is its total head less the kinetic head of the inflow, eta_b - (u^n . n)^2 / (2 g)
// (spec 1.4). Otherwise the boundary would hand the re-entering water its speed for free, and
// a recirculation at an outlet's corner feeds itself (docs/model.md "Backflow at an outlet").
// With characteristics only: the Eulerian form's counterpart is term (12).
double ShallowWaterSolver::elevation_boundary_level(int k, const Iteration& it) const {
  const ElevationNode& n = bc_.elevation_nodes[k];
  const double level = case_.flow.boundaries[n.condition].value(it.t_new);  // [m]
  if (!it.characteristics) return level;
  const auto& rate = balance_.group_rate;
  const int g = elevation_group_[k];
  if (g >= static_cast<int>(rate.size()) || rate[g] <= 0.0) return level;
  const double u_n = Vec2(previous_.u[n.vertex], previous_.v[n.vertex]).dot(n.outward);  // [m/s]
  return u_n < 0.0 ? level - u_n * u_n / (2.0 * case_.flow.gravity) : level;
}

void ShallowWaterSolver::apply_boundary_conditions(const Iteration& it) {
  system_.save_dirichlet_rows();
  int slot = 0;
  for (int k = 0; k < static_cast<int>(bc_.elevation_nodes.size()); ++k)
    system_.set_dirichlet(slot++, elevation_boundary_level(k, it));
  for (const auto& n : bc_.velocity_nodes) {
    const Vec2 u_b(state_.u[n.node], state_.v[n.node]);  // set by set_boundary_velocities
    system_.set_dirichlet(slot++, u_b.x());
    system_.set_dirichlet(slot++, u_b.y());
  }
  for (int k = 0; k < static_cast<int>(bc_.slip_nodes.size()); ++k) {
    const SlipNode& s = bc_.slip_nodes[k];
    const Vec2 u_n(previous_.u[s.node], previous_.v[s.node]);
    if (u_n.dot(s.outward) > 0.0) continue;  // water leaves an elevation boundary: u . t free
    system_.set_slip(k, s.normal);
  }
}

Eigen::VectorXd ShallowWaterSolver::solve() {
  Eigen::VectorXd x = pack(state_);  // the refinement's first guess: the last iterate
  if (solver_.solve(system_.A, system_.b, x)) return x;
  if (solver_.failure() == FactorizationFailure::singular)
    throw_run_error(
        "flow: t = {:.6g} s: the sparse LU factorisation failed: {}: check the boundary "
        "conditions of mesh {}",
        linearisation_.time, solver_.failure_message(), mesh_.source);
  throw_run_error("flow: t = {:.6g} s: the sparse LU factorisation failed: {} (mesh {})",
                  linearisation_.time, solver_.failure_message(), mesh_.source);
}

Eigen::VectorXd ShallowWaterSolver::pack(const FlowState& s) const {
  Eigen::VectorXd x(system_.size());
  for (int i = 0; i < mesh_.node_count(); ++i) {
    x[LinearSystem::u_row(i)] = s.u[i];
    x[LinearSystem::v_row(i)] = s.v[i];
  }
  for (int j = 0; j < mesh_.vertex_count; ++j) x[system_.eta_row(j)] = s.eta[j];
  return x;
}

void ShallowWaterSolver::unpack(const Eigen::VectorXd& x) {
  for (int i = 0; i < mesh_.node_count(); ++i) {
    state_.u[i] = x[LinearSystem::u_row(i)];
    state_.v[i] = x[LinearSystem::v_row(i)];
  }
  for (int j = 0; j < mesh_.vertex_count; ++j) state_.eta[j] = x[system_.eta_row(j)];
}

}  // namespace flotsam
