#include "mesh/mesh.hpp"

#include <cmath>

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

bool Mesh::is_curved(int element) const {
  const auto& el = elements[element];
  const double h = std::sqrt(area[element]);
  for (int k = 0; k < 3; ++k) {
    const Vec2 straight = 0.5 * (nodes[el[k]] + nodes[el[(k + 1) % 3]]);
    if ((nodes[el[3 + k]] - straight).norm() > 1e-9 * h) return true;
  }
  return false;
}

}  // namespace flotsam
