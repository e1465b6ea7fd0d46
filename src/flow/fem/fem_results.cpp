// The finite-element engine's UGRID results (flow/result_fields.hpp): each P2 element as its
// four straight sub-triangles over the P2 nodes (the paper's Fig. 3, as the .vtu's), the state
// per node at each output; the water level of a mid node is its depth on its bed.
#include "flow/fem/fem_engine.hpp"
#include "flow/result_variables.hpp"

namespace flotsam {

ResultMesh FemEngine::result_mesh() const {
  const Mesh& mesh = solver_.mesh();
  ResultMesh m;
  m.faces.reserve(4 * mesh.elements.size());
  for (const auto& el : mesh.elements)
    for (const auto& sub : Mesh::sub_triangles)
      m.faces.push_back({el[sub[0]], el[sub[1]], el[sub[2]]});
  m.node_bed = solver_.bed();
  return m;
}

ResultFields FemEngine::result_fields() const {
  namespace var = result_variables;
  std::vector<double> depth = solver_.depth(), level(depth.size());
  for (std::size_t k = 0; k < depth.size(); ++k) level[k] = depth[k] + solver_.bed()[k];
  constexpr auto node = UgridLocation::node;
  ResultFields f;
  f.add(var::depth(node), std::move(depth));
  f.add(var::water_level(node), std::move(level));
  f.add(var::velocity_x(node), solver_.u());
  f.add(var::velocity_y(node), solver_.v());
  return f;
}

}  // namespace flotsam
