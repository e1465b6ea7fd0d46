#include "flow/fv/fv_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>

#include <spdlog/spdlog.h>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "core/parallel_for.hpp"
#include "flow/bed.hpp"
#include "flow/friction_map.hpp"
#include "flow/fv/hllc_flux.hpp"

namespace flotsam {

namespace {

// Depth below which a negative depth is round-off, set to 0 with its volume counted as a source
// (model.md "Positivity"); deeper is a run error. [m]
constexpr double negative_depth_round_off = 1e-10;

// The desingularised velocity of a thin film (Kurganov & Petrova 2007; model.md (M-15)):
//   u = sqrt(2) h (hu) / sqrt(h^4 + max(h^4, H_eps^4)),
// which is hu / h for h >= H_eps and goes to 0 with h instead of blowing up.
inline double velocity(double h, double hu, double eps4) {
  const double h2 = h * h, h4 = h2 * h2;
  return h4 >= eps4 ? hu / h : std::sqrt(2.0) * h * hu / std::sqrt(h4 + eps4);
}

// Backward Euler in the velocity for a drag quadratic in it, du/dt = -gamma u with gamma
// proportional to |u| (friction (M-14), the piers' drag (M-25)): the new speed s solves
// s (1 + dt gamma s / |u*|) = |u*|, so u^{n+1} = u* times this factor, in (0, 1].
inline double quadratic_drag_factor(double dt, double gamma) {
  return 2.0 / (1.0 + std::sqrt(1.0 + 4.0 * dt * gamma));
}

// The value of the reconstruction of cell i at the midpoint of its local edge k; the bed there
// is eta_e - h_e (model.md (M-12)).
inline FaceState face_value(const CellField& f, int i, int k) {
  const int e = 3 * i + k;
  return {f.edge_h[e], f.edge_eta[e] - f.edge_h[e], f.edge_u[e], f.edge_v[e]};
}

}  // namespace

FiniteVolumeSolver::FiniteVolumeSolver(const Mesh& mesh, const Case& flow_case,
                                       std::shared_ptr<const CellMesh> cells)
    : mesh_(mesh),
      case_(flow_case),
      shared_cells_(
          cells ? std::move(cells)
                : std::make_shared<const CellMesh>(build_cell_mesh(mesh, flow_case.flow.fv.cells))),
      cells_(*shared_cells_),
      boundaries_(FvBoundaries::resolve(mesh, flow_case.flow)),
      friction_(FrictionModel::from(flow_case.flow)),
      rain_(flow_case.flow.rain, cells_),
      sources_(flow_case.flow.sources, mesh, cells_) {
  const FlowConfig& flow = flow_case.flow;
  g_ = flow.gravity;
  dry_depth_ = flow.dry_depth_or_default();
  velocity_depth_ = flow.fv.velocity_depth;
  coriolis_ =
      flow.coriolis ? 2.0 * earth_rotation_rate * std::sin(flow.latitude_deg * pi / 180.0) : 0.0;
  // (M-2) wind: F_wind H = (rho_air / rho) C_w |W| W  [m^2/s^2]
  wind_stress_ =
      air_density / flow.water_density * wind_drag_coefficient * flow.wind.norm() * flow.wind;
  const int n = cells_.cell_count, m = cells_.edge_count;
  for (auto* a : {&flux_mass_, &flux_x_, &flux_y_, &side_left_, &side_right_, &edge_speed_})
    a->assign(m, 0.0);
  for (auto* a : {&rate_h_, &rate_hu_, &rate_hv_}) a->assign(n, 0.0);
  if (sources_.any()) source_depth_.assign(n, 0.0);
  field_.resize(n);
  edge_discharge_.assign(m, 0.0);
  time_levels_ = choose_time_levels(cells_, flow.fv.time_levels);
  if (flow.fv.time_levels == 0)
    spdlog::info(
        "flow.fv.time_levels auto: {} (the cells' sizes predict {:.2f}x fewer updates "
        "with {} levels than with one)",
        time_levels_, size_gain(cells_, auto_levels), auto_levels);
  if (time_levels_ > 1) level_ties_ = tied_cells();
  all_edges_.resize(m);
  for (int e = 0; e < m; ++e) all_edges_[e] = e;
  all_cells_.resize(n);
  for (int i = 0; i < n; ++i) all_cells_[i] = i;
  outflow_rate_.assign(mesh.group_names.size(), 0.0);
  deck_edges_ = find_deck_edges(cells_, flow_case.bridges);
  pier_drag_ = find_pier_drag(mesh, cells_, flow_case.bridges, flow.fv.pier_drag);
  for (const PierDrag::Pier& pier : pier_drag_.piers)
    spdlog::info("pier drag on {}: C_d {}, width {:.3g} m, over {} cells within it ({:.3g} m^2)",
                 pier.name, flow.fv.pier_drag, pier.width, pier.ring.size(), pier.ring_area);
  if (friction_.law != FrictionLaw::none) {  // (M-19) at each cell's centroid
    FrictionCoefficients k = flotsam::friction_coefficients(
        flow, cells_.centroid, [](int i) { return fmt::format("cell {}", i); });
    log_friction_map(flow.friction_map, k, "cells");
    friction_coefficient_ = std::move(k.coefficient);
  }
}

void FiniteVolumeSolver::initialize() {
  const int n = cells_.cell_count;
  node_bed_ = bed_at_nodes(mesh_, case_.bed);
  const FlowConfig& flow = case_.flow;
  double x_min = std::numeric_limits<double>::max(), x_max = -x_min;
  for (const Vec2& p : mesh_.nodes) x_min = std::min(x_min, p.x()), x_max = std::max(x_max, p.x());
  z_.resize(n);
  U_.time = 0.0;
  U_.h.assign(n, 0.0);
  U_.hu.assign(n, 0.0);
  U_.hv.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    double z = 0.0;
    for (int corner : cells_.corners[i]) z += node_bed_[corner];
    z_[i] = z / 3.0;
    const Vec2& p = cells_.centroid[i];
    // Still water with eta linear in x (spec 8.2), or the case's formulas; dry below the bed.
    const double f = x_max > x_min ? (p.x() - x_min) / (x_max - x_min) : 0.0;
    const double eta =
        flow.initial_eta.empty()
            ? flow.initial_eta_start + f * (flow.initial_eta_end - flow.initial_eta_start)
            : flow.initial_eta(p.x(), p.y());
    U_.h[i] = std::max(0.0, eta - z_[i]);
    if (U_.h[i] > 0.0) {
      if (!flow.initial_u.empty()) U_.hu[i] = U_.h[i] * flow.initial_u(p.x(), p.y());
      if (!flow.initial_v.empty()) U_.hv[i] = U_.h[i] * flow.initial_v(p.x(), p.y());
    }
  }
  check(U_);
  cell_force_.clear();
  body_drag_ = {};
  stats_ = {};
  restart_water_balance();
}

