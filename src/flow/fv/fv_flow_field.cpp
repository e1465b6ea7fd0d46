#include "flow/fv/fv_flow_field.hpp"

#include <algorithm>
#include <cmath>

namespace flotsam {

FvFlowField::FvFlowField(FiniteVolumeSolver& solver, const Mesh& mesh, std::vector<double> node_bed)
    : solver_(solver), mesh_(mesh), locator_(mesh), node_bed_(std::move(node_bed)) {
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

int FvFlowField::cell_at(const Vec2& p, int& hint, FlowSample& out) const {
  const Location where = locator_.locate(p, hint);
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

void FvFlowField::set_body_reactions(const std::vector<BodyReaction>& reactions) {
  const CellMesh& c = solver_.cells();
  const auto& h = solver_.state().h;
  const double wet_depth = solver_.dry_depth();
  std::vector<Vec2> forces(c.cell_count, Vec2::Zero());
  // Cells near a body are found by a walk over neighbours from the cell holding its centre,
  // among those whose centroid lies within the footprint's circumcircle widened by the cell's
  // size; the footprint holds the wet ones whose centroid is inside the rectangle.
  std::vector<int> stamp(c.cell_count, -1), queue, covered;
  for (int k = 0; k < static_cast<int>(reactions.size()); ++k) {
    const BodyReaction& r = reactions[k];
    FlowSample where;
    int hint = -1;
    const int start = cell_at(r.centre, hint, where);
    if (start < 0) continue;
    const Vec2 axis(std::cos(r.angle), std::sin(r.angle));
    const double reach = r.half_extents.norm();  // [m]
    double area = 0.0;
    covered.clear();
    queue.assign(1, start);
    stamp[start] = k;
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const int i = queue[q];
      const Vec2 d = c.centroid[i] - r.centre;
      if (d.norm() > reach + 2.0 * std::sqrt(c.area[i])) continue;
      if (h[i] > wet_depth && std::abs(d.dot(axis)) <= r.half_extents.x() &&
          std::abs(cross(axis, d)) <= r.half_extents.y()) {
        covered.push_back(i);
        area += c.area[i];
      }
      for (int j : c.neighbour[i])
        if (j >= 0 && stamp[j] != k) {
          stamp[j] = k;
          queue.push_back(j);
        }
    }
    if (covered.empty()) {
      if (h[start] <= wet_depth) continue;  // on a dry bed: nothing reaches the water
      covered.push_back(start);
      area = c.area[start];
    }
    for (int i : covered) forces[i] += r.force * (c.area[i] / area);  // [N]
  }
  solver_.set_cell_forces(reactions.empty() ? std::vector<Vec2>{} : std::move(forces));
}

}  // namespace flotsam
