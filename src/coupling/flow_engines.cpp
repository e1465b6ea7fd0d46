#include "coupling/flow_engines.hpp"

#include "flow/fem/fem_engine.hpp"
#include "flow/fv/fv_engine.hpp"

namespace flotsam {

std::unique_ptr<FlowEngine> make_flow_engine(const Mesh& mesh, const Case& flow_case) {
  switch (flow_case.flow.engine) {
    case FlowEngineKind::fv:
      return std::make_unique<FvEngine>(mesh, flow_case);
    case FlowEngineKind::fem:
      break;
  }
  return std::make_unique<FemEngine>(mesh, flow_case);
}

}  // namespace flotsam
