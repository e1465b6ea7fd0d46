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
/// multiple of the sample interval, at the start and at the end. result.step_seconds: the wall
/// time of the steps (all their stages, without the outputs they write) and of the samples.
void simulate(Simulation& simulation, BlockingMonitor& monitor, double sample_interval,
              MemberResult& result) {
  using clock = std::chrono::steady_clock;
  const auto seconds_since = [](clock::time_point start) {
    return std::chrono::duration<double>(clock::now() - start).count();
  };
  simulation.initialize();
  auto start = clock::now();
  monitor.note_new_bodies(simulation.bodies());
  monitor.sample(simulation.time(), simulation.jam_statistics(), simulation.bodies(),
                 simulation.backwater_rise());
  result.step_seconds += seconds_since(start);
  const double eps = 1e-9 * simulation.run_case().time.step;  // [s]
  while (!simulation.done()) {
    const double t0 = simulation.time();
    const double output_before = simulation.timer().seconds(Stage::output);
    start = clock::now();
    simulation.step();
    monitor.note_new_bodies(simulation.bodies());
    const double t1 = simulation.time();
    if (std::floor((t1 + eps) / sample_interval) > std::floor((t0 + eps) / sample_interval) ||
        simulation.done())
      monitor.sample(t1, simulation.jam_statistics(), simulation.bodies(),
                     simulation.backwater_rise());
    result.step_seconds +=
        seconds_since(start) - (simulation.timer().seconds(Stage::output) - output_before);
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
                             .shared_flow = setup.shared_flow,
                             .mesh_setup = setup.mesh_setup,
                             .rerun_whole = true,
                             .adapt_threads = true};
    Simulation simulation(std::move(member_case), *setup.mesh, options);
    BlockingMonitor monitor(*setup.geometry, setup.criterion);
    simulate(simulation, monitor, setup.criterion.sample_interval, result);
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
  // The ensemble's count of set-up and output includes member.txt (the file holds the time
  // before it was written).
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace flotsam
