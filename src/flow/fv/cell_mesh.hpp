#pragma once
// The finite-volume engine's cells (docs/model.md "Finite-volume engine", flow.fv.cells):
//   elements: the mesh's triangles (corners v0 v1 v2), cell e = element e;
//   split:    each six-node triangle split into its four straight sub-triangles, as the paper's
//             Fig. 3 splits it: the cells' corners are the mesh's P2 nodes, so the engine
//             resolves the flow as finely as the FEM's velocity on the same mesh file, and a
//             pier's circle is followed by its mid nodes (4x the cells, half the time step).
//
//        2                 cell 4e + 0: (v0, m01, m20)     cell 4e + 2: (m20, m12, v2)
//        | \               cell 4e + 1: (m01, v1, m12)     cell 4e + 3: (m01, m12, m20)
//        5   4
//        | 3   \           Edges are stored once, from their left cell to their right cell
//        0 - 3 - 1         (normal pointing left -> right), or to a boundary group.
//
// Hot data in flat arrays, one per quantity, indexed by cell or edge.
#include <array>
#include <vector>

#include "core/vec.hpp"
#include "io/case.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

struct CellMesh {
  FvCells kind = FvCells::split;
  int cell_count = 0;
  std::vector<std::array<int, 3>> corners;  // mesh node indices, counter-clockwise
  std::vector<Vec2> centroid;               // [m]
  std::vector<double> area;                 // [m^2]
  std::vector<double> length_scale;         // [m] 2 A / (3 l_max): the Courant length (model.md)
  // Per cell and local edge k (from corner k to corner k+1): the edge index, whether the cell is
  // the edge's left cell, and the vector from the centroid to the edge's midpoint [m].
  std::vector<std::array<int, 3>> cell_edges;
  std::vector<std::array<bool, 3>> cell_is_left;
  std::vector<std::array<Vec2, 3>> to_edge;
  // Least-squares gradient weights: grad phi = sum_k weight[k] (phi_k - phi_i) over the three
  // neighbours across the cell's edges (a boundary edge: the centroid mirrored in it) [1/m].
  std::vector<std::array<Vec2, 3>> gradient_weight;
  std::vector<std::array<int, 3>> neighbour;  // across local edge k, or -1 at a boundary

  int edge_count = 0;
  std::vector<int> left, right;            // cells; right = -1 on the boundary
  std::vector<int> left_slot, right_slot;  // local edge index of the edge in left / right cell
  std::vector<Vec2> normal;                // unit, from left to right (outward at the boundary)
  std::vector<double> length;              // [m]
  std::vector<int> group;                  // boundary group (Mesh::group_names), -1 inside
  std::vector<int> boundary_edges;         // the edges with right == -1, in order

  /// The sub-triangle of `element` that holds the point of reference coordinates (r, s) in it.
  static int sub_cell(int element, double r, double s);
  /// The cell that holds that point (its element, or the sub-triangle).
  int cell_of(int element, double r, double s) const {
    return kind == FvCells::split ? sub_cell(element, r, s) : element;
  }
};

/// The cells of `kind` with their edges and geometry. Throws std::logic_error when a boundary
/// edge of the mesh finds no group (a malformed Mesh).
CellMesh build_cell_mesh(const Mesh& mesh, FvCells kind = FvCells::split);

}  // namespace flotsam