void FiniteVolumeSolver::set_state(const ConservedState& state) {
  U_ = state;
  check(U_);
}

void FiniteVolumeSolver::restart_water_balance() {
  balance_ = {};
  balance_.initial_volume = balance_.volume = volume();
  balance_.group_outflow.assign(mesh_.group_names.size(), 0.0);
  balance_.group_rate.assign(mesh_.group_names.size(), 0.0);
}

double FiniteVolumeSolver::volume() const {
  double V = 0.0;
  for (int i = 0; i < cells_.cell_count; ++i) V += cells_.area[i] * U_.h[i];
  return V;
}

double FiniteVolumeSolver::wet_fraction() const {
  double wet = 0.0, all = 0.0;
  for (int i = 0; i < cells_.cell_count; ++i) {
    all += cells_.area[i];
    if (U_.h[i] > case_.output.wet_depth) wet += cells_.area[i];
  }
  return wet / all;
}

// ---- the finite-volume operator L -------------------------------------------------------

void FiniteVolumeSolver::load_cells(const ConservedState& U) const {
  const auto load = [&](int i) { load_cell(i, U.h[i], U.hu[i], U.hv[i]); };
  if (const RankSplit* split = part()) {  // this rank's cells and the two rings around them
    const std::span<const int> cells = split->loaded();
    return parallel_for(static_cast<std::ptrdiff_t>(cells.size()), std::ptrdiff_t{0},
                        [&](std::ptrdiff_t k) { load(cells[k]); });
  }
  parallel_for(cells_.cell_count, 0, load);
}

void FiniteVolumeSolver::load_cell(int i, double h, double hu, double hv) const {
  const double eps2 = velocity_depth_ * velocity_depth_, eps4 = eps2 * eps2;
  field_.h[i] = h;
  field_.eta[i] = h + z_[i];
  field_.u[i] = h > 0.0 ? velocity(h, hu, eps4) : 0.0;
  field_.v[i] = h > 0.0 ? velocity(h, hv, eps4) : 0.0;
}

void FiniteVolumeSolver::fill_field(CellField& field) const {
  load_cells(U_);
  field = field_;
  reconstruct(cells_, case_.flow.fv.order, dry_depth_, field);
}

