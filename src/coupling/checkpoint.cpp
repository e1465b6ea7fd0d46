// Simulation checkpoints: everything a run needs to continue bit for bit from an output time
// (`flotsam run --restart`), written at every output (an ensemble's member: not at its start,
// RunOptions::rerun_whole) as <output folder>/checkpoint.bin, a binary
// archive of named arrays (io/binary_archive.hpp: each record with its length and checksum):
//
//   run       the case's settings (io/case_digest.hpp) and the mesh's checksum, then time, step
//             count, next output time, RKF45 totals, the times of the outputs
//   flow      the engine's own records (FlowEngine::save: FEM: state (time, eta, u, v) and the
//             state a step before; finite volumes: h, hu, hv per cell and the sub-step totals)
//             and its water balance; the same for the reference flow
//   bodies    every per-body array (BodySet::for_each_array), outflow count, next id
//   release   the random streams and counts of the release lines
//   contacts  last contacts (warm start) and the sweep order
//
// A restart first compares the settings with the case it is given (check_restart_case), then
// reads the state and checks that it is physical (check_restored_state): a damaged checkpoint
// is an error naming it, never blamed on the case.
//
// What is not kept is rebuilt the same way: the mesh and the flow's matrices from the case, the
// bodies' reaction on the flow and the debris under them from the bodies
// (Simulation::hand_bodies_to_flow).
#include <spdlog/spdlog.h>

#include <cmath>

#include "contact/impulse_solver.hpp"
#include "coupling/mesh_setup.hpp"
#include "coupling/simulation.hpp"
#include "io/binary_archive.hpp"
#include "io/case_digest.hpp"

