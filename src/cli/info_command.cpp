// flotsam info FILE: what a mesh holds (nodes, elements, boundary groups with their lengths,
// element sizes and quality). FILE is a Gmsh .msh file or a case file (its mesh is generated).
#include <fmt/core.h>

#include <filesystem>

#include "cli/commands.hpp"
#include "cli/logging.hpp"
#include "io/case_file.hpp"
#include "mesh/mesh_generator.hpp"
#include "mesh/mesh_summary.hpp"
#include "mesh/msh_reader.hpp"

namespace flotsam::cli {

Mesh load_mesh_from(const std::string& path) {
  const auto ext = std::filesystem::path(path).extension().string();
  if (ext == ".yaml" || ext == ".yml") return generate_mesh(read_case(path).mesh);
  return read_msh(path);
}

void add_info_command(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand(
      "info",
      "Print what a mesh holds: nodes, elements, boundary groups with their lengths, element\n"
      "sizes and quality. FILE is a Gmsh .msh file, or a case file whose mesh is generated.\n"
      "Example: flotsam info out/bridge.msh");
  cmd->add_option("file", *path, "mesh (.msh) or case file (.yaml)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->callback(
      [path] { print_result(format_mesh_summary(summarize_mesh(load_mesh_from(*path)))); });
}

}  // namespace flotsam::cli
