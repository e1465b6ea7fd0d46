// flotsam info FILE: what a mesh holds (nodes, elements, boundary groups with their lengths,
// element sizes and quality). FILE is a Gmsh .msh file or a case file (its mesh is generated).
// With --parts N, also how the finite-volume cells split into N parts for N MPI ranks
// (flow/fv/partition.hpp): each part's cells, its halo and the parts it exchanges with.
#include <fmt/core.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/logging.hpp"
#include "flow/fv/partition.hpp"
#include "flow/fv/time_levels.hpp"
#include "io/case_file.hpp"
#include "mesh/mesh_generator.hpp"
#include "mesh/mesh_summary.hpp"
#include "mesh/msh_reader.hpp"

namespace flotsam::cli {

namespace {

bool is_case_file(const std::string& path) {
  const auto ext = std::filesystem::path(path).extension().string();
  return ext == ".yaml" || ext == ".yml";
}

// The parts' figures: min / mean / max over the parts of each count.
std::string format_partition(const PartitionSummary& s, int parts) {
  const auto range = [](const auto& v) {
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    double sum = 0.0;
    for (const auto x : v) sum += static_cast<double>(x);
    return fmt::format("{} / {:.0f} / {}", *lo, sum / static_cast<double>(v.size()), *hi);
  };
  return fmt::format(
      "parts            {} (METIS, the finite-volume cells; min / mean / max over the parts)\n"
      "  cells          {}\n"
      "  halo cells     {} (two rings of other parts' cells)\n"
      "  neighbours     {} (parts exchanged with)\n"
      "  cut edges      {}; imbalance {:.3f} (largest part over the mean)\n",
      parts, range(s.cells), range(s.halo), range(s.neighbours), s.cut_edges, s.imbalance);
}

}  // namespace

void add_info_command(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  auto parts = std::make_shared<int>(0);
  CLI::App* cmd = app.add_subcommand(
      "info",
      "Print what a mesh holds: nodes, elements, boundary groups with their lengths, element\n"
      "sizes and quality. FILE is a Gmsh .msh file, or a case file whose mesh is generated.\n"
      "Example: flotsam info out/bridge.msh");
  cmd->add_option("file", *path, "mesh (.msh) or case file (.yaml)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--parts", *parts,
                  "also split the finite-volume cells into N parts, as N MPI ranks would take\n"
                  "them, and print their cells, halos and neighbours")
      ->check(CLI::Range(1, 1 << 20));
  cmd->callback([path, parts] {
    // The case's mesh and cells, or a .msh file's with the default cells.
    const std::optional<Case> c =
        is_case_file(*path) ? std::optional<Case>(read_case(*path)) : std::nullopt;
    const Mesh mesh = c ? generate_mesh(c->mesh) : read_msh(*path);
    std::string text = format_mesh_summary(summarize_mesh(mesh));
    if (*parts > 0) {
      const CellMesh cells =
          build_cell_mesh(mesh, c ? c->flow.fv.cells : FiniteVolumeConfig{}.cells);
      const int levels = c ? c->flow.fv.time_levels : 1;  // fine cells weigh their updates
      const std::vector<int> weights =
          levels > 1 ? size_weights(cells, levels) : std::vector<int>{};
      const std::vector<int> part = partition_cells(cells, *parts, weights);
      text += format_partition(summarize_partition(cells, part, *parts, weights), *parts);
    }
    print_result(text);
  });
}

}  // namespace flotsam::cli
