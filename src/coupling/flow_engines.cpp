#include "coupling/flow_engines.hpp"

#include "core/error.hpp"
#include "flow/fem/fem_engine.hpp"
#include "flow/fv/fv_engine.hpp"

namespace flotsam {

std::unique_ptr<FlowEngine> make_flow_engine(const Mesh& mesh, const Case& flow_case,
                                             const MeshSetup* setup, int rank, int ranks) {
  switch (flow_case.flow.engine) {
    case FlowEngineKind::fv: {
      const bool shared = setup && setup->cells && setup->cell_kind == flow_case.flow.fv.cells;
      auto engine = shared
                        ? std::make_unique<FvEngine>(mesh, flow_case, setup->cells, setup->locator)
                        : std::make_unique<FvEngine>(mesh, flow_case);
      if (ranks > 1) engine->split_over_ranks(rank, ranks);
      return engine;
    }
    case FlowEngineKind::fem:
      break;
  }
  if (ranks > 1)
    throw_input_error(
        "{}: flow.engine: fem does not split one flood over MPI ranks ({} were started); run it "
        "on one rank (its threads), or with `engine: fv`",
        flow_case.file.empty() ? "case" : flow_case.file, ranks);
  return std::make_unique<FemEngine>(mesh, flow_case);
}

}  // namespace flotsam