// Per edge: the two sides' reconstructed values, the hydrostatic reconstruction (Audusse et al.
// 2004; model.md (M-12)),
//   z* = max(z_L, z_R),   h*_L = max(0, h_L + z_L - z*),   h*_R = max(0, h_R + z_R - z*),
// the HLLC flux between (h*_L, u_L) and (h*_R, u_R), and each side's correction
// g/2 (h_side^2 - h*_side^2) that keeps a lake at rest at rest.
void FiniteVolumeSolver::compute_edge_fluxes(std::span<const int> edges,
                                             std::span<const int> boundary_edges, double t,
                                             LevelRange levels) const {
  const CellMesh& c = cells_;
  const auto& conditions = case_.flow.boundaries;
  // Discharge conditions: Q(t) shared along the group as h^{3/2} (by length when dry). Over
  // ranks (`edges` this rank's, `boundary_edges` still every rank's), each edge's h^{3/2} is
  // formed by its cell's owner and goes to every rank, and the sums run over `boundary_edges` in
  // their order, as on one rank.
  const RankSplit* split = part();
  if (split) {
    gather_discharge_weights(boundary_edges);
  } else {
    for (const int edge : boundary_edges) {
      if (discharge_condition(edge) < 0) continue;
      const double h = face_value(field_, c.left[edge], c.left_slot[edge]).h;
      edge_discharge_[edge] = h * std::sqrt(h);
    }
  }
  std::vector<double> weight_sum(conditions.size(), 0.0), length_sum(conditions.size(), 0.0);
  for (const int edge : boundary_edges) {
    const int k = discharge_condition(edge);
    if (k < 0) continue;
    weight_sum[k] += c.length[edge] * edge_discharge_[edge];
    length_sum[k] += c.length[edge];
  }
  for (const int edge : boundary_edges) {
    const int k = discharge_condition(edge);
    if (k < 0) continue;
    const double Q = conditions[k].value(t);
    edge_discharge_[edge] =
        weight_sum[k] > 0.0 ? Q * edge_discharge_[edge] / weight_sum[k] : Q / length_sum[k];
  }

  const double g = g_;
  const auto count = static_cast<std::ptrdiff_t>(edges.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t index = 0; index < count; ++index) {
    const int edge = edges[index];
    const Vec2 n = c.normal[edge];
    const FaceState L = face_value(field_, c.left[edge], c.left_slot[edge]);
    const int j = c.right[edge];
    const int condition = j < 0 ? boundaries_.group_condition[c.group[edge]] : -1;
    FaceState R;
    if (j >= 0) {
      R = face_value(field_, j, c.right_slot[edge]);
    } else {
      static const BoundaryCondition wall;
      R = ghost_state(condition >= 0 ? conditions[condition] : wall, L, n, t, edge_discharge_[edge],
                      g);
    }
    const double z_star = std::max(L.z, R.z);
    const double h_L = std::max(0.0, L.h + L.z - z_star), h_R = std::max(0.0, R.h + R.z - z_star);
    const EdgeState left{h_L, L.u * n.x() + L.v * n.y(), -L.u * n.y() + L.v * n.x()};
    const EdgeState right{h_R, R.u * n.x() + R.v * n.y(), -R.u * n.y() + R.v * n.x()};
    EdgeFlux f = hllc_flux(left, right, g);
    if (j < 0 && !open_edge(edge)) f.mass = f.momentum_t = 0.0;  // nothing crosses a wall
    flux_mass_[edge] = f.mass;
    flux_x_[edge] = f.momentum_n * n.x() - f.momentum_t * n.y();
    flux_y_[edge] = f.momentum_n * n.y() + f.momentum_t * n.x();
    side_left_[edge] = 0.5 * g * (L.h * L.h - h_L * h_L);
    side_right_[edge] = 0.5 * g * (R.h * R.h - h_R * h_R);
    edge_speed_[edge] = f.max_speed;
  }

  deck_fluxes(levels);

  // Over ranks, the open edges' fluxes from their owners (a wall's is 0 on every rank).
  if (split && std::any_of(boundary_edges.begin(), boundary_edges.end(),
                           [this](int e) { return open_edge(e); })) {
    const std::vector<int>& B = c.boundary_edges;
    boundary_value_.assign(B.size(), 0.0);
    for (const int k : split->boundary_positions()) boundary_value_[k] = flux_mass_[B[k]];
    split->gather_boundary(boundary_value_);
    for (const int k : split->gathered_positions()) flux_mass_[B[k]] = boundary_value_[k];
  }
  std::fill(outflow_rate_.begin(), outflow_rate_.end(), 0.0);
  for (int edge : boundary_edges) outflow_rate_[c.group[edge]] += c.length[edge] * flux_mass_[edge];
}

