#pragma once
// Shape functions of one element at the quadrature points, in physical coordinates: the P2
// (velocity, bed) and P1 (elevation) bases, their gradients, the weights |det J| w_q, and the
// P2 Hessians used by the SUPG residual. Curved elements are isoparametric (J varies over the
// element); their Hessians are set to zero (second-order terms of the stabilisation only).
#include <array>

#include "core/vec.hpp"
#include "flow/fem/quadrature.hpp"
#include "mesh/mesh.hpp"
#include "mesh/shape_functions.hpp"

namespace flotsam {

struct ElementValues {
  std::array<P2Values, triangle_point_count> N2;      // P2 values [-]
  std::array<P2Gradients, triangle_point_count> dN2;  // [1/m]
  std::array<P1Values, triangle_point_count> N1;      // P1 values [-]
  std::array<P1Gradients, triangle_point_count> dN1;  // [1/m]
  std::array<double, triangle_point_count> JxW;       // [m^2]
  std::array<Vec2, triangle_point_count> x;           // quadrature points [m]
  std::array<Mat2, 6> hessian2;                       // d2 N_k / dx_i dx_j [1/m^2]
  double area = 0.0;                                  // [m^2]
  double size = 0.0;                                  // h_e = sqrt(2 A_e) [m]
};

/// Fills `values` for element e of the mesh; the Hessians (SUPG's alone) are zero unless
/// `with_hessians`.
void compute_element_values(const Mesh& mesh, int e, ElementValues& values,
                            bool with_hessians = true);

/// One boundary edge at the edge quadrature points: the P2 edge is parametrised by xi in [0, 1]
/// (vertex a = local k, vertex b = local k+1, mid node 3+k), so curved edges are exact.
struct EdgeValues {
  std::array<int, 3> nodes;                                // global a, b, mid
  std::array<std::array<double, 3>, edge_point_count> N2;  // along the edge: a, b, mid [-]
  std::array<std::array<double, 2>, edge_point_count> N1;  // along the edge: a, b [-]
  std::array<Vec2, edge_point_count> normal;               // unit outward normal [-]
  std::array<double, edge_point_count> ds;                 // weight |dx/dxi| w_q [m]
  std::array<Vec2, edge_point_count> x;                    // [m]
};

void compute_edge_values(const Mesh& mesh, const BoundaryEdge& edge, EdgeValues& values);

/// Unit outward normal of a boundary edge at xi (0: vertex a, 1/2: mid node, 1: vertex b).
Vec2 edge_normal(const Mesh& mesh, const BoundaryEdge& edge, double xi);

}  // namespace flotsam
