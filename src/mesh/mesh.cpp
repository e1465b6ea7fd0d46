#include "mesh/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace flotsam {

int Mesh::find_group(const std::string& name) const {
  for (int g = 0; g < static_cast<int>(group_names.size()); ++g)
    if (group_names[g] == name) return g;
  return -1;
}

Mat2 Mesh::jacobian(int element) const {
  const auto& el = elements[element];
  const Vec2& x0 = nodes[el[0]];
  Mat2 J;
  J.col(0) = nodes[el[1]] - x0;
  J.col(1) = nodes[el[2]] - x0;
  return J;
}

std::array<int, 3> Mesh::edge_nodes(int element, int local_edge) const {
  const auto& el = elements[element];
  return {el[local_edge], el[(local_edge + 1) % 3], el[3 + local_edge]};
}

// A mid node within 1e-9 of the element's size of its edge's midpoint is on it, or within the
// rounding of coordinates of its magnitude (a mesh file's digits at UTM coordinates, 6e6 m,
// round to about 1e-9 m): 64 ulps of the largest coordinate. A curved boundary bulges by
// h^2 / (8 R), 1e-4 m for a 1 m edge on a 1 km radius, far above either.
bool Mesh::is_curved(int element) const {
  const auto& el = elements[element];
  double magnitude = 0.0;  // [m]
  for (const int n : el) magnitude = std::max(magnitude, nodes[n].cwiseAbs().maxCoeff());
  const double tolerance =
      1e-9 * std::sqrt(area[element]) + 64.0 * std::numeric_limits<double>::epsilon() * magnitude;
  for (int k = 0; k < 3; ++k) {
    const Vec2 straight = 0.5 * (nodes[el[k]] + nodes[el[(k + 1) % 3]]);
    if ((nodes[el[3 + k]] - straight).norm() > tolerance) return true;
  }
  return false;
}

}  // namespace flotsam
