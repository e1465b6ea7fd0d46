#pragma once
// The readers of the case file's larger sections (io/case_file.cpp calls them in order). Each
// takes its section as a checked map and returns the configuration of io/case.hpp.
#include <filesystem>
#include <string>
#include <vector>

#include "geo/vector_layer.hpp"
#include "io/case.hpp"
#include "io/yaml_reader.hpp"

namespace flotsam {

/// A coordinate system met in one of the case's geodata files, and what it belongs to ("the
/// terrain raster 'dem.tif'"): all must agree (case_file.cpp).
struct GeodataCrs {
  std::string wkt;
  std::string what;
};

/// A vector layer given as a path or as {file, layer} (the map's other keys are the caller's),
/// with the numeric attribute `value_field` per polygon and the text `label_field` per line when
/// not empty (geo/vector_layer.hpp).
VectorLayer read_case_layer(const YamlValue& value, const std::filesystem::path& case_folder,
                            const std::string& value_field = "",
                            const std::string& label_field = "");

/// flow: engine (and the finite-volume options), water, viscosity (M-3), friction and other sources
/// (M-2), initial state (numbers or formulas), boundaries. Files (a roughness raster and zones,
/// a rain raster) are read relative to `case_folder`; their coordinate systems are added to
/// `geodata`.
FlowConfig read_flow(const YamlMap& flow, const std::filesystem::path& case_folder,
                     std::vector<GeodataCrs>& geodata);

/// flow.friction: the law, its default coefficient, and where it differs (a raster, zones).
void read_friction(const YamlMap& friction, const std::filesystem::path& case_folder,
                   FlowConfig& flow, std::vector<GeodataCrs>& geodata);

/// mesh.region: outline, boundary lines, buildings, piers (files read relative to `case_folder`),
/// sizes; `crs_wkt` receives the outline file's coordinate system (unchanged for points).
RegionGeometry read_region(const YamlMap& region, const std::filesystem::path& case_folder,
                           std::string& crs_wkt);

/// bridges: a list of {name, axis, piers, backwater_distance}, or a line layer {file, layer,
/// name_field, backwater_distance} (its coordinate system added to `geodata`). Refused with a
/// mesh.channel, which makes its bridges from its piers.
std::vector<BridgeConfig> read_bridges(const YamlValue& value,
                                       const std::filesystem::path& case_folder,
                                       const MeshSource& mesh, std::vector<GeodataCrs>& geodata);

/// bodies: physics (spec 3), contact (spec 4.3), the explicit list (spec 2), releases (spec 5).
BodiesConfig read_bodies(const YamlMap& bodies);

}  // namespace flotsam
