#pragma once
// Second-order MUSCL reconstruction on the cells (docs/model.md (M-12)): per cell, limited
// gradients of the depth h, the surface eta = h + z_b and the velocity (u, v), from which the
// value at an edge's midpoint x_e is phi_e = phi_i + grad phi . (x_e - x_i).
//
//   gradient: least squares over the three neighbours (cell_mesh.hpp), neighbours whose
//             differences do not count contributing 0 (boundary edges: zero-gradient ghosts);
//   limiter:  Barth-Jespersen: the gradient scaled by the largest alpha in [0, 1] that keeps
//             every edge value within the min and max of the cell and its neighbours. h >= 0
//             on every edge follows, and the edge values average to the cell's.
//   wet/dry:  a dry cell (h <= dry depth) is first order; a wet cell leaves its dry
//             neighbours out of eta's and the velocity's gradients, so a shoreline does not tilt
//             the surface of a lake at rest (eta of a dry cell is its bed).
//   order 1:  all gradients are zero.
#include <span>
#include <vector>

#include "core/vec.hpp"
#include "flow/fv/cell_mesh.hpp"

namespace flotsam {

/// The flow in every cell with its limited gradients and its values at the midpoints of the
/// cell's three edges: what the fluxes, the sources and the bodies' samples read.
struct CellField {
  std::vector<double> h, eta, u, v;                    // [m], [m], [m/s], [m/s]
  std::vector<Vec2> grad_h, grad_eta, grad_u, grad_v;  // [-], [-], [1/s], [1/s]
  // At edge k of cell i, index 3 i + k: h_e >= 0, eta_e, u_e, v_e.
  std::vector<double> edge_h, edge_eta, edge_u, edge_v;

  void resize(int cells);
};

/// Fills `field`'s gradients and edge values from its cell values h, eta, u, v.
void reconstruct(const CellMesh& cells, int order, double dry_depth, CellField& field);
/// The same for `cells` only (local time stepping: the cells whose edges are evaluated).
void reconstruct(const CellMesh& cells, int order, double dry_depth, CellField& field,
                 std::span<const int> cells_to_do);

}  // namespace flotsam
