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

// Inline: the sampling of a batch of points calls them in its loops over the points.
inline P1Values p1_values(double r, double s) {
  return {1.0 - r - s, r, s};
}

inline P1Gradients p1_reference_gradients() {
  return {Vec2(-1, -1), Vec2(1, 0), Vec2(0, 1)};
}

inline P2Values p2_values(double r, double s) {
  const double l0 = 1.0 - r - s, l1 = r, l2 = s;
  return {l0 * (2 * l0 - 1), l1 * (2 * l1 - 1), l2 * (2 * l2 - 1),
          4 * l0 * l1,       4 * l1 * l2,       4 * l2 * l0};
}

inline P2Gradients p2_reference_gradients(double r, double s) {
  const double l0 = 1.0 - r - s, l1 = r, l2 = s;
  // d lambda / d(r, s): lambda_0 -> (-1, -1), lambda_1 -> (1, 0), lambda_2 -> (0, 1).
  const Vec2 g0(-1, -1), g1(1, 0), g2(0, 1);
  return {(4 * l0 - 1) * g0,       (4 * l1 - 1) * g1,       (4 * l2 - 1) * g2,
          4 * (l0 * g1 + l1 * g0), 4 * (l1 * g2 + l2 * g1), 4 * (l2 * g0 + l0 * g2)};
}

}  // namespace flotsam
