#include "flow/fv/fv_flow_field.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

#include "flow/body_footprint.hpp"

namespace flotsam {

FvFlowField::FvFlowField(FiniteVolumeSolver& solver, const Mesh& mesh, std::vector<double> node_bed,
                         std::shared_ptr<const PointLocator> locator)
    : solver_(solver),
      mesh_(mesh),
      locator_(locator ? std::move(locator) : std::make_shared<const PointLocator>(mesh)),
      node_bed_(std::move(node_bed)) {
  const CellMesh& c = solver_.cells();
  bed_slope_.resize(c.cell_count);
  for (int i = 0; i < c.cell_count; ++i) {  // the plane through the corners: J^-T (dz1, dz2)
    const auto& k = c.corners[i];
    Mat2 J;
    J.col(0) = mesh.nodes[k[1]] - mesh.nodes[k[0]];
    J.col(1) = mesh.nodes[k[2]] - mesh.nodes[k[0]];
    const Vec2 dz(node_bed_[k[1]] - node_bed_[k[0]], node_bed_[k[2]] - node_bed_[k[0]]);
    bed_slope_[i] = J.inverse().transpose() * dz;
  }
}

void FvFlowField::advance_to_state() {
  std::swap(begin_, end_);
  t0_ = t1_;
  solver_.fill_field(end_);
  t1_ = solver_.time();
}

void FvFlowField::reset_to_state() {
  solver_.fill_field(end_);
  begin_ = end_;
  t0_ = t1_ = solver_.time();
}

int FvFlowField::cell_of(const Vec2& p, int& hint) const {
  const Location where = locator_->locate(p, hint);
  if (where.element >= 0) hint = where.element;
  return where.inside ? solver_.cells().cell_of(where.element, where.r, where.s) : -1;
}

int FvFlowField::cell_at(const Vec2& p, int& hint, FlowSample& out) const {
  const Location where = locator_->locate(p, hint);
  if (where.element >= 0) hint = where.element;
  if (!where.inside) {
    out.inside = false;
    out.boundary_group = where.boundary_group;
    return -1;
  }
  return solver_.cells().cell_of(where.element, where.r, where.s);
}

FlowSample FvFlowField::sample(const Vec2& p, double t, int& hint) const {
  FlowSample out;
  const int i = cell_at(p, hint, out);
  if (i < 0) return out;
  const CellMesh& c = solver_.cells();
  const Vec2 d = p - c.centroid[i];
  const double span = t1_ - t0_;
  const double alpha = span > 0.0 ? std::clamp((t - t0_) / span, 0.0, 1.0) : 1.0;
  const double z_b = solver_.bed()[i] + bed_slope_[i].dot(d);  // the cell's mean is z_i
  double H = 0.0, eta = 0.0;
  Vec2 u_at[2];
  Mat2 G = Mat2::Zero();
  for (int s = 0; s < 2; ++s) {
    const CellField& f = s == 0 ? begin_ : end_;
    const double w = s == 0 ? 1.0 - alpha : alpha;
    // A wet cell's surface is its reconstruction, its depth that surface over the bed plane.
    const double eta_s = f.h[i] > 0.0 ? f.eta[i] + f.grad_eta[i].dot(d) : z_b;
    H += w * std::max(0.0, eta_s - z_b);
    eta += w * std::max(eta_s, z_b);
    u_at[s] = Vec2(f.u[i] + f.grad_u[i].dot(d), f.v[i] + f.grad_v[i].dot(d));
    G.row(0) += w * f.grad_u[i].transpose();
    G.row(1) += w * f.grad_v[i].transpose();
  }
  out.H = H;
  out.eta = eta;
  out.u = (1.0 - alpha) * u_at[0] + alpha * u_at[1];
  out.grad_u = G;
  out.du_dt = span > 0.0 ? Vec2((u_at[1] - u_at[0]) / span) : Vec2::Zero();
  out.grad_zb = bed_slope_[i];
  return out;
}

namespace {

// The cells as the footprint walk sees them: those deeper than `wet_depth` count (a reaction's
// share; -infinity: every cell, wet or dry, as for the debris under a body).
struct WetCells {
  const CellMesh& c;
  const std::vector<double>& h;
  double wet_depth;  // [m]
  const Vec2& centroid(int i) const { return c.centroid[i]; }
  double area(int i) const { return c.area[i]; }
  const std::array<int, 3>& neighbours(int i) const { return c.neighbour[i]; }
  bool counts(int i) const { return h[i] > wet_depth; }
};

}  // namespace

void FvFlowField::set_body_reactions(const std::vector<BodyReaction>& reactions) {
  const CellMesh& c = solver_.cells();
  const WetCells cells{c, solver_.state().h, solver_.dry_depth()};
  const double rho = solver_.water_density();  // [kg/m^3]
  std::vector<Vec2> forces(c.cell_count, Vec2::Zero());
  BodyDrag drag;
  drag.reset(c.cell_count);
  reactions_ = reactions;
  shares_.clear();
  FootprintWalk walk(c.cell_count);
  for (int k = 0; k < static_cast<int>(reactions.size()); ++k) {
    const BodyReaction& r = reactions[k];
    FlowSample where;
    int hint = -1;
    const int start = cell_at(r.centre, hint, where);
    const std::vector<int>& found =
        start < 0 ? std::vector<int>{} : walk.covered(r, start, k, cells);
    // A footprint smaller than the cells: the one holding the centre; on a dry bed nothing
    // reaches the water.
    const bool wet = start >= 0 && (!found.empty() || cells.counts(start));
    const std::span<const int> covered = !wet            ? std::span<const int>{}
                                         : found.empty() ? std::span<const int>(&start, 1)
                                                         : std::span<const int>(found);
    double area = 0.0;  // [m^2]
    for (int i : covered) area += c.area[i];
    for (int i : covered) {
      const double w = c.area[i] / area;                     // [-] the cell's share of the body
      forces[i] += r.force * w;                              // [N]
      const double a = r.drag_rate * w / (rho * c.area[i]);  // [m/s]
      drag.rate[i] += a;
      drag.target[i] += a * r.velocity;
      shares_.add(i, w);
    }
    shares_.close_body();
  }
  drag.cells = shares_.cell;  // the cells under any body, each once
  std::sort(drag.cells.begin(), drag.cells.end());
  drag.cells.erase(std::unique(drag.cells.begin(), drag.cells.end()), drag.cells.end());
  drag_start_ = solver_.time();
  solver_.set_cell_forces(reactions.empty() ? std::vector<Vec2>{} : std::move(forces));
  solver_.set_body_drag(reactions.empty() ? BodyDrag{} : std::move(drag));
}

// Body k's drag over the flow step, K sum_i w_i (int u_i dt - v int dt) / span, exactly what its
// cells gave up (body_drag.hpp), and its added mass's explicit part.
std::vector<Vec2> FvFlowField::exchanged_forces() const {
  const BodyDrag& drag = solver_.body_drag();
  const double span = solver_.time() - drag_start_;  // [s]
  std::vector<Vec2> out(reactions_.size(), Vec2::Zero());
  if (drag.empty() || !(span > 0.0)) return out;
  for (int k = 0; k < static_cast<int>(reactions_.size()); ++k) {
    if (shares_.empty(k)) continue;  // on a dry bed or outside: nothing exchanged
    const BodyReaction& r = reactions_[k];
    Vec2 slip = Vec2::Zero();  // [m] int (u - u_p) dt, by the cells' shares
    for (int j = shares_.start[k]; j < shares_.start[k + 1]; ++j) {
      const int i = shares_.cell[j];
      slip += shares_.share[j] * (drag.velocity_time[i] - drag.time[i] * r.velocity);
    }
    out[k] = r.drag_rate * slip / span - r.force;
  }
  return out;
}

// The cells under each body, and the one holding its centre when its footprint holds no cell's
// centroid (a body smaller than the cells).
std::vector<std::uint8_t> FvFlowField::cells_under(const std::vector<BodyFootprint>& bodies) const {
  const CellMesh& c = solver_.cells();
  const WetCells cells{c, solver_.state().h, -std::numeric_limits<double>::infinity()};
  std::vector<std::uint8_t> under(bodies.empty() ? 0 : c.cell_count, 0);
  FootprintWalk walk(c.cell_count);
  for (int k = 0; k < static_cast<int>(bodies.size()); ++k) {
    int hint = -1;
    const int start = cell_of(bodies[k].centre, hint);
    if (start < 0) continue;
    under[start] = 1;
    for (int i : walk.covered(bodies[k], start, k, cells)) under[i] = 1;
  }
  return under;
}

}  // namespace flotsam
