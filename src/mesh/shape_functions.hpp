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

P1Values p1_values(double r, double s);
P1Gradients p1_reference_gradients();
P2Values p2_values(double r, double s);
P2Gradients p2_reference_gradients(double r, double s);

}  // namespace flotsam
