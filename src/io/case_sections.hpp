#pragma once
// The readers of the case file's larger sections (io/case_file.cpp calls them in order). Each
// takes its section as a checked map and returns the configuration of io/case.hpp.
#include "io/case.hpp"
#include "io/yaml_reader.hpp"

namespace flotsam {

/// flow: engine (and the finite-volume options), water, viscosity (M-3), friction and other sources
/// (M-2), initial state (numbers or formulas), boundaries.
FlowConfig read_flow(const YamlMap& flow);

/// bodies: physics (spec 3), contact (spec 4.3), the explicit list (spec 2), releases (spec 5).
BodiesConfig read_bodies(const YamlMap& bodies);

}  // namespace flotsam
