#pragma once
// The flow engine a case asks for (flow.engine), chosen once at setup.
#include <memory>

#include "flow/flow_engine.hpp"
#include "io/case.hpp"

namespace flotsam {

/// The case's engine on `mesh`; keeps references to both. InputError when the case uses what
/// the engine cannot take (a boundary type, naming the group and the engine).
std::unique_ptr<FlowEngine> make_flow_engine(const Mesh& mesh, const Case& flow_case);

}  // namespace flotsam
