#include "mesh/element_order.hpp"

#include <algorithm>
#include <numeric>

#include "core/cuthill_mckee.hpp"
#include "mesh/curve_order.hpp"

namespace flotsam {

Mesh ordered_by_cuthill_mckee(const Mesh& mesh) {
  const int count = mesh.element_count();
  std::vector<int> start(1, 0), index;  // each element's neighbours across edges, increasing
  start.reserve(static_cast<std::size_t>(count) + 1);
  index.reserve(3 * static_cast<std::size_t>(count));
  for (int e = 0; e < count; ++e) {
    const auto first = index.end() - index.begin();
    for (const int across : mesh.neighbours[e])
      if (!Mesh::is_boundary(across)) index.push_back(across);
    std::sort(index.begin() + first, index.end());
    start.push_back(static_cast<int>(index.size()));
  }
  std::vector<int> same_nodes(mesh.node_count());
  std::iota(same_nodes.begin(), same_nodes.end(), 0);
  return renumbered(mesh, same_nodes, cuthill_mckee(start, index));
}

}  // namespace flotsam
