#pragma once
// The flow engine a case asks for (flow.engine), chosen once at setup.
#include <memory>

#include "coupling/mesh_setup.hpp"
#include "flow/flow_engine.hpp"
#include "io/case.hpp"

namespace flotsam {

/// The case's engine on `mesh`; keeps references to both. InputError when the case uses what
/// the engine cannot take (a boundary type, naming the group and the engine). `setup` (or
/// nullptr): what it may take ready-made instead of building (coupling/mesh_setup.hpp).
/// `rank` of `ranks` > 1: this process advances its part of one flood split over MPI ranks
/// (finite volumes only: InputError for the FEM, naming the engine).
std::unique_ptr<FlowEngine> make_flow_engine(const Mesh& mesh, const Case& flow_case,
                                             const MeshSetup* setup = nullptr, int rank = 0,
                                             int ranks = 1);

}  // namespace flotsam
