#pragma once
// The coupled sparse system in (u, v, eta) of one linearised step, its constraints and its
// direct solver. Unknowns: u at P2 node i is row 2i, v is 2i+1, eta at vertex j is 2N + j
// (N = P2 node count). The sparsity pattern holds full 2x2 node blocks, so that the u and v rows
// of a node have the same columns (slip constraints combine them); it is built once, and the
// symbolic factorisation is computed once and reused by every numeric factorisation
// (sparse_direct_solver.hpp).
#include <array>
#include <vector>

#include "core/vec.hpp"
#include "flow/fem/element_assembly.hpp"
#include "flow/fem/sparse_direct_solver.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

class LinearSystem {
 public:
  /// Builds the pattern for the mesh and the row lists of the constrained rows.
  void setup(const Mesh& mesh, const std::vector<int>& dirichlet_rows,
             const std::vector<int>& slip_nodes);

  int size() const { return static_cast<int>(b.size()); }
  static int u_row(int node) { return 2 * node; }
  static int v_row(int node) { return 2 * node + 1; }
  int eta_row(int vertex) const { return 2 * node_count_ + vertex; }

  /// Global rows of the 15 local unknowns of element e (element_assembly.hpp order).
  std::array<int, 15> element_rows(const Mesh& mesh, int e) const;

  void set_zero();
  /// Adds the local matrix and vector of `element`, whose rows are element_rows(mesh, element).
  /// The blocks of one colour (element_blocks.hpp) may be added concurrently: they share no
  /// node, so they touch no common entry.
  void add(int element, const std::array<int, 15>& rows, const LocalMatrix& K,
           const LocalVector& F);
  /// Adds `value` to A(row, column), an entry of the pattern (serial use only).
  void add_entry(int row, int column, double value) {
    A.valuePtr()[position(row, column)] += value;
  }

  /// Replaces Dirichlet row `slot` (index into dirichlet_rows of setup) by x_row = value.
  void set_dirichlet(int slot, double value);
  /// Replaces the rows of slip node `slot`: the u row by the tangential momentum equation, the
  /// v row by n . u = 0.
  void set_slip(int slot, const Vec2& normal);

  /// Residual (A x - b) of Dirichlet row `slot` before set_dirichlet replaced it: call
  /// save_dirichlet_rows after assembly and before the constraints. [units of that row]
  void save_dirichlet_rows();
  double saved_row_residual(int slot, const Eigen::VectorXd& x) const;

  SparseMatrix A;
  Eigen::VectorXd b;

 private:
  struct RowEntries {
    std::vector<int> position;  // index into A's value array
    std::vector<int> column;
  };
  int position(int row, int column) const;

  int node_count_ = 0;
  // Per element, 81 positions in A's value array: the first entry of each node block (u rows
  // and columns of the six P2 nodes, eta of the three vertices), from which add finds all 225
  // entries without a search. 324 B per element: 1.4 MB at 4.5k elements, 140 MB at 430k.
  std::vector<int> block_positions_;
  std::vector<int> dirichlet_rows_;
  std::vector<int> slip_nodes_;
  std::vector<RowEntries> dirichlet_entries_, slip_u_entries_, slip_v_entries_;
  std::vector<std::vector<double>> saved_values_;
  std::vector<double> saved_rhs_;
};

}  // namespace flotsam
