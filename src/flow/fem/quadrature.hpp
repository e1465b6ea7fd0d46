#pragma once
// Quadrature rules for the flow assembly: a degree-5 rule on the reference triangle (exact for
// every product the weak form of (M-1) integrates on straight elements: P2 x P2 x P2 advection,
// P1 x P2 x P2 fluxes) and 3-point Gauss-Legendre on an edge (exact to degree 5).
#include <array>

namespace flotsam {

struct TrianglePoint {
  double r, s;    // [-] reference coordinates
  double weight;  // [-] weights sum to 1/2, the reference triangle's area
};

struct EdgePoint {
  double xi;      // [-] position along the edge, 0 at its first vertex, 1 at the second
  double weight;  // [-] weights sum to 1
};

constexpr int triangle_point_count = 7;
constexpr int edge_point_count = 3;

/// Radon's 7-point degree-5 rule (Strang & Fix, table 4.1).
const std::array<TrianglePoint, triangle_point_count>& triangle_rule();

/// Gauss-Legendre, 3 points, on [0, 1].
const std::array<EdgePoint, edge_point_count>& edge_rule();

}  // namespace flotsam
