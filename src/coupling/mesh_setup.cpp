#include "coupling/mesh_setup.hpp"

#include "io/checksum.hpp"

namespace flotsam {

MeshSetup prepare_mesh_setup(const Mesh& mesh, const Case& run_case) {
  MeshSetup setup;
  setup.mesh_checksum = mesh_checksum(mesh);
  if (run_case.flow.engine == FlowEngineKind::fv) {
    setup.cell_kind = run_case.flow.fv.cells;
    setup.cells = std::make_shared<const CellMesh>(build_cell_mesh(mesh, setup.cell_kind));
    setup.locator = std::make_shared<const PointLocator>(mesh);
  }
  return setup;
}

std::string mesh_checksum(const Mesh& mesh) {
  Checksum sum;
  sum.add(mesh.nodes.data(), mesh.nodes.size() * sizeof(Vec2));
  sum.add(mesh.elements.data(), mesh.elements.size() * sizeof(mesh.elements.front()));
  for (const BoundaryEdge& e : mesh.boundary) {
    sum.add(&e.element, sizeof e.element);
    sum.add(&e.local_edge, sizeof e.local_edge);
    sum.add(&e.group, sizeof e.group);
  }
  for (const std::string& group : mesh.group_names) sum.add(group + '\n');
  return sum.hex();
}

}  // namespace flotsam
