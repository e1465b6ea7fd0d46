// flotsam run CASE.yaml: mesh the case, run it, write results for ParaView and CSV tables, and
// print the end-of-run summary.
#include <fmt/core.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "cli/commands.hpp"
#include "cli/logging.hpp"
#include "core/error.hpp"
#include "coupling/mesh_setup.hpp"
#include "coupling/simulation.hpp"
#include "ensemble/rank_world.hpp"
#include "io/case_estimate.hpp"
#include "io/case_file.hpp"
#include "mesh/mesh_generator.hpp"

namespace flotsam::cli {
namespace {

// Under `mpirun -n N` (N > 1) the flood is split over the ranks (finite volumes,
// flow/fv/rank_split.hpp): each advances its part of the cells, rank 0 writes and reports. An
// error on one rank stops them all (the others would wait for it).
// Each rank meshes the case itself; the parts assume the same mesh on every rank, checked.
void run_case(const std::string& case_file, const RunOptions& base, double end,
              const RankWorld* world = nullptr) {
  Case c = read_case(case_file);
  if (end > 0) c.time.end = end;
  const RunEstimate estimate = estimate_run(c);  // before meshing, which can take long
  check_estimate(c, estimate);
  if (is_large(estimate) && base.rank == 0)
    print_error(fmt::format("flotsam: a large run: {}\n", describe_estimate(estimate)));
  Mesh mesh = generate_mesh(c.mesh);
  if (world && world->size() > 1) {
    const std::vector<std::string> sums = world->gather(mesh_checksum(mesh));
    const bool same = std::all_of(sums.begin(), sums.end(),
                                  [&](const std::string& x) { return x == sums.front(); });
    if (world->broadcast(same ? "same" : "differ") != "same")
      throw_run_error(
          "{}: the ranks meshed the case differently (mesh checksums differ), so its cells "
          "cannot be split over them; write the mesh once (flotsam mesh {} -o case.msh) and "
          "give the file as mesh.file",
          case_file, case_file);
  }
  Simulation simulation(std::move(c), std::move(mesh), base);
  simulation.run();
  if (base.rank == 0) print_result(simulation.summary());
}

}  // namespace

void add_run_command(CLI::App& app) {
  struct Options {
    std::string case_file, output;
    bool overwrite = false, quiet = false, restart = false, accept_output_changes = false,
         fixed_threads = false;
    double end = -1.0;
  };
  auto options = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "run",
      "Run a case: the flow, and the bodies with their contacts when the case has any.\n"
      "Results go to <output.directory>/<name>/ (open <name>.pvd in ParaView).\n"
      "Example: flotsam run examples/bridge_piers.yaml");
  cmd->add_option("case", options->case_file, "case file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", options->output,
                  "output folder (default: <output.directory>/<name> from the case)");
  cmd->add_flag("--overwrite", options->overwrite,
                "replace the results of an earlier run in the output folder");
  cmd->add_option("--end", options->end, "end time [s], instead of the case's time.end")
      ->check(CLI::Validator(
          [](std::string& text) {  // CLI::PositiveNumber lets "nan" through
            const double t = std::strtod(text.c_str(), nullptr);
            return std::isfinite(t) && t > 0.0 ? std::string()
                                               : "expected a finite time > 0 [s], got " + text;
          },
          "TIME > 0"));
  cmd->add_flag("-q,--quiet", options->quiet, "no progress line");
  cmd->add_flag("--restart", options->restart,
                "continue the run in the output folder from its last output (checkpoint.bin); "
                "with --end, to a later end time")
      ->excludes("--overwrite");
  cmd->add_flag("--accept-output-changes", options->accept_output_changes,
                "with --restart: continue although output.interval, output.probe_interval, "
                "output.rasters or output.wet_depth changed (any other change is refused)")
      ->needs("--restart");
  cmd->add_flag("--fixed-threads", options->fixed_threads,
                "every step on all the threads (OMP_NUM_THREADS, else every core), even where "
                "fewer would be faster on a shared machine (by default each step takes the "
                "count measured fastest)");
  cmd->callback([options] {
    RunOptions run{.output_directory = options->output,
                   .overwrite = options->overwrite,
                   .write_output = true,
                   .progress = !options->quiet,
                   .restart = options->restart,
                   .accept_output_changes = options->accept_output_changes,
                   .adapt_threads = !options->fixed_threads};
    if (!RankWorld::launched_by_mpirun()) return run_case(options->case_file, run, options->end);
    const RankWorld world;
    run.rank = world.rank(), run.ranks = world.size();
    run.write_output = world.rank() == 0;
    run.progress = run.progress && world.rank() == 0;
    if (world.size() == 1) return run_case(options->case_file, run, options->end);
    // The ranks compute the same and would say the same: rank 0 speaks for all (errors excepted).
    if (world.rank() != 0) spdlog::default_logger()->set_level(spdlog::level::err);
    try {
      run_case(options->case_file, run, options->end, &world);
    } catch (const std::exception& e) {
      print_error(
          fmt::format("flotsam: rank {} of {}: {}\n", world.rank(), world.size(), e.what()));
      world.abort(1);
    }
  });
}

}  // namespace flotsam::cli
