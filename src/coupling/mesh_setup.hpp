#pragma once
// What the runs of one case on one mesh can share instead of each building it again (an
// ensemble's members, docs/performance.md "Ensembles"): the finite-volume engine's cells, the
// point locator of its flow field, and the mesh's checksum that every checkpoint holds. Built
// once and only read after, so runs on several threads share it.
#include <memory>
#include <string>

#include "flow/fv/cell_mesh.hpp"
#include "io/case.hpp"
#include "mesh/mesh.hpp"
#include "mesh/point_locator.hpp"

namespace flotsam {

struct MeshSetup {
  FvCells cell_kind = FvCells::split;           // the kind `cells` were built as
  std::shared_ptr<const CellMesh> cells;        // flow.engine fv; nullptr for the FEM
  std::shared_ptr<const PointLocator> locator;  // flow.engine fv; nullptr for the FEM
  std::string mesh_checksum;                    // mesh_checksum(mesh)
};

/// Built on `mesh` for the case's engine; `mesh` must outlive every run given the set-up, and
/// those runs' meshes must equal it (copies of it).
MeshSetup prepare_mesh_setup(const Mesh& mesh, const Case& run_case);

/// The mesh the run was computed on, whether read or generated: nodes, elements, groups (FNV-1a
/// of their bytes, as hex digits; checkpoints hold it, io/case_digest.hpp).
std::string mesh_checksum(const Mesh& mesh);

}  // namespace flotsam
