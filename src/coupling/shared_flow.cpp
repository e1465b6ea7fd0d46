#include "coupling/shared_flow.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <system_error>

#include "core/error.hpp"
#include "coupling/flow_engines.hpp"

namespace flotsam {

namespace {

std::string step_prefix(long k) {
  return std::to_string(k);
}

}  // namespace

std::filesystem::path shared_fields_folder(const std::filesystem::path& flow_file) {
  return flow_file.string() + ".fields";
}

void remove_shared_flow(const std::filesystem::path& flow_file) {
  std::error_code ignored;
  std::filesystem::remove(flow_file, ignored);
  std::filesystem::remove_all(shared_fields_folder(flow_file), ignored);
}

bool flow_can_be_shared(const Case& run_case) {
  return run_case.time.mode == CouplingMode::one_way || run_case.time.mode == CouplingMode::frozen;
}

// The steps and output times of Simulation::step and Simulation::write_output_if_due: steps of
// time.step ending at time.end; an output at the start and at the first step at or past each
// multiple of output.interval after it, and at the end.
void record_shared_flow(const Case& run_case, const Mesh& mesh, const std::string& path,
                        bool with_output) {
  if (!flow_can_be_shared(run_case))
    throw_run_error("a two-way run's flow depends on its bodies and cannot be shared");
  const TimeConfig& time = run_case.time;
  const std::filesystem::path fields = shared_fields_folder(path);
  std::error_code error;
  std::filesystem::remove_all(fields, error);  // files shared by an earlier recording
  std::unique_ptr<FlowEngine> flow = make_flow_engine(mesh, run_case);
  flow->initialize();
  ArchiveWriter w(path);
  auto finish = [&] {  // the folder of shared files, once the flow is recorded
    w.close();
    std::filesystem::create_directories(fields, error);
    if (error)
      throw_run_error("cannot create the folder '{}': {}", fields.string(), error.message());
  };
  w.write_value("shared.mode", static_cast<int>(time.mode));
  w.write_value("shared.step", time.step);
  w.write_value("shared.end", time.end);
  w.write_value("shared.output", static_cast<int>(with_output));
  if (time.mode == CouplingMode::frozen) {
    flow->settle(time);
    flow->save(w, "settled");
    finish();
    return;
  }
  const double eps = 1e-9 * time.step;  // [s]
  double t = flow->time(), next_output = t;
  auto output_if_due = [&] {
    if (!with_output || t < next_output - eps) return;
    flow->after_checkpoint();
    while (next_output <= t + eps) next_output += run_case.output.interval;
  };
  output_if_due();
  for (long k = 0; t < time.end - eps; ++k) {
    const double t1 = std::min(t + time.step, time.end);
    flow->step(t1 - flow->time());
    t = t1;
    flow->save(w, step_prefix(k));
    output_if_due();
  }
  finish();
}

SharedFlowReplay::SharedFlowReplay(const std::string& path, const Case& run_case, bool with_output)
    : reader_(path), dt_(run_case.time.step) {
  const auto mode = static_cast<CouplingMode>(reader_.read_value<int>("shared.mode"));
  const double step = reader_.read_value<double>("shared.step");
  const double end = reader_.read_value<double>("shared.end");
  const bool output = reader_.read_value<int>("shared.output") != 0;
  if (mode != run_case.time.mode || step != run_case.time.step || end != run_case.time.end ||
      output != with_output)
    throw_run_error(
        "the shared flow '{}' was recorded for other times or another mode than the run of '{}'",
        path, run_case.file);
}

void SharedFlowReplay::settle(FlowEngine& flow) {
  flow.restore(reader_, "settled");
}

void SharedFlowReplay::step(FlowEngine& flow, double t1) {
  flow.restore_step(reader_, step_prefix(next_++));
  if (std::abs(flow.time() - t1) > 1e-9 * dt_)
    throw_run_error("the shared flow '{}' is at t = {} s where the run is at t = {} s",
                    reader_.path(), flow.time(), t1);
}

}  // namespace flotsam