// Whether water may cross a boundary edge: its group has a condition other than a wall.
bool FiniteVolumeSolver::open_edge(int edge) const {
  const int k = boundaries_.group_condition[cells_.group[edge]];
  if (k < 0) return false;
  const BoundaryCondition::Kind kind = case_.flow.boundaries[k].kind;
  return kind != BoundaryCondition::Kind::wall && kind != BoundaryCondition::Kind::noslip;
}

std::vector<char> FiniteVolumeSolver::open_boundary() const {
  std::vector<char> open;
  for (const int e : cells_.boundary_edges) open.push_back(open_edge(e) ? 1 : 0);
  return open;
}

// The discharge condition of a boundary edge's group, or -1.
int FiniteVolumeSolver::discharge_condition(int edge) const {
  const int k = boundaries_.group_condition[cells_.group[edge]];
  return k >= 0 && case_.flow.boundaries[k].kind == BoundaryCondition::Kind::discharge ? k : -1;
}

// h^{3/2} at every edge of a discharge condition among `boundary_edges`, each formed by the rank
// that owns its cell.
void FiniteVolumeSolver::gather_discharge_weights(std::span<const int> boundary_edges) const {
  const CellMesh& c = cells_;
  if (std::none_of(boundary_edges.begin(), boundary_edges.end(),
                   [this](int e) { return discharge_condition(e) >= 0; }))
    return;
  const std::vector<int>& B = c.boundary_edges;
  boundary_value_.assign(B.size(), 0.0);
  for (const int k : split_->boundary_positions()) {
    const int edge = B[k];
    if (discharge_condition(edge) < 0) continue;
    const double h = face_value(field_, c.left[edge], c.left_slot[edge]).h;
    boundary_value_[k] = h * std::sqrt(h);
  }
  split_->gather_boundary(boundary_value_);
  for (const int k : split_->gathered_positions()) edge_discharge_[B[k]] = boundary_value_[k];
}

// The edges a deck stands on (deck_flux.hpp), once the water reaches its soffit on either side:
// the ordinary discharge limited to the structure's, carried with the upstream cell's velocity;
// each side's own hydrostatic pressure on the structure (side_*: the whole g h^2 / 2, the flux
// holding none); and the jets' momentum, less what the discharge carried, to the downstream side.
void FiniteVolumeSolver::deck_fluxes(LevelRange levels) const {
  const CellMesh& c = cells_;
  const double g = g_;
  for (const DeckEdge& d : deck_edges_) {
    const int e = d.edge, i = c.left[e], j = c.right[e];
    if (!levels.holds(levels_, e)) continue;  // not in this part of L (local time stepping)
    if (std::max(field_.eta[i], field_.eta[j]) < d.soffit) continue;  // free: the ordinary flux
    const FaceState L = face_value(field_, i, c.left_slot[e]);
    const FaceState R = face_value(field_, j, c.right_slot[e]);
    const double z_e = std::max(z_[i], z_[j]);  // [m] the cells' beds: the opening as built
    const bool from_left = flux_mass_[e] >= 0.0;
    const int up = from_left ? i : j, down = from_left ? j : i;
    const Vec2 u_up(field_.u[up], field_.v[up]);
    const double energy = field_.eta[up] + 0.5 * u_up.squaredNorm() / g - z_e;  // [m]
    const double opening = std::max(0.0, d.soffit - z_e);                       // [m]
    const DeckFlow f = deck_flow(energy, field_.eta[down] - z_e, opening, d.crest - z_e,
                                 d.projection, std::abs(flux_mass_[e]), g);
    const Vec2 along = (from_left ? 1.0 : -1.0) * c.normal[e];  // from up to down
    flux_mass_[e] = (from_left ? 1.0 : -1.0) * f.discharge;
    flux_x_[e] = flux_mass_[e] * u_up.x();
    flux_y_[e] = flux_mass_[e] * u_up.y();
    const double jets = f.momentum - f.discharge * u_up.dot(along);  // [m^3/s^2]
    side_left_[e] = 0.5 * g * L.h * L.h + (from_left ? 0.0 : jets);
    side_right_[e] = 0.5 * g * R.h * R.h + (from_left ? jets : 0.0);
    edge_speed_[e] = std::max(edge_speed_[e], f.jet_speed + std::sqrt(g * opening));
  }
}

