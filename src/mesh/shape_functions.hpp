#pragma once
// Lagrange shape functions on the reference triangle (0,0), (1,0), (0,1), in reference
// coordinates (r, s). Node order as Mesh::elements: vertices 0 1 2, then mid nodes of edges
// 0-1, 1-2, 2-0. With lambda_0 = 1 - r - s, lambda_1 = r, lambda_2 = s:
//   P1: N_k = lambda_k
//   P2: N_k = lambda_k (2 lambda_k - 1) at vertices, N_{3+k} = 4 lambda_k lambda_{k+1} at mid nodes
#include <array>

#include "core/vec.hpp"

namespace flotsam {

using P1Values = std::array<double, 3>;
using P2Values = std::array<double, 6>;
using P1Gradients = std::array<Vec2, 3>;  // d N / d(r, s)
using P2Gradients = std::array<Vec2, 6>;

/// P2 values N_k and reference gradients (dN_k/dr, dN_k/ds) at (r, s) as plain numbers, into
/// N[k * stride], dr[k * stride], ds[k * stride], for loops over many points that compile to
/// vector code (stride: the points, the sampling of a batch of points); p2_values and
/// p2_reference_gradients are these. d lambda / d(r, s): lambda_0 -> (-1, -1), lambda_1 -> (1, 0),
/// lambda_2 -> (0, 1); the products by 0 and 1 are kept as written, so that every zero has the
/// sign the vector form (4 l0 - 1) (-1, -1), ... gives.
[[gnu::always_inline]] inline void p2_basis(double r, double s, double* N, double* dr, double* ds,
                                            int stride = 1) {
  const double l0 = 1.0 - r - s, l1 = r, l2 = s;
  const double c0 = 4 * l0 - 1, c1 = 4 * l1 - 1, c2 = 4 * l2 - 1;
  const int i = stride;
  N[0] = l0 * (2 * l0 - 1), N[i] = l1 * (2 * l1 - 1), N[2 * i] = l2 * (2 * l2 - 1);
  N[3 * i] = 4 * l0 * l1, N[4 * i] = 4 * l1 * l2, N[5 * i] = 4 * l2 * l0;
  dr[0] = c0 * -1.0, ds[0] = c0 * -1.0;
  dr[i] = c1 * 1.0, ds[i] = c1 * 0.0;
  dr[2 * i] = c2 * 0.0, ds[2 * i] = c2 * 1.0;
  dr[3 * i] = 4 * (l0 * 1.0 + l1 * -1.0), ds[3 * i] = 4 * (l0 * 0.0 + l1 * -1.0);
  dr[4 * i] = 4 * (l1 * 0.0 + l2 * 1.0), ds[4 * i] = 4 * (l1 * 1.0 + l2 * 0.0);
  dr[5 * i] = 4 * (l2 * -1.0 + l0 * 0.0), ds[5 * i] = 4 * (l2 * -1.0 + l0 * 1.0);
}

inline P1Values p1_values(double r, double s) {
  return {1.0 - r - s, r, s};
}

inline P1Gradients p1_reference_gradients() {
  return {Vec2(-1, -1), Vec2(1, 0), Vec2(0, 1)};
}

inline P2Values p2_values(double r, double s) {
  P2Values N;
  double dr[6], ds[6];
  p2_basis(r, s, N.data(), dr, ds);
  return N;
}

inline P2Gradients p2_reference_gradients(double r, double s) {
  double N[6], dr[6], ds[6];
  p2_basis(r, s, N, dr, ds);
  return {Vec2(dr[0], ds[0]), Vec2(dr[1], ds[1]), Vec2(dr[2], ds[2]),
          Vec2(dr[3], ds[3]), Vec2(dr[4], ds[4]), Vec2(dr[5], ds[5])};
}

}  // namespace flotsam
