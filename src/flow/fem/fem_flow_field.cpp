#include "flow/fem/fem_flow_field.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "flow/body_footprint.hpp"
#include "mesh/shape_functions.hpp"

namespace flotsam {

FemFlowField::FemFlowField(ShallowWaterSolver& solver) : solver_(solver), locator_(solver.mesh()) {
  // A straight element's map x = x_0 + r (x_1 - x_0) + s (x_2 - x_0) has a constant Jacobian:
  // its J^-T once here instead of the isoparametric sum at every sample.
  const Mesh& mesh = solver_.mesh();
  elements_.resize(mesh.element_count());
  for (int e = 0; e < mesh.element_count(); ++e) {
    const auto& el = mesh.elements[e];
    ElementRecord& record = elements_[e];
    for (int k = 0; k < 6; ++k) record.pack[k] = NodePack::size * el[k];
    Mat2 J_inv_T = Mat2::Zero();
    if (!mesh.is_curved(e)) {
      Mat2 J;
      J.col(0) = mesh.nodes[el[1]] - mesh.nodes[el[0]];
      J.col(1) = mesh.nodes[el[2]] - mesh.nodes[el[0]];
      J_inv_T = J.inverse().transpose();
    }
    record.J[0] = J_inv_T(0, 0), record.J[1] = J_inv_T(0, 1);
    record.J[2] = J_inv_T(1, 0), record.J[3] = J_inv_T(1, 1);
  }
}

FlowSample FemFlowField::sample(const Vec2& p, double t, int& hint) const {
  const Location where = locator_.locate(p, hint);
  FlowSample out;
  if (where.element >= 0) hint = where.element;
  if (!where.inside) {
    out.inside = false;
    out.boundary_group = where.boundary_group;
    return out;
  }
  const Mesh& mesh = solver_.mesh();
  const auto& el = mesh.elements[where.element];
  const P2Values N = p2_values(where.r, where.s);
  const P2Gradients g2 = p2_reference_gradients(where.r, where.s);
  const P1Values M = p1_values(where.r, where.s);
  const double* straight = elements_[where.element].J;
  Mat2 J_inv_T;
  J_inv_T << straight[0], straight[1], straight[2], straight[3];
  if (where.curved) {
    Mat2 J = Mat2::Zero();  // isoparametric map at (r, s)
    for (int k = 0; k < 6; ++k) J += mesh.nodes[el[k]] * g2[k].transpose();
    J_inv_T = J.inverse().transpose();
  }

  const FlowState& s0 = solver_.previous_state();
  const FlowState& s1 = solver_.state();
  const double span = s1.time - s0.time;  // [s]
  const double alpha = span > 0.0 ? std::clamp((t - s0.time) / span, 0.0, 1.0) : 1.0;
  Vec2 u0 = Vec2::Zero(), u1 = Vec2::Zero();
  Mat2 G0 = Mat2::Zero(), G1 = Mat2::Zero();
  double z_b = 0.0;
  for (int k = 0; k < 6; ++k) {
    const Vec2 a(s0.u[el[k]], s0.v[el[k]]), b(s1.u[el[k]], s1.v[el[k]]);
    const Vec2 d = J_inv_T * g2[k];
    u0 += N[k] * a;
    u1 += N[k] * b;
    G0 += a * d.transpose();
    G1 += b * d.transpose();
    z_b += N[k] * solver_.bed()[el[k]];
    out.grad_zb += solver_.bed()[el[k]] * d;
  }
  double eta0 = 0.0, eta1 = 0.0;
  for (int j = 0; j < 3; ++j) {
    eta0 += M[j] * s0.eta[el[j]];
    eta1 += M[j] * s1.eta[el[j]];
  }
  out.eta = (1 - alpha) * eta0 + alpha * eta1;
  out.H = out.eta - z_b;
  out.u = (1 - alpha) * u0 + alpha * u1;
  out.grad_u = (1 - alpha) * G0 + alpha * G1;
  out.du_dt = span > 0.0 ? Vec2((u1 - u0) / span) : Vec2::Zero();
  return out;
}

namespace {

// The elements as the footprint walk sees them: every element carries a share.
struct Elements {
  const Mesh& mesh;
  Vec2 centroid(int e) const {
    const auto& el = mesh.elements[e];
    return (mesh.nodes[el[0]] + mesh.nodes[el[1]] + mesh.nodes[el[2]]) / 3.0;
  }
  double area(int e) const { return mesh.area[e]; }
  const std::array<int, 3>& neighbours(int e) const { return mesh.neighbours[e]; }  // < 0: edge
  bool counts(int) const { return true; }
};

}  // namespace

void FemFlowField::set_body_reactions(const std::vector<BodyReaction>& reactions) {
  const Mesh& mesh = solver_.mesh();
  const double rho = solver_.flow_case().flow.water_density;  // [kg m^-3]
  std::vector<Vec2> forces(mesh.element_count(), Vec2::Zero());
  std::vector<double> drag_rates(mesh.element_count(), 0.0);
  const FlowState& s = solver_.state();
  auto element_water_mass = [&](int e) {  // rho * integral of H over e (P1 eta, P2 bed, straight)
    const auto& el = mesh.elements[e];
    const auto& z = solver_.bed();
    const double eta = (s.eta[el[0]] + s.eta[el[1]] + s.eta[el[2]]) / 3.0;
    const double zb = (z[el[3]] + z[el[4]] + z[el[5]]) / 3.0;  // exact mean of a P2 field
    return rho * mesh.area[e] * (eta - zb);
  };
  reactions_ = reactions;
  shares_.clear();
  FootprintWalk walk(mesh.element_count());
  for (int k = 0; k < static_cast<int>(reactions.size()); ++k) {
    const BodyReaction& r = reactions[k];
    const Location where = locator_.locate(r.centre, -1);
    const std::vector<int>& found =
        where.inside ? walk.covered(r, where.element, k, Elements{mesh}) : std::vector<int>{};
    // A footprint smaller than the elements: the one holding the centre.
    const std::span<const int> covered = !where.inside   ? std::span<const int>{}
                                         : found.empty() ? std::span<const int>(&where.element, 1)
                                                         : std::span<const int>(found);
    double mass = 0.0;  // [kg]
    for (int e : covered) {
      shares_.add(e, element_water_mass(e));
      mass += shares_.share.back();
    }
    for (int j = shares_.start[k]; j < static_cast<int>(shares_.cell.size()); ++j) {
      // Spread by the water's mass: every element under the body takes the same acceleration,
      // the added mass's part explicit, the drag -K (u - u_p) / mass implicit.
      const int e = shares_.cell[j];
      forces[e] += (r.force + r.drag_rate * r.velocity) / mass;  // [m s^-2]
      drag_rates[e] += r.drag_rate / mass;                       // [1/s]
      shares_.share[j] /= mass;
    }
    shares_.close_body();
  }
  const bool none = reactions.empty();
  solver_.set_element_forces(none ? std::vector<Vec2>{} : std::move(forces));
  solver_.set_element_drag_rates(none ? std::vector<double>{} : std::move(drag_rates));
}

// Body k's drag at the elements' mean velocity now, K sum_e w_e (u_e - u_p), and its added
// mass's part: after a step, what the step's implicit drag took from the water.
std::vector<Vec2> FemFlowField::exchanged_forces() const {
  const Mesh& mesh = solver_.mesh();
  const FlowState& s = solver_.state();
  std::vector<Vec2> out(reactions_.size(), Vec2::Zero());
  for (int k = 0; k < static_cast<int>(reactions_.size()); ++k) {
    if (shares_.empty(k)) continue;  // outside: nothing exchanged
    const BodyReaction& r = reactions_[k];
    Vec2 u = Vec2::Zero();  // [m/s] the water's mean velocity under the body, by mass
    for (int j = shares_.start[k]; j < shares_.start[k + 1]; ++j) {
      const auto& el = mesh.elements[shares_.cell[j]];
      const Vec2 u_e((s.u[el[3]] + s.u[el[4]] + s.u[el[5]]) / 3.0,  // exact mean of P2
                     (s.v[el[3]] + s.v[el[4]] + s.v[el[5]]) / 3.0);
      u += shares_.share[j] * u_e;
    }
    out[k] = r.drag_rate * (u - r.velocity) - r.force;
  }
  return out;
}

}  // namespace flotsam