// What edge k gives cell i: minus the flux out through it, with the edge's share of the
// bed-slope source of the second-order scheme (Audusse et al. 2004, centred part),
//   - l_k g/2 (h_k + h_i)(z_k - z_i) n_k     (h_k, z_k: the cell's own edge values).
FiniteVolumeSolver::EdgeRate FiniteVolumeSolver::edge_rate(int i, int k) const {
  const CellMesh& c = cells_;
  const int e = c.cell_edges[i][k];
  const bool left = c.cell_is_left[i][k];
  const double sign = left ? 1.0 : -1.0, l = c.length[e];
  const Vec2 n = sign * c.normal[e];
  const FaceState F = face_value(field_, i, k);
  const double side =
      (left ? side_left_[e] : side_right_[e]) + 0.5 * g_ * (F.h + field_.h[i]) * (F.z - z_[i]);
  return {-sign * l * flux_mass_[e], -l * (sign * flux_x_[e] + side * n.x()),
          -l * (sign * flux_y_[e] + side * n.y())};
}

// Coriolis f (hv, -hu) and wind where the cell is wet, and the bodies' reactions [m^2/s^2],
// added to the momentum rates (ru, rv).
void FiniteVolumeSolver::add_local_rate(int i, double h, double hu, double hv, double& ru,
                                        double& rv) const {
  if (h > dry_depth_) {
    ru += coriolis_ * hv + wind_stress_.x();
    rv += -coriolis_ * hu + wind_stress_.y();
  }
  if (!cell_force_.empty()) {
    const double rho_A = case_.flow.water_density * cells_.area[i];
    ru += cell_force_[i].x() / rho_A;
    rv += cell_force_[i].y() / rho_A;
  }
}

// Per cell: the sum of its edges' rates, divided by the area, and Coriolis, wind, body
// reactions. The largest wave speed at its edges gives its Courant step (model.md (M-16)).
void FiniteVolumeSolver::sum_cell_rates(const ConservedState& U, bool courant) const {
  const CellMesh& c = cells_;
  const auto cell = [&](int i) {  // cell i's rates; its Courant step (infinite when still)
    double dh = 0.0, dx = 0.0, dy = 0.0, speed = 0.0;
    for (int k = 0; k < 3; ++k) {
      const EdgeRate r = edge_rate(i, k);
      dh += r.h, dx += r.hu, dy += r.hv;
      speed = std::max(speed, edge_speed_[c.cell_edges[i][k]]);
    }
    const double A = c.area[i];
    rate_h_[i] = dh / A;
    rate_hu_[i] = dx / A;
    rate_hv_[i] = dy / A;
    add_local_rate(i, field_.h[i], U.hu[i], U.hv[i], rate_hu_[i], rate_hv_[i]);
    return speed > 0.0 ? c.length_scale[i] / speed : std::numeric_limits<double>::infinity();
  };
  double dt_min = std::numeric_limits<double>::infinity();
  const RankSplit* split = part();
  if (split) {  // this rank's cells
    const std::span<const int> own = split->own();
    const auto n = static_cast<std::ptrdiff_t>(own.size());
#pragma omp parallel for schedule(static) reduction(min : dt_min)
    for (std::ptrdiff_t k = 0; k < n; ++k) dt_min = std::min(dt_min, cell(own[k]));
  } else {
#pragma omp parallel for schedule(static) reduction(min : dt_min)
    for (int i = 0; i < c.cell_count; ++i) dt_min = std::min(dt_min, cell(i));
  }
  if (!courant) return;  // the second stage's: not needed (over ranks, a reduction saved)
  stage_courant_step_ = case_.flow.fv.courant * (split ? split->min(dt_min) : dt_min);
}

SectionFlux FiniteVolumeSolver::section_flux(std::span<const int> edges, Vec2 direction) const {
  evaluate(U_, U_.time);
  SectionFlux sum;
  for (const int e : edges) {
    const Vec2 n = cells_.normal[e];
    const int i = cells_.left[e], j = cells_.right[e];
    const Vec2 across = j >= 0 ? Vec2(cells_.centroid[j] - cells_.centroid[i]) : n;
    const double sign = across.dot(direction) >= 0.0 ? 1.0 : -1.0, l = cells_.length[e];
    const double side = sign > 0.0 ? side_right_[e] : side_left_[e];  // the receiving cell's
    sum.discharge += l * sign * flux_mass_[e];
    sum.momentum += l * sign * (Vec2(flux_x_[e], flux_y_[e]) + side * n);
  }
  return sum;
}

void FiniteVolumeSolver::evaluate(const ConservedState& U, double t, bool courant) const {
  evaluate_fluxes(U, t);
  sum_cell_rates(U, courant);
}

void FiniteVolumeSolver::evaluate_fluxes(const ConservedState& U, double t) const {
  load_cells(U);
  if (const RankSplit* split = part()) {
    reconstruct(cells_, case_.flow.fv.order, dry_depth_, field_, split->reconstructed());
    compute_edge_fluxes(split->edges(), cells_.boundary_edges, t, {});
    return;
  }
  reconstruct(cells_, case_.flow.fv.order, dry_depth_, field_);
  compute_edge_fluxes(all_edges_, cells_.boundary_edges, t, {});
}

