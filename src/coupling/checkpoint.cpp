// Simulation checkpoints: everything a run needs to continue bit for bit from an output time
// (`flotsam run --restart`), written at every output as <output folder>/checkpoint.bin, a binary
// archive of named arrays (io/binary_archive.hpp):
//
//   run       time, step count, next output time, RKF45 totals, the times of the outputs
//   flow      the engine's own records (FlowEngine::save: FEM: state (time, eta, u, v) and the
//             state a step before; finite volumes: h, hu, hv per cell and the sub-step totals)
//             and its water balance; the same for the reference flow
//   bodies    every per-body array (BodySet::for_each_array), outflow count, next id
//   release   the random streams and counts of the release lines
//   contacts  last contacts (warm start) and the sweep order
//
// What is not kept is rebuilt the same way: the mesh and the flow's matrices from the case, the
// bodies' reaction on the flow from the bodies (Simulation::apply_reaction).
#include "contact/impulse_solver.hpp"
#include "coupling/simulation.hpp"
#include "io/binary_archive.hpp"

namespace flotsam {

template <>
struct is_plain_struct<ContactConstraint> : std::true_type {};

void Simulation::write_checkpoint(const std::string& path) const {
  ArchiveWriter w(path);
  w.write_value("run.time", time_);
  w.write_value("run.step_count", step_count_);
  w.write_value("run.next_output", next_output_);
  w.write_value("run.rkf45", integration_totals_);
  w.write("run.output_times", output_ ? output_->times() : std::vector<double>{});
  flow_->save(w, "flow");
  if (reference_flow_) reference_flow_->save(w, "reference_flow");
  if (has_bodies_) {
    BodySet& bodies = const_cast<BodySet&>(bodies_);  // for_each_array only reads here
    w.write_value("bodies.count", bodies.size());
    w.write_value("bodies.outflow_count", bodies.outflow_count);
    w.write_value("bodies.next_id", bodies.next_id);
    bodies.for_each_array(
        [&](const char* name, auto& array) { w.write(std::string("bodies.") + name, array); });
    w.write_text("release.state", releaser_->save_state());
    w.write("contacts.last", contacts_->contacts());
    w.write("contacts.sweep_order", contacts_->sweep().order());
    w.write_value("contacts.sweep_axis", contacts_->sweep().axis());
  }
  w.close();
}

void Simulation::read_checkpoint(const std::string& path) {
  ArchiveReader r(path);
  time_ = r.read_value<double>("run.time");
  step_count_ = r.read_value<long>("run.step_count");
  next_output_ = r.read_value<double>("run.next_output");
  integration_totals_ = r.read_value<IntegrationStats>("run.rkf45");
  const auto output_times = r.read<double>("run.output_times");
  flow_->restore(r, "flow");
  if (reference_flow_) reference_flow_->restore(r, "reference_flow");
  if (has_bodies_) {
    const int count = r.read_value<int>("bodies.count");
    bodies_.outflow_count = r.read_value<long>("bodies.outflow_count");
    bodies_.next_id = r.read_value<long>("bodies.next_id");
    bodies_.for_each_array([&](const char* name, auto& array) {
      using T = typename std::decay_t<decltype(array)>::value_type;
      array = r.read<T>(std::string("bodies.") + name);
      if (static_cast<int>(array.size()) != count)
        throw_input_error("{}: bodies.{} holds {} values for {} bodies", path, name, array.size(),
                          count);
    });
    releaser_->restore_state(r.read_text("release.state"));
    auto last = r.read<ContactConstraint>("contacts.last");
    auto order = r.read<int>("contacts.sweep_order");
    contacts_->restore(std::move(last), std::move(order), r.read_value<int>("contacts.sweep_axis"));
  }
  if (options_.write_output)
    output_ = std::make_unique<RunOutput>(output_directory(), case_.name, mesh_, run_layout(),
                                          output_times, has_bodies_);
}

}  // namespace flotsam
