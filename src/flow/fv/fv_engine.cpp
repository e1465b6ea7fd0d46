#include "flow/fv/fv_engine.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "flow/bed.hpp"
#include "flow/friction_map.hpp"
#include "io/binary_archive.hpp"
#include "io/vtu_writer.hpp"

namespace flotsam {

FvEngine::FvEngine(const Mesh& mesh, const Case& flow_case, std::shared_ptr<const CellMesh> cells,
                   std::shared_ptr<const PointLocator> locator)
    : mesh_(mesh),
      case_(flow_case),
      solver_(mesh, flow_case, std::move(cells)),
      locator_(std::move(locator)) {}

void FvEngine::initialize() {
  solver_.initialize();
  envelope_.reset(solver_.cells().cell_count, case_.output.wet_depth);
  envelope_.update(solver_.state().h, solver_.state().hu, solver_.state().hv, 0.0, 0.0);
  envelope_.end_step({});
  solver_.set_sub_step_observer([this](double t, double dt) {
    const ConservedState& U = solver_.state();
    const RankSplit* split = solver_.rank_split();  // over ranks: its own cells, gathered later
    envelope_.update(U.h, U.hu, U.hv, t, dt, split ? split->own() : std::span<const int>());
  });
  field_ = std::make_unique<FvFlowField>(solver_, mesh_, solver_.node_bed(), locator_);
  field_->reset_to_state();
  nodal_valid_ = false;
}

void FvEngine::split_over_ranks(int rank, int ranks) {
  const std::vector<int> weights = size_weights(solver_.cells(), solver_.time_levels());
  solver_.set_rank_split(std::make_shared<const RankSplit>(solver_.cells(), rank, ranks, weights,
                                                           solver_.open_boundary()));
}

void FvEngine::synchronize() {
  if (const RankSplit* split = solver_.rank_split()) {  // each cell's envelope from its owner
    for (std::vector<double>* a : envelope_.per_cell_arrays()) split->gather(a->data(), 1);
  }
}

void FvEngine::step(double dt) {
  envelope_.start_step();
  solver_.advance(dt);
  envelope_.end_step(debris_);  // over ranks, right in the own cells until synchronize()
  field_->advance_to_state();
  nodal_valid_ = false;
}

// Frozen mode: steps of time.spin_up_step until the largest change of the velocity in one step
// is at most 1e-5 of the largest velocity; that state is the flow at t = 0.
void FvEngine::settle(const TimeConfig& time) {
  double change = 1.0;
  while (solver_.time() < time.spin_up_end) {
    const ConservedState before = solver_.state();
    solver_.advance(time.spin_up_step);
    const ConservedState& now = solver_.state();
    double largest = 0.0, most = 0.0;
    for (std::size_t i = 0; i < now.h.size(); ++i) {
      if (now.h[i] <= solver_.dry_depth() || before.h[i] <= solver_.dry_depth()) continue;
      const Vec2 u1(now.hu[i] / now.h[i], now.hv[i] / now.h[i]);
      const Vec2 u0(before.hu[i] / before.h[i], before.hv[i] / before.h[i]);
      largest = std::max(largest, u1.norm());
      most = std::max(most, (u1 - u0).norm());
    }
    change = largest > 0.0 ? most / largest : 0.0;
    if (change <= settled_change) break;
  }
  finish_march(change, solver_.time());
  ConservedState steady = solver_.state();
  steady.time = 0.0;
  solver_.set_state(steady);
  solver_.restart_water_balance();
  envelope_.reset(solver_.cells().cell_count, case_.output.wet_depth);  // the run starts now
  envelope_.update(steady.h, steady.hu, steady.hv, 0.0, 0.0);
  envelope_.end_step({});
  field_->reset_to_state();
  nodal_valid_ = false;
}

// Each corner of a cell takes the area-weighted mean of the wet cells around it (the bed and no
// velocity where all are dry: the node is dry); with cells = elements, a mid node the mean of
// its edge's ends (wet when either is).
const FlowState& FvEngine::nodal_state() const {
  if (nodal_valid_) return nodal_;
  const CellMesh& c = solver_.cells();
  const ConservedState& U = solver_.state();
  const int nodes = mesh_.node_count();
  std::vector<double> eta(nodes, 0.0), u(nodes, 0.0), v(nodes, 0.0), weight(nodes, 0.0);
  for (int i = 0; i < c.cell_count; ++i) {
    if (U.h[i] <= solver_.dry_depth()) continue;
    const double A = c.area[i];
    for (int k : c.corners[i]) {
      eta[k] += A * (U.h[i] + solver_.bed()[i]);
      u[k] += A * U.hu[i] / U.h[i];
      v[k] += A * U.hv[i] / U.h[i];
      weight[k] += A;
    }
  }
  const auto& z = field_->node_bed();
  nodal_.time = U.time;
  nodal_.eta.resize(mesh_.vertex_count);
  nodal_.u.resize(nodes);
  nodal_.v.resize(nodes);
  nodal_wet_.resize(nodes);
  for (int k = 0; k < nodes; ++k) {
    const bool wet = weight[k] > 0.0;
    nodal_wet_[k] = wet;
    if (k < mesh_.vertex_count) nodal_.eta[k] = wet ? eta[k] / weight[k] : z[k];
    nodal_.u[k] = wet ? u[k] / weight[k] : 0.0;
    nodal_.v[k] = wet ? v[k] / weight[k] : 0.0;
  }
  if (c.kind == FvCells::elements)
    for (const auto& el : mesh_.elements)
      for (int k = 0; k < 3; ++k) {
        const int a = el[k], b = el[(k + 1) % 3], mid = el[3 + k];
        nodal_.u[mid] = 0.5 * (nodal_.u[a] + nodal_.u[b]);
        nodal_.v[mid] = 0.5 * (nodal_.v[a] + nodal_.v[b]);
        nodal_wet_[mid] = nodal_wet_[a] | nodal_wet_[b];
      }
  nodal_valid_ = true;
  return nodal_;
}

std::vector<std::uint8_t> FvEngine::wet_nodes() const {
  nodal_state();
  return nodal_wet_;
}

void FvEngine::write_fields(const std::string& path, double t) const {
  const CellMesh& c = solver_.cells();
  const ConservedState& U = solver_.state();
  const int n = c.cell_count;
  std::vector<double> eta(n), speed(n), froude(n);
  std::vector<Vec2> u(n);
  for (int i = 0; i < n; ++i) {
    const double h = U.h[i];
    eta[i] = h + solver_.bed()[i];
    u[i] = h > solver_.dry_depth() ? Vec2(U.hu[i] / h, U.hv[i] / h) : Vec2::Zero();
    speed[i] = u[i].norm();
    froude[i] = h > solver_.dry_depth() ? speed[i] / std::sqrt(case_.flow.gravity * h) : 0.0;
  }
  const FlowState& nodal = nodal_state();
  std::vector<Vec2> nodal_u(mesh_.node_count());
  for (int k = 0; k < mesh_.node_count(); ++k) nodal_u[k] = Vec2(nodal.u[k], nodal.v[k]);
  VtuFields fields;
  fields.add_cell_scalar("H [m]", U.h);
  fields.add_cell_scalar("eta [m]", eta);
  fields.add_cell_vector("u [m/s]", u);
  fields.add_cell_scalar("|u| [m/s]", speed);
  fields.add_cell_scalar("Froude [-]", froude);
  fields.add_cell_scalar("z_b [m]", solver_.bed());
  if (!case_.flow.friction_map.empty() && !solver_.friction_coefficients().empty())
    fields.add_cell_scalar(friction_field_name(case_.flow.friction),
                           solver_.friction_coefficients());
  if (case_.flow.rain.raster) fields.add_cell_scalar("rain weight [-]", solver_.rain().weights());
  fields.add_cell_scalar("max H [m]", envelope_.max_depth);
  fields.add_cell_scalar("max |u| [m/s]", envelope_.max_speed);
  fields.add_cell_scalar("max H|u| [m^2/s]", envelope_.max_unit_discharge);
  fields.add_cell_scalar("arrival time [s]", envelope_.arrival);
  fields.add_cell_scalar("wet duration [s]", envelope_.wet_duration);
  fields.add_cell_scalar("max hazard rating HR [-]", envelope_.max_hazard_rating);
  const std::vector<double> rating_class = envelope_.hazard_rating_class();
  fields.add_cell_scalar("hazard rating class (1-4)", rating_class);
  fields.add_cell_scalar("Australian hazard class (H1-H6)", envelope_.australian_class);
  fields.add_cell_scalar("vehicles unstable (0-3)", envelope_.vehicle_class);
  fields.add_p1_scalar("eta (nodal) [m]", nodal.eta);
  fields.add_point_vector("u (nodal) [m/s]", nodal_u);
  fields.add_point_scalar("z_b (nodal) [m]", field_->node_bed());
  write_vtu(path, mesh_, fields, t,
            c.kind == FvCells::split ? VtuCells::split : VtuCells::quadratic);
}

void FvEngine::save(ArchiveWriter& w, const std::string& prefix) const {
  const ConservedState& U = solver_.state();
  const WaterBalance& b = solver_.water_balance();
  const SubStepStats& s = solver_.sub_steps();
  w.write_value(prefix + ".time", U.time);
  w.write(prefix + ".h", U.h);
  w.write(prefix + ".hu", U.hu);
  w.write(prefix + ".hv", U.hv);
  write_water_balance(w, prefix, b);
  w.write(prefix + ".sub_steps",
          std::vector<double>{static_cast<double>(s.count), s.smallest, s.total,
                              static_cast<double>(s.rejected), s.cell_updates});
  envelope_.save(w, prefix);
}

void FvEngine::restore(ArchiveReader& r, const std::string& prefix) {
  restore_state(r, prefix, true);
  field_->reset_to_state();
  nodal_valid_ = false;
}

// The shared flow's step, with this run's bodies in its hazard rating, as step() folds them.
void FvEngine::restore_step(ArchiveReader& r, const std::string& prefix) {
  restore_state(r, prefix, false);
  envelope_.end_step(debris_);
  field_->advance_to_state();
  nodal_valid_ = false;
}

void FvEngine::restore_state(ArchiveReader& r, const std::string& prefix, bool own_rating) {
  ConservedState U;
  U.time = r.read_value<double>(prefix + ".time");
  U.h = r.read<double>(prefix + ".h");
  U.hu = r.read<double>(prefix + ".hu");
  U.hv = r.read<double>(prefix + ".hv");
  const auto cells = static_cast<std::size_t>(solver_.cells().cell_count);
  if (U.h.size() != cells || U.hu.size() != cells || U.hv.size() != cells)
    throw_input_error(
        "{}: the checkpoint's flow has {} cells, the case's mesh {}: the case or its mesh "
        "changed since the run",
        r.path(), U.h.size(), cells);
  solver_.set_state(U);
  solver_.restore_water_balance(read_water_balance(r, prefix));
  const auto s = r.read<double>(prefix + ".sub_steps");
  solver_.restore_sub_steps({static_cast<long>(s.at(0)), static_cast<long>(s.at(3)), s.at(1),
                             s.at(2), s.size() > 4 ? s[4] : 0.0});
  envelope_.restore(r, prefix, own_rating);
}

// The debris factor's cells (M-H2): those under the bodies, for the sub-steps to come.
void FvEngine::mark_debris(const std::vector<BodyFootprint>& bodies) {
  debris_ = field_->cells_under(bodies);
}

std::string FvEngine::summary() const {
  const SubStepStats& s = solver_.sub_steps();
  // Still, dry water has no wave speed: its sub-steps took what was left of each step.
  const std::string courant = s.smallest > 0.0
                                  ? fmt::format("Courant step smallest {:.3g} s, mean {:.3g} s",
                                                s.smallest, s.count > 0 ? s.total / s.count : 0.0)
                                  : std::string("no Courant limit (the water was dry and still)");
  // The work done, whatever the machine: one cell advanced one step (a retried one too).
  const double updates = s.cell_updates;
  // Local time stepping: the sub-steps are those of the finest cells (docs/model.md).
  const int levels = solver_.time_levels();
  const std::string finest =
      levels > 1 ? fmt::format(" of the finest of {} time levels", levels) : "";
  return fmt::format(
             "finite volumes   {} cells, {} sub-steps{} ({} retried at half the step), {:.4g} cell "
             "updates, {}; wet (deeper than {:g} m) {:.1f} % of the area\n",
             solver_.cells().cell_count, s.count, finest, s.rejected, updates, courant,
             case_.output.wet_depth, 100.0 * solver_.wet_fraction()) +
         piers_summary() + ranks_summary() + hazard_summary();
}

// The mean drag (M-25) each pier took over the run (since its start or restart), the first few.
std::string FvEngine::piers_summary() const {
  const PierDrag& drag = solver_.pier_drag();
  if (drag.empty() || drag.duration <= 0.0) return "";
  constexpr int listed = 6;
  const auto mean_kn = [&](const Vec2& impulse) {  // [m^4/s] -> mean force [kN]
    return case_.flow.water_density * impulse.norm() / drag.duration / 1e3;
  };
  std::string line;
  Vec2 total = Vec2::Zero();  // [m^4/s]
  for (int p = 0; p < static_cast<int>(drag.piers.size()); ++p) {
    const Vec2 impulse = drag.impulse_of(p);
    total += impulse;
    if (p < listed)
      line +=
          fmt::format("{}{} {:.3g} kN", p > 0 ? ", " : "", drag.piers[p].name, mean_kn(impulse));
  }
  if (drag.piers.size() > listed)
    line += fmt::format(" and {} more, all together {:.3g} kN", drag.piers.size() - listed,
                        mean_kn(total));
  return fmt::format("piers            mean drag over {:g} s (C_d {:g}): {}\n", drag.duration,
                     case_.flow.fv.pier_drag, line);
}

// One flood over ranks: this rank's part and what it spent and sent in communication.
std::string FvEngine::ranks_summary() const {
  const RankSplit* split = solver_.rank_split();
  if (!split) return "";
  return fmt::format(
      "MPI ranks        {}: rank {} advanced {} cells and read {} around them; {:.3g} s in "
      "communication ({:.2g} % of the run since the split), {:.3g} MB sent\n",
      split->size(), split->rank(), split->own().size(),
      split->loaded().size() - split->own().size(), split->communication_seconds(),
      100.0 * split->communication_seconds() / std::max(1e-9, split->seconds_since_split()),
      split->bytes_sent() / 1e6);
}

// The areas where the hazard reached the classes people act on (docs/model.md "Flood hazard").
std::string FvEngine::hazard_summary() const {
  const CellMesh& c = solver_.cells();
  const std::vector<double> rating = envelope_.hazard_rating_class();
  double largest = 0.0, extreme = 0.0, h5 = 0.0, cars = 0.0;  // [-], then [m^2]
  for (int i = 0; i < c.cell_count; ++i) {
    if (rating[i] == 0.0) continue;  // never wet
    largest = std::max(largest, envelope_.max_hazard_rating[i]);
    if (rating[i] == 4.0) extreme += c.area[i];
    if (envelope_.australian_class[i] >= 5.0) h5 += c.area[i];
    if (envelope_.vehicle_class[i] >= 1.0) cars += c.area[i];
  }
  return fmt::format(
      "flood hazard     largest rating HR {:.3g}; area of HR > 2 (danger for all) {:.4g} m^2, "
      "of H5-H6 {:.4g} m^2, where small cars lose stability {:.4g} m^2\n",
      largest, extreme, h5, cars);
}

std::vector<std::string> FvEngine::write_envelope_rasters(const std::string& prefix,
                                                          const RasterGrid& grid) const {
  if (raster_cells_.empty())  // the grid is the run's: its cells are found once
    raster_cells_ =
        pixel_cells(grid, [this](const Vec2& p, int& hint) { return field_->cell_of(p, hint); });
  return flotsam::write_envelope_rasters(envelope_, grid, raster_cells_, prefix);
}

}  // namespace flotsam