// (M-14) friction, backward Euler in the velocity: u^{n+1} = u* - dt c_f |u^{n+1}| u^{n+1} / H,
// with c_f and H at the sub-step's depth. u^{n+1} is parallel to u*, and its speed s solves
//   s (1 + b s) = |u*|,  b = dt c_f / H   =>   s = 2 |u*| / (1 + sqrt(1 + 4 b |u*|)),
// so (hu)^{n+1} = (hu)* 2 / (1 + sqrt(1 + 4 dt gamma)), gamma = c_f |u*| / H = rate (friction.hpp)
// with the cell's own coefficient (M-19).
// The factor is in (0, 1]: the flow slows, never turns round; and a flow in which the stages'
// drive balances friction (uniform flow, a film under rain on a slope) is its fixed point
// whatever dt, where gamma at |u*| (the drive already added) would settle short of it.
void FiniteVolumeSolver::apply_friction(ConservedState& U, double dt) const {
  if (friction_.law == FrictionLaw::none) return;
  const auto friction = [&](int i) { apply_friction(U, i, dt); };
  if (const RankSplit* split = part()) {  // this rank's cells
    const std::span<const int> own = split->own();
    return parallel_for(static_cast<std::ptrdiff_t>(own.size()), std::ptrdiff_t{0},
                        [&](std::ptrdiff_t k) { friction(own[k]); });
  }
  parallel_for(cells_.cell_count, 0, friction);
}

// Cell i's speed |u| [m/s], desingularised below H_eps (M-15).
double FiniteVolumeSolver::speed(const ConservedState& U, int i) const {
  const double h = U.h[i], eps2 = velocity_depth_ * velocity_depth_, eps4 = eps2 * eps2;
  const double u = velocity(h, U.hu[i], eps4), v = velocity(h, U.hv[i], eps4);
  return std::sqrt(u * u + v * v);
}

void FiniteVolumeSolver::apply_friction(ConservedState& U, int i, double dt) const {
  const double h = U.h[i];
  if (h <= 0.0) return;
  const double gamma = friction_.rate(speed(U, i), h, friction_coefficient_[i]);  // [1/s]
  const double factor = quadratic_drag_factor(dt, gamma);
  U.hu[i] *= factor;
  U.hv[i] *= factor;
}

// The piers' and the bodies' drag after friction (pier_drag.hpp, body_drag.hpp), in the cells
// near piers and under bodies only: a few among many, each on its own (the order does not change
// a bit).
void FiniteVolumeSolver::apply_drag(ConservedState& U, double dt) {
  const RankSplit* split = part();
  for (const int i : pier_drag_.cells)
    if (!split || split->owns(i)) apply_pier_drag(U, i, dt);
  for (const int i : body_drag_.cells)
    if (!split || split->owns(i)) body_drag_.apply(U, i, dt, dry_depth_);
}

// (M-25) backward Euler in the velocity, as friction: gamma = m_i |u*|.
void FiniteVolumeSolver::apply_pier_drag(ConservedState& U, int i, double dt) {
  const double m = pier_drag_.density[i];
  if (m == 0.0 || U.h[i] <= dry_depth_) return;
  const double factor = quadratic_drag_factor(dt, m * speed(U, i));
  const Vec2 before(U.hu[i], U.hv[i]);
  U.hu[i] *= factor;
  U.hv[i] *= factor;
  pier_drag_.impulse[i] += (1.0 - factor) * cells_.area[i] * before;
}

// (M-17) infiltration after the stages: each cell loses min(h, f dt), counted in the balance.
// Over ranks each rank infiltrates its own cells and the depths lost go to every rank, so that
// the volume is summed in the cells' order as on one.
void FiniteVolumeSolver::apply_infiltration(ConservedState& U, double dt) {
  if (!rain_.infiltrating()) return;
  const RankSplit* split = part();
  if (!split) {
    balance_.infiltration += rain_.infiltrate(U.h, U.hu, U.hv, dt);
    return;
  }
  balance_.infiltration +=
      rain_.infiltrate(U.h, U.hu, U.hv, dt, split->own(),
                       [split](std::vector<double>& lost) { split->gather(lost.data(), 1); });
}

// ---- stepping -----------------------------------------------------------------------------

double FiniteVolumeSolver::courant_step() const {
  evaluate(U_, U_.time);
  return stage_courant_step_;
}

