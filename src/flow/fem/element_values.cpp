#include "flow/fem/element_values.hpp"

#include <cmath>

namespace flotsam {

namespace {

// Hessians of the P2 basis in reference coordinates: with lambda_0 = 1 - r - s, lambda_1 = r,
// lambda_2 = s and g_k = grad_(r,s) lambda_k (constant), N_k = lambda_k (2 lambda_k - 1) gives
// 4 g_k g_k^T and N_{3+k} = 4 lambda_k lambda_{k+1} gives 4 (g_k g_{k+1}^T + g_{k+1} g_k^T).
std::array<Mat2, 6> reference_hessians() {
  const std::array<Vec2, 3> g = {Vec2(-1, -1), Vec2(1, 0), Vec2(0, 1)};
  std::array<Mat2, 6> h;
  for (int k = 0; k < 3; ++k) {
    const int l = (k + 1) % 3;
    h[k] = 4.0 * g[k] * g[k].transpose();
    h[3 + k] = 4.0 * (g[k] * g[l].transpose() + g[l] * g[k].transpose());
  }
  return h;
}

// The basis and its reference gradients at the quadrature points, the same for every element.
struct ReferenceValues {
  std::array<P2Values, triangle_point_count> N2;
  std::array<P2Gradients, triangle_point_count> dN2;
  std::array<P1Values, triangle_point_count> N1;
  P1Gradients dN1;
};

const ReferenceValues& reference_values() {
  static const ReferenceValues values = [] {
    ReferenceValues v;
    const auto& rule = triangle_rule();
    for (int q = 0; q < triangle_point_count; ++q) {
      v.N2[q] = p2_values(rule[q].r, rule[q].s);
      v.dN2[q] = p2_reference_gradients(rule[q].r, rule[q].s);
      v.N1[q] = p1_values(rule[q].r, rule[q].s);
    }
    v.dN1 = p1_reference_gradients();
    return v;
  }();
  return values;
}

}  // namespace

void compute_element_values(const Mesh& mesh, int e, ElementValues& v, bool with_hessians) {
  const auto& el = mesh.elements[e];
  const auto& rule = triangle_rule();
  const ReferenceValues& ref = reference_values();
  const P1Gradients& g1 = ref.dN1;
  // A straight element's map is affine: its Jacobian is the same at every point.
  const bool curved = mesh.is_curved(e);
  Mat2 J_inv_T;
  double det_J = 0.0;  // [m^2]
  for (int q = 0; q < triangle_point_count; ++q) {
    const P2Gradients& g2 = ref.dN2[q];
    v.N2[q] = ref.N2[q];
    v.N1[q] = ref.N1[q];
    // Isoparametric map x(r, s) = sum_k X_k N_k(r, s): J = sum_k X_k (grad_(r,s) N_k)^T.
    Vec2 x = Vec2::Zero();
    for (int k = 0; k < 6; ++k) x += v.N2[q][k] * mesh.nodes[el[k]];
    if (q == 0 || curved) {
      Mat2 J = Mat2::Zero();
      for (int k = 0; k < 6; ++k) J += mesh.nodes[el[k]] * g2[k].transpose();
      J_inv_T = J.inverse().transpose();
      det_J = std::abs(J.determinant());
    }
    for (int k = 0; k < 6; ++k) v.dN2[q][k] = J_inv_T * g2[k];
    for (int k = 0; k < 3; ++k) v.dN1[q][k] = J_inv_T * g1[k];
    v.JxW[q] = det_J * rule[q].weight;
    v.x[q] = x;
  }
  v.area = mesh.area[e];
  v.size = std::sqrt(2.0 * v.area);
  static const std::array<Mat2, 6> h_ref = reference_hessians();
  if (!with_hessians || curved) {
    for (auto& h : v.hessian2) h.setZero();
  } else {
    const Mat2 J_inv = mesh.jacobian(e).inverse();
    for (int k = 0; k < 6; ++k) v.hessian2[k] = J_inv.transpose() * h_ref[k] * J_inv;
  }
}

namespace {

// Quadratic edge x(xi) = X_a (1-xi)(1-2xi) + X_b xi(2xi-1) + X_m 4xi(1-xi).
Vec2 edge_tangent(const Mesh& mesh, const std::array<int, 3>& nd, double xi) {
  return mesh.nodes[nd[0]] * (4 * xi - 3) + mesh.nodes[nd[1]] * (4 * xi - 1) +
         mesh.nodes[nd[2]] * (4 - 8 * xi);
}

}  // namespace

Vec2 edge_normal(const Mesh& mesh, const BoundaryEdge& edge, double xi) {
  const Vec2 t = edge_tangent(mesh, mesh.edge_nodes(edge.element, edge.local_edge), xi);
  // Counter-clockwise elements have their interior on the left of each edge: outward = right.
  return Vec2(t.y(), -t.x()).normalized();
}

void compute_edge_values(const Mesh& mesh, const BoundaryEdge& edge, EdgeValues& v) {
  v.nodes = mesh.edge_nodes(edge.element, edge.local_edge);
  const auto& rule = edge_rule();
  for (int q = 0; q < edge_point_count; ++q) {
    const double xi = rule[q].xi;
    v.N2[q] = {(1 - xi) * (1 - 2 * xi), xi * (2 * xi - 1), 4 * xi * (1 - xi)};
    v.N1[q] = {1 - xi, xi};
    const Vec2 t = edge_tangent(mesh, v.nodes, xi);
    v.normal[q] = Vec2(t.y(), -t.x()).normalized();
    v.ds[q] = t.norm() * rule[q].weight;
    v.x[q] = v.N2[q][0] * mesh.nodes[v.nodes[0]] + v.N2[q][1] * mesh.nodes[v.nodes[1]] +
             v.N2[q][2] * mesh.nodes[v.nodes[2]];
  }
}

}  // namespace flotsam
