#include "flow/fem/mass_matrix.hpp"

#include <stdexcept>

#include "flow/fem/element_values.hpp"

namespace flotsam {

P2MassMatrix::P2MassMatrix(const Mesh& mesh) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(36 * static_cast<size_t>(mesh.element_count()));
  ElementValues ev;
  for (int e = 0; e < mesh.element_count(); ++e) {
    compute_element_values(mesh, e, ev);
    const auto& el = mesh.elements[e];
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b) {
        double m = 0.0;  // [m^2] exact: the rule integrates degree 5
        for (int q = 0; q < triangle_point_count; ++q) m += ev.N2[q][a] * ev.N2[q][b] * ev.JxW[q];
        entries.emplace_back(el[a], el[b], m);
      }
  }
  Eigen::SparseMatrix<double> M(mesh.node_count(), mesh.node_count());
  M.setFromTriplets(entries.begin(), entries.end());
  factor_.compute(M);
  if (factor_.info() != Eigen::Success)
    throw std::logic_error("P2MassMatrix: the mass matrix of mesh " + mesh.source +
                           " is not positive definite (an inverted element?)");
}

void P2MassMatrix::project(std::vector<double>& F) const {
  Eigen::Map<Eigen::VectorXd> f(F.data(), static_cast<Eigen::Index>(F.size()));
  f = factor_.solve(Eigen::VectorXd(f));
}

}  // namespace flotsam