// out = a U + b (y + dt L(y) + R), L evaluated last (rate_), R the sub-step's rain
// (rain_depth_ w_i) and sources (source_depth_): the Runge-Kutta stages. Returns true when a depth
// came out negative or a value not finite (clamp_round_off then looks at every cell). The balance
// is counted once per sub-step, with the weights of the whole step: U^{n+1} = U^n + dt/2 (L(U^n) +
// L(U1)) + R, so each stage's boundary outflow counts half (the rain is counted whole by advance).
bool FiniteVolumeSolver::add_stage(const ConservedState& U, const ConservedState& y,
                                   ConservedState& out, double a, double b, double dt) {
  const double rain = rain_depth_;  // [m] times w_i
  const std::vector<double>& w = rain_.weights();
  const double* source = sources_.any() ? source_depth_.data() : nullptr;  // [m]
  const auto cell = [&](int i) {  // true when the result is suspect
    const double R = rain * w[i] + (source ? source[i] : 0.0);
    out.h[i] = a * U.h[i] + b * (y.h[i] + dt * rate_h_[i] + R);
    out.hu[i] = a * U.hu[i] + b * (y.hu[i] + dt * rate_hu_[i]);
    out.hv[i] = a * U.hv[i] + b * (y.hv[i] + dt * rate_hv_[i]);
    return !(out.h[i] >= 0.0) || !std::isfinite(out.hu[i] + out.hv[i]);
  };
  bool suspect = false;
  const RankSplit* split = part();
  if (split) {  // this rank's cells
    const std::span<const int> own = split->own();
    const auto n = static_cast<std::ptrdiff_t>(own.size());
#pragma omp parallel for schedule(static) reduction(|| : suspect)
    for (std::ptrdiff_t k = 0; k < n; ++k) suspect = cell(own[k]) || suspect;
  } else {
#pragma omp parallel for schedule(static) reduction(|| : suspect)
    for (int i = 0; i < cells_.cell_count; ++i) suspect = cell(i) || suspect;
  }
  for (std::size_t g = 0; g < outflow_rate_.size(); ++g) {
    balance_.group_outflow[g] += 0.5 * dt * outflow_rate_[g];
    balance_.outflow += 0.5 * dt * outflow_rate_[g];
    balance_.group_rate[g] = outflow_rate_[g];
  }
  if (split) {
    suspect = split->any(suspect);
    if (suspect) gather(out);  // every rank looks at every cell (clamp_round_off)
  }
  return suspect;
}

// Sub-steps of dt = min(courant * Courant step, what is left), each retried at half the step
// when it leaves a negative depth or a value that is not finite: the Courant limit with
// courant <= 0.5 guarantees positive depths (model.md (M-16)); larger values, stable and twice
// as fast, rely on this retry at the rare fronts where positivity needs the smaller step. A
// domain dry and still has no Courant step (no wave speed): rain on it takes what is left of dt
// in one sub-step, halved on retry like the others.
//
// Rain (M-17) and sources (M-24) enter both stages as the constant R = w_i int_t^{t+dt} r +
// int Q_s dt / A_s: Heun's weights add it once, exactly the hyetograph's depth and the
// hydrographs' volume, and since R >= 0 it never makes a depth negative.
// Infiltration follows the stages (it cannot fail), then friction.
void FiniteVolumeSolver::advance(double dt) {
  pier_drag_.duration += dt;
  struct Advancing {  // over ranks, each advances its own part while this lasts (part())
    bool& flag;
    ~Advancing() { flag = false; }
  } advancing{advancing_ = true};
  if (time_levels_ > 1) return advance_local(dt);
  const double t_end = U_.time + dt;
  U1_.h.resize(U_.h.size());
  U1_.hu.resize(U_.h.size());
  U1_.hv.resize(U_.h.size());
  double shrink = 1.0;  // [-] of the Courant step, halved at each retry
  while (U_.time < t_end - 1e-12 * dt) {
    const double t = U_.time;
    const WaterBalance balance_before = balance_;
    // Stage 1: U1 = U + dt L(U) + R, dt from the Courant limit of L(U)'s wave speeds.
    evaluate(U_, t);
    const double dt_courant = stage_courant_step_;
    const double h = shrink * std::min(dt_courant, t_end - t);
    rain_depth_ = rain_.depth(t, t + h);
    const double source_volume = sources_.any() ? sources_.depths(t, t + h, source_depth_) : 0.0;
    int bad = add_stage(U_, U_, U1_, 0.0, 1.0, h) ? clamp_round_off(U1_, 0.5, all_cells_) : -1;
    // Stage 2: U^{n+1} = (U + U1 + dt L(U1) + R) / 2, then infiltration and friction.
    if (bad < 0) {
      exchange(U1_);
      evaluate(U1_, t + h, false);
      if (add_stage(U_, U1_, U1_, 0.5, 0.5, h)) bad = clamp_round_off(U1_, 1.0, all_cells_);
    }
    if (bad >= 0) {
      balance_ = balance_before;
      ++stats_.rejected;
      stats_.cell_updates += cells_.cell_count;
      shrink *= 0.5;
      if (shrink < 1.0 / 64.0) fail_at(U1_, bad, t + h);
      continue;
    }
    balance_.rain += rain_depth_ * rain_.weighted_area();
    balance_.sources += source_volume;
    apply_infiltration(U1_, h);
    apply_friction(U1_, h);
    apply_drag(U1_, h);
    exchange(U1_);
    std::swap(U_, U1_);
    U_.time = h == t_end - t ? t_end : t + h;
    shrink = 1.0;
    ++stats_.count;
    stats_.cell_updates += cells_.cell_count;
    stats_.total += h;
    if (std::isfinite(dt_courant) && (stats_.smallest == 0.0 || dt_courant < stats_.smallest))
      stats_.smallest = dt_courant;
    if (sub_step_observer_) sub_step_observer_(U_.time, h);
  }
  U_.time = t_end;
  gather_step();
  balance_.volume = volume();
}

