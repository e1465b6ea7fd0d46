// flotsam ensemble CASE.yaml: run the case many times over drawn inputs (its `ensemble:`
// section), on --jobs threads and on the ranks of `mpirun -n K`, and print the blocking
// probabilities and the distributions (src/ensemble/ensemble_runner.hpp).
#include <fmt/core.h>

#include <algorithm>

#include "cli/commands.hpp"
#include "cli/logging.hpp"
#include "ensemble/ensemble_runner.hpp"

namespace flotsam::cli {

void add_ensemble_command(CLI::App& app) {
  auto options = std::make_shared<EnsembleOptions>();
  auto quiet = std::make_shared<bool>(false);
  auto no_pictures = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand(
      "ensemble",
      "Run an ensemble: the case's members over drawn inputs (its `ensemble:` section), with\n"
      "the blocking probability of each bridge and gap, backwater rise, travel distances.\n"
      "Results go to <output.directory>/<name>/; run again on the same folder to resume.\n"
      "On several machines: mpirun -n K flotsam ensemble CASE.yaml\n"
      "Example: flotsam ensemble examples/bridge_blocking.yaml --jobs 2");
  cmd->add_option("case", options->case_file, "case file (YAML) with an ensemble section")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", options->output,
                  "output folder (default: <output.directory>/<name> from the case)");
  cmd->add_option("--members", options->members,
                  "members per sweep value, instead of ensemble.members")
      ->check(CLI::PositiveNumber);
  cmd->add_option("-j,--jobs", options->jobs, "members run at once on this machine (default 1)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--overwrite", options->overwrite,
                "replace an earlier ensemble in the output folder instead of resuming it");
  cmd->add_flag("-q,--quiet", *quiet, "no progress line");
  cmd->add_flag("--no-pictures", *no_pictures, "no PNG pictures");
  // Each member runs on one rank; one flood over several ranks is `mpirun -n N flotsam run`.
  auto ranks_per_member = std::make_shared<int>(1);
  cmd->add_option("--ranks-per-member", *ranks_per_member,
                  "MPI ranks each member spans: 1 (members split over ranks are not supported)")
      ->check(CLI::Validator(
          [](std::string& text) {
            return text == "1" ? std::string()
                               : "each member runs on one rank (got " + text +
                                     "): members split over ranks are not supported; an "
                                     "ensemble deals its members to the ranks of mpirun -n K, "
                                     "and one flood splits over ranks with mpirun -n N flotsam run";
          },
          "1"));
  auto no_shared_flow = std::make_shared<bool>(false);
  cmd->add_flag("--no-shared-flow", *no_shared_flow,
                "each member computes its own flow even in one-way and frozen cases (the "
                "results are the same, bit for bit; for checks)");
  cmd->callback([options, quiet, no_pictures, no_shared_flow] {
    options->progress = !*quiet;
    options->share_flow = !*no_shared_flow;
    options->pictures = !*no_pictures;
    const RankWorld world;
    const EnsembleReport report = run_ensemble(*options, world);
    if (world.rank() != 0) return;
    std::string text = report.summary;
    text += fmt::format(
        "rank 0           ran {} members, kept {} from an earlier run ({} rank(s) x {} "
        "job(s))\n",
        report.ran, report.kept, world.size(), options->jobs);
    if (report.ran > 0)
      text += fmt::format(
          "members          {:.3f} s each on rank 0, of which {:.1f} % set-up and output (the "
          "rest in their steps)\n",
          report.member_seconds / report.ran,
          100.0 * (1.0 - report.step_seconds / std::max(report.member_seconds, 1e-300)));
    text += fmt::format("flow             {}{}\n", report.flow_sharing,
                        report.flow_shared ? fmt::format(", {:.2f} s", report.flow_seconds) : "");
    text += fmt::format("wall time        {:.2f} s\n", report.wall_seconds);
    text += fmt::format("results in       {}\n", report.directory.string());
    print_result(text);
  });
}

}  // namespace flotsam::cli
