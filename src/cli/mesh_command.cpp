// flotsam mesh CASE.yaml -o mesh.msh [--vtu mesh.vtu]: generate (or read) the case's mesh, write
// it as Gmsh MSH and optionally as a ParaView file, and print its summary.
#include <fmt/core.h>

#include <filesystem>

#include "cli/commands.hpp"
#include "cli/logging.hpp"
#include "core/error.hpp"
#include "io/case_file.hpp"
#include "io/vtk_writer.hpp"
#include "mesh/mesh_generator.hpp"
#include "mesh/mesh_summary.hpp"

namespace flotsam::cli {

void check_can_write(const std::string& path, bool overwrite) {
  if (std::filesystem::exists(path) && !overwrite)
    throw_input_error("'{}' exists; pass --overwrite to replace it, or choose another name", path);
  const auto parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
}

void add_mesh_command(CLI::App& app) {
  struct Options {
    std::string case_file, msh, vtu;
    bool overwrite = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "mesh",
      "Generate the mesh of a case file's geometry (channel with piers, bend, polygon) with Gmsh\n"
      "and write it as a Gmsh .msh file (MSH 4.1; .msh2 for MSH 2.2).\n"
      "Example: flotsam mesh examples/bridge_piers.yaml -o out/bridge.msh --vtu out/bridge.vtu");
  cmd->add_option("case", options->case_file, "case file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", options->msh, "mesh file to write (.msh)")->required();
  cmd->add_option("--vtu", options->vtu, "also write the mesh for ParaView (.vtu)");
  cmd->add_flag("--overwrite", options->overwrite, "replace output files that exist");
  cmd->callback([options] {
    check_can_write(options->msh, options->overwrite);
    if (!options->vtu.empty()) check_can_write(options->vtu, options->overwrite);
    const Case c = read_case(options->case_file);
    const Mesh mesh = generate_mesh(c.mesh, options->msh);
    if (!options->vtu.empty()) write_vtu(options->vtu, mesh, VtuFields{}, 0.0);
    print_result(format_mesh_summary(summarize_mesh(mesh)));
    print_result(fmt::format("wrote {}{}\n", options->msh,
                             options->vtu.empty() ? "" : " and " + options->vtu));
  });
}

}  // namespace flotsam::cli
