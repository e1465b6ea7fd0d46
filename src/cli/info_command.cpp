// flotsam info FILE: what a mesh holds (nodes, elements, boundary groups with their lengths,
// element sizes and quality). FILE is a Gmsh .msh file or a case file (its mesh is generated);
// for a finite-volume case also the time levels the run will take (flow/fv/time_levels.hpp).
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
#include "io/vtu_writer.hpp"
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
  struct Options {
    std::string path, parts_vtu;
    int parts = 0;
    bool overwrite = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "info",
      "Print what a mesh holds: nodes, elements, boundary groups with their lengths, element\n"
      "sizes and quality. FILE is a Gmsh .msh file, or a case file whose mesh is generated.\n"
      "Example: flotsam info out/bridge.msh");
  cmd->add_option("file", options->path, "mesh (.msh) or case file (.yaml)")
      ->required()
      ->check(CLI::ExistingFile);
  CLI::Option* parts_option =
      cmd->add_option("--parts", options->parts,
                      "also split the finite-volume cells into N parts, as N MPI ranks would take\n"
                      "them, and print their cells, halos and neighbours")
          ->check(CLI::Range(1, 1 << 20));
  cmd->add_option("--parts-vtu", options->parts_vtu,
                  "with --parts: also write the cells with their part (0 .. N-1, cell data\n"
                  "'part') for ParaView (.vtu)")
      ->needs(parts_option);
  cmd->add_flag("--overwrite", options->overwrite, "replace the --parts-vtu file if it exists");
  cmd->callback([options] {
    if (!options->parts_vtu.empty()) check_can_write(options->parts_vtu, options->overwrite);
    // The case's mesh and cells, or a .msh file's with the default cells.
    const std::optional<Case> c =
        is_case_file(options->path) ? std::optional<Case>(read_case(options->path)) : std::nullopt;
    const Mesh mesh = c ? generate_mesh(c->mesh) : read_msh(options->path);
    std::string text = format_mesh_summary(summarize_mesh(mesh));
    const bool finite_volumes = c && c->flow.engine == FlowEngineKind::fv;
    if (!finite_volumes && options->parts == 0) return print_result(text);
    const FiniteVolumeConfig fv = c ? c->flow.fv : FiniteVolumeConfig{};
    const CellMesh cells = build_cell_mesh(mesh, fv.cells);
    const int levels = finite_volumes ? choose_time_levels(cells, fv.time_levels) : 1;
    if (finite_volumes)
      text += fmt::format(
          "time levels    {}{} ({:.2f}x fewer cell updates with {} than with one, by the cells' "
          "sizes)\n",
          levels, fv.time_levels == 0 ? " (auto)" : "", size_gain(cells, auto_levels), auto_levels);
    if (const int parts = options->parts; parts > 0) {
      const std::vector<int> weights = size_weights(cells, levels);  // each cell's updates
      const std::vector<int> part = partition_cells(cells, parts, weights);
      text += format_partition(summarize_partition(cells, part, parts, weights), parts);
      if (!options->parts_vtu.empty()) {
        const std::vector<double> value(part.begin(), part.end());
        VtuFields fields;
        fields.add_cell_scalar("part", value);
        write_vtu(options->parts_vtu, mesh, fields, 0.0,
                  cells.kind == FvCells::split ? VtuCells::split : VtuCells::quadratic);
        text += fmt::format("  written to     {}\n", options->parts_vtu);
      }
    }
    print_result(text);
  });
}

}  // namespace flotsam::cli
