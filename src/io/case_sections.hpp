#pragma once
// The readers of the case file's larger sections (io/case_file.cpp calls them in order). Each
// takes its section as a checked map and returns the configuration of io/case.hpp.
#include <filesystem>
#include <string>

#include "io/case.hpp"
#include "io/yaml_reader.hpp"

namespace flotsam {

/// flow: engine (and the finite-volume options), water, viscosity (M-3), friction and other sources
/// (M-2), initial state (numbers or formulas), boundaries.
FlowConfig read_flow(const YamlMap& flow);

/// mesh.region: outline, boundary lines, buildings, piers (files read relative to `case_folder`),
/// sizes; `crs_wkt` receives the outline file's coordinate system (unchanged for points).
RegionGeometry read_region(const YamlMap& region, const std::filesystem::path& case_folder,
                           std::string& crs_wkt);

/// bodies: physics (spec 3), contact (spec 4.3), the explicit list (spec 2), releases (spec 5).
BodiesConfig read_bodies(const YamlMap& bodies);

}  // namespace flotsam
