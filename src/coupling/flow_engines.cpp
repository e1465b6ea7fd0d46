#include "coupling/flow_engines.hpp"

#include "flow/fem/fem_engine.hpp"
#include "flow/fv/fv_engine.hpp"

namespace flotsam {

std::unique_ptr<FlowEngine> make_flow_engine(const Mesh& mesh, const Case& flow_case,
                                             const MeshSetup* setup) {
  switch (flow_case.flow.engine) {
    case FlowEngineKind::fv:
      if (setup && setup->cells && setup->cell_kind == flow_case.flow.fv.cells)
        return std::make_unique<FvEngine>(mesh, flow_case, setup->cells, setup->locator);
      return std::make_unique<FvEngine>(mesh, flow_case);
    case FlowEngineKind::fem:
      break;
  }
  return std::make_unique<FemEngine>(mesh, flow_case);
}

}  // namespace flotsam
