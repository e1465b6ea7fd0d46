#pragma once
// The consistent P2 mass matrix M_ij = (N_i, N_j) of the mesh and its sparse Cholesky factor,
// computed once: the L2 projection onto P2 of a field given by its weak form, f = M^{-1} F
// with F_i = (N_i, f). Used for the explicit acceleration that the characteristics carry
// (flow_time_stepping.cpp).
#include <Eigen/SparseCholesky>
#include <vector>

#include "mesh/mesh.hpp"

namespace flotsam {

class P2MassMatrix {
 public:
  explicit P2MassMatrix(const Mesh& mesh);

  /// Replaces the load vector F (one value per P2 node) by the nodal values of M^{-1} F.
  void project(std::vector<double>& F) const;

 private:
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor_;
};

}  // namespace flotsam