// Over ranks, after a step: the whole state on every rank, and what the bodies' and the piers'
// cells gave up.
void FiniteVolumeSolver::gather_step() {
  if (!split_) return;
  gather(U_);
  if (!pier_drag_.empty()) split_->gather(pier_drag_.impulse.data()->data(), 2);
  if (!body_drag_.empty()) {
    split_->gather(body_drag_.velocity_time.data()->data(), 2);
    split_->gather(body_drag_.time.data(), 1);
  }
}

void FiniteVolumeSolver::set_rank_split(std::shared_ptr<const RankSplit> split) {
  split_ = split && split->size() > 1 ? std::move(split) : nullptr;
}

void FiniteVolumeSolver::exchange(ConservedState& U) const {
  if (!split_) return;
  double* arrays[] = {U.h.data(), U.hu.data(), U.hv.data()};
  split_->exchange(arrays);
}

void FiniteVolumeSolver::gather(ConservedState& U) const {
  if (!split_) return;
  for (auto* a : {&U.h, &U.hu, &U.hv}) split_->gather(a->data(), 1);
}

// Round-off can leave a depth of -1e-17 m where a cell drained; such depths become 0 and the
// volume this adds to the sub-step's result (`weight` of it: half for the first stage) is
// counted as a source, so the balance stays exact. Returns a cell whose depth is more negative,
// or whose state is not finite, or -1.
int FiniteVolumeSolver::clamp_round_off(ConservedState& U, double weight,
                                        std::span<const int> cells) {
  for (int i : cells) {
    const double h = U.h[i];
    if (h >= 0.0 && std::isfinite(U.hu[i]) && std::isfinite(U.hv[i])) continue;
    if (!(h >= -negative_depth_round_off) || !std::isfinite(U.hu[i]) || !std::isfinite(U.hv[i]))
      return i;
    balance_.source -= weight * h * cells_.area[i];
    U.h[i] = U.hu[i] = U.hv[i] = 0.0;
  }
  return -1;
}

void FiniteVolumeSolver::fail_at(const ConservedState& U, int i, double t) const {
  const Vec2& p = cells_.centroid[i];
  throw_run_error(
      "t = {:.6g} s: the flow fails in the cell at ({:.3f}, {:.3f}) m even at 1/64 of the "
      "Courant step (h = {:.6g} m, hu = {:.6g}, hv = {:.6g} m^2/s): a negative depth or a value "
      "that is not finite; check the case (a discharge into a dry cell too small for it, a bed "
      "formula), or lower flow.fv.courant",
      t, p.x(), p.y(), U.h[i], U.hu[i], U.hv[i]);
}

void FiniteVolumeSolver::check(const ConservedState& U) const {
  for (int i = 0; i < cells_.cell_count; ++i)
    if (!std::isfinite(U.h[i]) || !std::isfinite(U.hu[i]) || !std::isfinite(U.hv[i]) ||
        U.h[i] < 0.0)
      throw_input_error(
          "{}: the initial flow is not finite or has a negative depth in the cell at ({:.3f}, "
          "{:.3f}) m (h = {}, hu = {}, hv = {})",
          case_.file.empty() ? "case" : case_.file, cells_.centroid[i].x(), cells_.centroid[i].y(),
          U.h[i], U.hu[i], U.hv[i]);
}

}  // namespace flotsam