namespace flotsam {

// Structs are archived field by field (no padding bytes). A new member must be added here: the
// size checks below fail to remind whoever changes the struct.
template <>
struct archive_fields<ContactPointConstraint> {
  using C = ContactPointConstraint;
  static constexpr auto fields = std::make_tuple(
      &C::r_a, &C::r_b, &C::normal_mass, &C::tangent_mass, &C::normal_impulse, &C::tangent_impulse,
      &C::approach_velocity, &C::target_velocity, &C::separation, &C::first_impulse,
      &C::last_impulse, &C::local_incident, &C::feature, &C::resting);
};
static_assert(sizeof(ContactPointConstraint) == 160, "list the new member in archive_fields");

template <>
struct archive_fields<ContactConstraint> {
  using C = ContactConstraint;
  static constexpr auto fields =
      std::make_tuple(&C::a, &C::b, &C::segment, &C::normal, &C::point_count, &C::points,
                      &C::friction, &C::slop, &C::width, &C::use_block, &C::K, &C::normal_mass,
                      &C::reference_on_a, &C::local_normal, &C::local_plane_point);
  static_assert(sizeof(ContactConstraint) == 512, "list the new member in archive_fields");
};

template <>
struct archive_fields<IntegrationStats> {
  using S = IntegrationStats;
  static constexpr auto fields =
      std::make_tuple(&S::accepted, &S::rejected, &S::contact_intervals, &S::grouped, &S::linked);
};
static_assert(sizeof(IntegrationStats) == 32, "list the new member in archive_fields");

std::vector<CaseSetting> Simulation::run_settings() const {
  if (mesh_checksum_.empty())  // once: the mesh never changes (or the ensemble's, the same)
    mesh_checksum_ =
        options_.mesh_setup ? options_.mesh_setup->mesh_checksum : mesh_checksum(mesh_);
  std::vector<CaseSetting> settings = case_.settings;
  settings.push_back({"the mesh (its nodes, elements and groups)", mesh_checksum_});
  return settings;
}

void Simulation::write_checkpoint(const std::string& path) const {
  ArchiveWriter w(path);
  w.write_text("run.case", format_settings(run_settings()));
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

bool Simulation::check_restart_case(const std::string& path) const {
  ArchiveReader r(path);
  const auto changes = compare_settings(parse_settings(r.read_text("run.case")), run_settings());
  std::vector<SettingChange> run_changes, output_changes;
  for (const SettingChange& c : changes)
    (c.kind == SettingKind::output ? output_changes : run_changes).push_back(c);
  const std::string case_name = case_.file.empty() ? "the case" : "'" + case_.file + "'";
  if (!run_changes.empty())
    throw_input_error(
        "cannot restart from '{}': {} differs from the case the run started with:{}\n"
        "A restart continues the same run: put these values back, or run the case afresh "
        "(without --restart, with --overwrite). Only time.end (or --end) may change, and the "
        "output settings with --accept-output-changes.",
        path, case_name, describe_changes(run_changes));
  if (!output_changes.empty() && !options_.accept_output_changes)
    throw_input_error(
        "cannot restart from '{}': the output settings of {} differ from those the run started "
        "with:{}\nPass --accept-output-changes to continue with the new ones, or put them back.",
        path, case_name, describe_changes(output_changes));
  if (output_changes.empty()) return false;
  spdlog::warn("restart: continuing with changed output settings:{}",
               describe_changes(output_changes));
  return true;
}

void Simulation::read_checkpoint(const std::string& path) {
  ArchiveReader r(path);
  r.read_text("run.case");  // checked by check_restart_case
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
  r.finish();
  check_restored_state(path, output_times);
  open_output(&output_times);
}

// What a damaged checkpoint shows that its checksums cannot (a file written by a broken run, or
// edited with its checksums recomputed): non-finite numbers, and bodies far from the domain.
void Simulation::check_restored_state(const std::string& path,
                                      const std::vector<double>& output_times) const {
  const auto damaged = [&](const std::string& what) {
    throw_input_error(
        "'{}': {}; the checkpoint is damaged or comes from another run: run the case afresh "
        "(without --restart, with --overwrite)",
        path, what);
  };
  if (!std::isfinite(time_) || !std::isfinite(next_output_) || step_count_ < 0)
    damaged(fmt::format("the time {} s (step {}, next output {} s) is not a time", time_,
                        step_count_, next_output_));
  for (const double t : output_times)
    if (!(t <= time_))
      damaged(fmt::format("an output time {} s lies after the time {} s", t, time_));
  const auto check_field = [&](const char* name, const std::vector<double>& values) {
    for (std::size_t k = 0; k < values.size(); ++k)
      if (!std::isfinite(values[k]))
        damaged(fmt::format("the flow's {} is {} at node {}", name, values[k], k));
  };
  check_field("eta", flow_->eta());
  check_field("u", flow_->u());
  check_field("v", flow_->v());
  if (!has_bodies_) return;
  Vec2 lo = mesh_.nodes.front(), hi = lo;
  for (const Vec2& p : mesh_.nodes) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  for (int i = 0; i < bodies_.size(); ++i) {
    if (bodies_.state[i] == BodyState::gone) continue;
    const Vec2 x = bodies_.position[i], u = bodies_.velocity[i];
    const double reach = bodies_.length[i];  // [m] a body's centre stays this close
    if (!x.allFinite() || !u.allFinite() || !std::isfinite(bodies_.angle[i]) ||
        !std::isfinite(bodies_.angular_velocity[i]) || !(reach > 0.0))
      damaged(fmt::format(
          "body {} has position ({}, {}) m, velocity ({}, {}) m/s, angle {} rad, length {} m",
          bodies_.id[i], x.x(), x.y(), u.x(), u.y(), bodies_.angle[i], reach));
    if ((x.array() < lo.array() - reach).any() || (x.array() > hi.array() + reach).any())
      damaged(fmt::format("body {} at ({}, {}) m lies far outside the domain [{}, {}] x [{}, {}] m",
                          bodies_.id[i], x.x(), x.y(), lo.x(), hi.x(), lo.y(), hi.y()));
  }
}

}  // namespace flotsam
