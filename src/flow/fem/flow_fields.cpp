// ShallowWaterSolver: derived fields for output and sampling (depth, vorticity).
#include "flow/fem/shallow_water_solver.hpp"

namespace flotsam {

std::vector<double> ShallowWaterSolver::depth() const {
  std::vector<double> H(mesh_.node_count());
  for (int i = 0; i < mesh_.node_count(); ++i) {
    const double eta =
        i < mesh_.vertex_count
            ? state_.eta[i]
            : 0.5 * (state_.eta[mid_vertices_[i][0]] + state_.eta[mid_vertices_[i][1]]);
    H[i] = eta - z_b_[i];
  }
  return H;
}

// omega = dv/dx - du/dy at each P2 node, averaged over the elements that share the node.
std::vector<double> ShallowWaterSolver::vorticity() const {
  static const double node_r[6] = {0, 1, 0, 0.5, 0.5, 0};
  static const double node_s[6] = {0, 0, 1, 0, 0.5, 0.5};
  std::vector<double> omega(mesh_.node_count(), 0.0), count(mesh_.node_count(), 0.0);
  for (int e = 0; e < mesh_.element_count(); ++e) {
    const auto& el = mesh_.elements[e];
    for (int m = 0; m < 6; ++m) {
      const P2Gradients g = p2_reference_gradients(node_r[m], node_s[m]);
      Mat2 J = Mat2::Zero();
      for (int k = 0; k < 6; ++k) J += mesh_.nodes[el[k]] * g[k].transpose();
      const Mat2 J_inv_T = J.inverse().transpose();
      double w = 0.0;
      for (int k = 0; k < 6; ++k) {
        const Vec2 d = J_inv_T * g[k];
        w += state_.v[el[k]] * d.x() - state_.u[el[k]] * d.y();
      }
      omega[el[m]] += w;
      count[el[m]] += 1.0;
    }
  }
  for (int i = 0; i < mesh_.node_count(); ++i) omega[i] /= count[i];
  return omega;
}

}  // namespace flotsam
