#include "ensemble/member_runner.hpp"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <exception>
#include <fstream>

#include "core/error.hpp"
#include "coupling/simulation.hpp"
#include "ensemble/blocking_monitor.hpp"
#include "io/case_file.hpp"

namespace flotsam {

namespace {

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw_run_error("could not write '{}'", path.string());
}

/// Steps the member's run to its end, sampling the statistics at the first step past each
/// multiple of the sample interval, at the start and at the end.
void simulate(Simulation& simulation, BlockingMonitor& monitor, double sample_interval,
              MemberResult& result) {
  simulation.initialize();
  monitor.note_new_bodies(simulation.bodies());
  monitor.sample(simulation.time(), simulation.jam_statistics(), simulation.bodies(),
                 simulation.backwater_rise());
  const double eps = 1e-9 * simulation.run_case().time.step;  // [s]
  while (!simulation.done()) {
    const double t0 = simulation.time();
    simulation.step();
    monitor.note_new_bodies(simulation.bodies());
    const double t1 = simulation.time();
    if (std::floor((t1 + eps) / sample_interval) > std::floor((t0 + eps) / sample_interval) ||
        simulation.done())
      monitor.sample(t1, simulation.jam_statistics(), simulation.bodies(),
                     simulation.backwater_rise());
  }
  simulation.write_final_output();
  monitor.finish(simulation.jam_statistics(), simulation.bodies(), result);
}

}  // namespace

MemberResult run_member(const MemberRun& run, const MemberSetup& setup) {
  const auto start = std::chrono::steady_clock::now();
  if (setup.threads > 0) omp_set_num_threads(setup.threads);
  MemberResult result;
  result.inputs = run.inputs;
  try {
    write_text(run.case_path, run.case_text);
    Case member_case = parse_case(run.case_text, run.case_path.string());
    const bool has_bodies =
        !member_case.bodies.bodies.empty() || !member_case.bodies.releases.empty();
    if (!has_bodies) throw_input_error("{}: the member has no bodies", run.case_path.string());
    const RunOptions options{.output_directory = run.folder,
                             .overwrite = true,
                             .write_output = true,
                             .progress = false,
                             .shared_flow = setup.shared_flow};
    Simulation simulation(std::move(member_case), *setup.mesh, options);
    BlockingMonitor monitor(*setup.geometry, setup.criterion);
    simulate(simulation, monitor, setup.criterion.sample_interval, result);
    // The bodies' time holds their contacts' (resolved inside the bodies' sub-steps).
    for (const Stage stage : {Stage::flow, Stage::bodies, Stage::reaction, Stage::diagnostics})
      result.step_seconds += simulation.timer().seconds(stage);
  } catch (const std::exception& e) {
    result = MemberResult{};
    result.inputs = run.inputs;
    result.failed = true;
    result.message = e.what();
  }
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  try {
    std::filesystem::create_directories(run.folder);
    write_member_result(run.folder, result);
  } catch (const std::exception& e) {
    result.failed = true;
    result.message = e.what();
  }
  return result;
}

}  // namespace flotsam
