#include "coupling/simulation.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>

#include "bodies/outflow.hpp"
#include "bridges/deck_contact.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"
#include "coupling/flow_engines.hpp"
#include "coupling/jam_extent.hpp"
#include "coupling/placement_overlap.hpp"
#include "coupling/progress.hpp"
#include "io/case_file.hpp"

namespace flotsam {

Simulation::Simulation(Case run_case, Mesh mesh, RunOptions options)
    : case_(std::move(run_case)), mesh_(std::move(mesh)), options_(std::move(options)) {
  has_bodies_ = !case_.bodies.bodies.empty() || !case_.bodies.releases.empty();
}

void Simulation::initialize() {
  check_case_against_mesh(case_, mesh_.group_names);
  if (options_.adapt_threads) threads_.emplace(omp_get_max_threads());
  bool output_changed = false;
  const std::filesystem::path checkpoint =
      options_.restart ? restart_checkpoint(output_changed) : "";
  flow_ = make_flow_engine(mesh_, case_, options_.mesh_setup.get(), options_.rank, options_.ranks);
  flow_->initialize();
  if (!options_.shared_flow.empty()) {
    if (options_.restart || !flow_can_be_shared(case_))
      throw_run_error("{}: a shared flow serves one-way and frozen runs from their start only",
                      case_.file);
    shared_flow_ = std::make_unique<SharedFlowReplay>(options_.shared_flow.string(), case_,
                                                      options_.write_output);
  }
  if (case_.time.mode == CouplingMode::frozen && shared_flow_)
    shared_flow_->settle(*flow_);
  else if (case_.time.mode == CouplingMode::frozen)
    flow_->settle(case_.time);
  time_ = flow_->time();

  for (const auto& bc : case_.flow.boundaries) {
    const bool open = bc.kind == BoundaryCondition::Kind::elevation ||
                      bc.kind == BoundaryCondition::Kind::discharge ||
                      bc.kind == BoundaryCondition::Kind::free;
    const int g = mesh_.find_group(bc.group);
    if (open && g >= 0 &&
        std::find(outflow_groups_.begin(), outflow_groups_.end(), g) == outflow_groups_.end())
      outflow_groups_.push_back(g);
  }
  // The bridges stand on the mesh, with or without bodies (a deck shapes the flow either way).
  std::vector<int> solids;  // the wall groups
  if (has_bodies_ || !case_.bridges.empty()) {
    solids = solid_group_indices(mesh_, case_.flow.boundaries);
    jam_geometry_ = jam_geometry_for(case_.mesh, mesh_, solids, case_.bridges);
  }
  if (has_bodies_) {
    bodies_.water_density = case_.flow.water_density;
    const PlacementCheck check{case_.file};
    if (!options_.restart) {  // a restart takes its bodies from the checkpoint
      add_explicit_bodies(bodies_, case_.bodies.bodies, flow_->field(), time_, check);
      const double allowed = 0.01;  // [m] touching bodies are not worth a word
      if (const auto overlaps = placement_overlaps(bodies_, allowed); !overlaps.empty())
        spdlog::warn("{}", describe_overlaps(bodies_, overlaps, case_.file));
    }
    releaser_ = std::make_unique<Releaser>(case_.bodies.releases, check);
    releaser_->check_inside(flow_->field(), time_);
    integrator_ =
        std::make_unique<BodyIntegrator>(make_force_model(case_.bodies.physics, case_.flow));
    contacts_ = std::make_unique<ContactWorld>(case_.bodies.contact,
                                               case_.bodies.physics.added_mass_coefficient);
    walls_ = extract_boundary_segments(mesh_, solids);
    add_deck_faces(walls_, jam_geometry_.bridges, jam_geometry_.group_names);
    has_decks_ = !walls_.band_lower.empty();
    if (case_.output.backwater && case_.time.mode == CouplingMode::two_way &&
        !jam_geometry_.bridges.empty()) {
      reference_flow_ =
          make_flow_engine(mesh_, case_, options_.mesh_setup.get(), options_.rank, options_.ranks);
      reference_flow_->initialize();
      backwater_probe_ = std::make_unique<BackwaterProbe>(mesh_, jam_geometry_);
    }
  }
  check_decks_stand_above_the_bed();
  check_probes_inside(case_.output.probes, flow_->field(), case_.file);  // before any output
  if (case_.output.raster_resolution > 0.0) (void)envelope_grid();
  next_output_ = time_;
  if (options_.restart) {
    read_checkpoint(checkpoint.string());
    // The checkpoint's time was an output: a new interval counts from it.
    if (output_changed) next_output_ = time_ + case_.output.interval;
    if (has_bodies_) hand_bodies_to_flow();  // for the next flow step, as before the stop
    open_probes(CsvResume{time_});
    return;
  }
  open_output(nullptr);
  open_probes(std::nullopt);
  if (probes_) probes_->write(time_);
  write_output_if_due(false);
}

RunLayout Simulation::run_layout() const {
  RunLayout layout;
  layout.open_group.assign(mesh_.group_names.size(), 0);
  for (int g : outflow_groups_) layout.open_group[g] = 1;
  layout.rain = case_.flow.rain.enabled;
  layout.sources = !case_.flow.sources.empty();
  layout.formats = case_.output.formats;
  layout.crs_wkt = case_.crs_wkt;
  layout.time_origin = case_.time.origin;
  for (const Bridge& b : jam_geometry_.bridges) {
    if (!b.deck) continue;
    const Vec2 half = 0.5 * b.deck->width * b.downstream;  // [m]
    layout.decks.push_back({b.start - half, b.end - half, b.end + half, b.start + half});
  }
  return layout;
}

void Simulation::open_probes(std::optional<CsvResume> resume) {
  if (!options_.write_output || case_.output.probes.empty()) return;
  probes_ =
      std::make_unique<ProbeWriter>((output_directory() / (case_.name + "_probes.csv")).string(),
                                    case_.output.probes, flow_->field(), case_.file, resume);
}

std::filesystem::path Simulation::restart_checkpoint(bool& output_changed) const {
  const auto checkpoint = output_directory() / "checkpoint.bin";
  if (!std::filesystem::exists(checkpoint))
    throw_input_error(
        "cannot restart: '{}' holds no checkpoint.bin (a run writes one at every output); "
        "run without --restart to start afresh",
        output_directory().string());
  output_changed = check_restart_case(checkpoint.string());
  // Files a stopped run was writing when it stopped (complete files were renamed).
  for (const auto& entry : std::filesystem::directory_iterator(output_directory()))
    if (entry.path().extension() == ".part") std::filesystem::remove(entry.path());
  return checkpoint;
}

std::filesystem::path Simulation::output_directory() const {
  return options_.output_directory.empty()
             ? std::filesystem::path(case_.output.directory) / case_.name
             : options_.output_directory;
}

bool Simulation::done() const {
  return time_ >= case_.time.end - 1e-9 * case_.time.step;
}

// The simulation step: the stages in order, each timed (docs/architecture.md); the computing
// ones on the thread count the governor chose.
void Simulation::step() {
  const double t0 = time_, t1 = std::min(time_ + case_.time.step, case_.time.end);
  on_chosen_threads([&] {
    advance_flow(t1);
    if (has_bodies_) {
      take_exchanged_forces();
      advance_bodies(t0, t1);
      hand_bodies_to_flow();
    }
  });
  time_ = t1;
  ++step_count_;
  check_diagnostics();
  write_output_if_due(false);
}

// `stages` on the governor's thread count, their wall time told to it (RunOptions::adapt_threads);
// else on the threads as they are.
void Simulation::on_chosen_threads(const std::function<void()>& stages) {
  if (!threads_) return stages();
  const ThreadCountScope scope(threads_->threads());
  const auto start = std::chrono::steady_clock::now();
  stages();
  threads_->record(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

void Simulation::advance_flow(double t1) {
  auto timed = timer_.time(Stage::flow);
  if (case_.time.mode == CouplingMode::frozen) return;  // the steady flow stays
  const double t0 = flow_->time();
  if (shared_flow_)
    shared_flow_->step(*flow_, t1);
  else
    flow_->step(t1 - t0);
  if (reference_flow_) reference_flow_->step(t1 - reference_flow_->time());
  // Gauges: every step, or at the first step past each multiple of output.probe_interval.
  const double every = case_.output.probe_interval, eps = 1e-9 * case_.time.step;
  if (probes_ && (every <= 0.0 || std::floor((t1 + eps) / every) > std::floor((t0 + eps) / every)))
    probes_->write(t1);
}

void Simulation::advance_bodies(double t0, double t1) {
  // The bodies' stage encloses the contacts' (printed as "bodies ... of which contacts ...").
  auto timed_bodies = timer_.time(Stage::bodies);
  releaser_->release(bodies_, flow_->field(), t0, t1);
  const std::vector<Vec2> start_velocity = bodies_.velocity;  // [m/s]
  if (has_decks_) {  // who passes under a deck, who stops, who floats over (deck_contact.hpp)
    BodyLevels levels = body_levels(bodies_, flow_->field(), t0);
    contacts_->set_body_levels(std::move(levels.bottom), std::move(levels.top));
  }
  // RKF45 sub-steps of every body; the bodies that may touch, in contact groups, with their
  // contacts resolved at the end of each of their contact intervals (body_integrator.hpp). The
  // contact solve moves bodies over the interval just integrated (ContactWorld::step).
  ContactSchedule schedule;
  {
    auto timed = timer_.time(Stage::contacts);
    schedule = contacts_->plan(bodies_, walls_, t1 - t0);
  }
  const ContactHook resolve_contacts = [this](const ContactInterval& interval, BodySet& bodies) {
    auto timed = timer_.time(Stage::contacts);
    contacts_->step(bodies, walls_, interval.length, interval.bodies, interval.lengths);
  };
  const IntegrationStats stats =
      integrator_->advance(bodies_, flow_->field(), t0, t1, schedule, resolve_contacts);
  integration_totals_.accepted += stats.accepted;
  integration_totals_.rejected += stats.rejected;
  integration_totals_.contact_intervals =
      std::max(integration_totals_.contact_intervals, stats.contact_intervals);

  if (case_.bodies.jams.vertical_extent == JamExtent::accumulation) {  // (M-J1), jam_extent.hpp
    const JamStatistics jams =
        compute_jam_statistics(bodies_, contacts_->report(walls_, bodies_.size()), jam_geometry_);
    set_wetted_heights(bodies_, jams, jam_geometry_, case_.bodies.jams);
  }
  for (int i = 0; i < bodies_.size(); ++i)  // contacts included
    bodies_.mean_acceleration[i] = (bodies_.velocity[i] - start_velocity[i]) / (t1 - t0);
  const OutflowResult out = remove_outflowing_bodies(bodies_, flow_->field(), t1, outflow_groups_);
  if (!out.stray.empty()) {
    const int i = out.stray.front();
    throw_run_error(
        "t = {:.3f} s: body {} is outside the domain at ({:.3f}, {:.3f}) m, through a wall; "
        "contacts should have stopped it (a smaller time.step may help)",
        t1, bodies_.id[i], bodies_.position[i].x(), bodies_.position[i].y());
  }
}

void Simulation::check_decks_stand_above_the_bed() const {
  for (std::size_t b = 0; b < jam_geometry_.bridges.size(); ++b) {
    const Bridge& bridge = jam_geometry_.bridges[b];
    if (!bridge.deck) continue;
    const double bed = lowest_bed_on_axis(bridge, flow_->field(), time_);  // [m]
    if (bridge.deck->top <= bed)
      throw_input_error(
          "{}: bridge '{}': its deck's top ({} m) is below the bed everywhere along its axis "
          "(the lowest bed there is {} m); give the deck's elevations in the terrain's datum",
          case_.bridges.at(b).origin, bridge.name, bridge.deck->top, bed);
  }
}

// What the flow's next step takes from the bodies: where they lie (the debris of the hazard
// rating, (M-H2)) and, two-way, their reaction.
void Simulation::hand_bodies_to_flow() {
  auto timed = timer_.time(Stage::reaction);
  std::vector<BodyFootprint> footprints;
  std::vector<BodyReaction> reactions;
  const bool two_way = case_.time.mode == CouplingMode::two_way;
  reaction_bodies_.clear();
  for (int i = 0; i < bodies_.size(); ++i) {
    if (bodies_.state[i] == BodyState::gone) continue;
    footprints.push_back({bodies_.position[i], bodies_.half_extents(i), bodies_.angle[i]});
    if (!two_way) continue;
    // Spec 5 step 3: the fluid gets -F_x, F_x = F_drag + C_a m_f (Du_f/Dt - du_p/dt), spread
    // over the footprint; it acts during the next flow step. du_p/dt is the body's mean
    // acceleration over the step, its contacts' included (a body held against a pier does not
    // accelerate), and the drag goes as its law, K and u_p (model.md "Two-way coupling").
    const Vec2 added =
        bodies_.added_mass[i] * (bodies_.fluid_acceleration[i] - bodies_.mean_acceleration[i]);
    reactions.push_back({footprints.back(), -added, bodies_.drag_rate[i], bodies_.velocity[i]});
    reaction_bodies_.push_back(i);
  }
  flow_->mark_debris(footprints);
  if (two_way) flow_->field().set_body_reactions(reactions);
}

// What the water exchanged with each body over the flow step just taken (Body::water_force).
void Simulation::take_exchanged_forces() {
  auto timed = timer_.time(Stage::reaction);
  const std::vector<Vec2> forces = flow_->field().exchanged_forces();
  for (std::size_t k = 0; k < forces.size() && k < reaction_bodies_.size(); ++k)
    bodies_.water_force[reaction_bodies_[k]] = forces[k];
}

void Simulation::check_diagnostics() {
  auto timed = timer_.time(Stage::diagnostics);
  // Every component of the state (a velocity goes bad a step before the position it moves).
  for (int i = 0; i < bodies_.size(); ++i) {
    const char* bad = !bodies_.position[i].allFinite()              ? "position"
                      : !std::isfinite(bodies_.angle[i])            ? "angle"
                      : !bodies_.velocity[i].allFinite()            ? "velocity"
                      : !std::isfinite(bodies_.angular_velocity[i]) ? "angular velocity"
                                                                    : nullptr;
    if (bad)
      throw_run_error("t = {:.3f} s: body {} has a non-finite {}", time_, bodies_.id[i], bad);
  }
}

void Simulation::write_output_if_due(bool force) {
  if (!force && time_ < next_output_ - 1e-9 * case_.time.step) return;
  if (!force) synchronize_flows();  // every rank of a flood split over ranks, at the same times
  while (next_output_ <= time_ + 1e-9 * case_.time.step) next_output_ += case_.output.interval;
  if (!output_) return;
  auto timed = timer_.time(Stage::output);
  std::vector<std::uint8_t> jammed;
  if (has_bodies_) {
    const JamStatistics jams = jam_statistics();
    jammed.assign(bodies_.size(), 0);
    for (const Jam& jam : jams.jams)
      for (int i : jam.bodies) jammed[i] = 1;
    output_->write_jams(time_, jams, jam_geometry_, backwater_rise(), reference_flow_ != nullptr,
                        bodies_);
  }
  output_->write(time_, *flow_, bodies_, has_bodies_, jammed);
  // A run rerun whole when interrupted has no use for a checkpoint of its start.
  if (!options_.rerun_whole || step_count_ > 0)
    write_checkpoint((output_->directory() / "checkpoint.bin").string());
  flow_->after_checkpoint();  // as a run restarted from this checkpoint does
  if (reference_flow_) reference_flow_->after_checkpoint();
}

void Simulation::open_output(const std::vector<double>* output_times) {
  if (!options_.write_output) return;
  std::vector<ProtectedInput> inputs;  // never deleted by --overwrite
  for (const InputFile& input : case_.input_files) inputs.emplace_back(input.key, input.path);
  output_ =
      output_times
          ? std::make_unique<RunOutput>(output_directory(), case_.name, mesh_, run_layout(),
                                        *output_times, has_bodies_, time_)
          : std::make_unique<RunOutput>(
                output_directory(), case_.name, mesh_, run_layout(),
                options_.overwrite || case_.output.overwrite, case_.file, inputs,
                shared_flow_ ? shared_fields_folder(shared_flow_->path()) : std::filesystem::path(),
                options_.rerun_whole ? PvdWriter::Start::when_closed
                                     : PvdWriter::Start::at_first_add);
  const std::string& crs = case_.crs_wkt;
  if (!crs.empty()) output_->write_coordinate_system(crs);
  if (case_.output.raster_resolution > 0.0) output_->write_rasters_on(envelope_grid());
}

// About 24 bytes a pixel: the cell under each pixel, one envelope's values and GDAL's copy of
// them while it writes. Checked before anything is written: a resolution of 1e-4 m stopped the
// run with std::bad_alloc after its first outputs.
RasterGrid Simulation::envelope_grid() const {
  const double r = case_.output.raster_resolution;  // [m]
  Vec2 lo = mesh_.nodes.front(), hi = lo;           // the envelopes' rasters cover the mesh
  for (const Vec2& p : mesh_.nodes) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double pixels =
      (std::ceil((hi.x() - lo.x()) / r) + 1.0) * (std::ceil((hi.y() - lo.y()) / r) + 1.0);
  const double bytes = 24.0 * pixels;
  if (bytes > 0.5 * usable_memory())
    throw_input_error(
        "{}: output.rasters.resolution: {} m over the mesh ({:.0f} m x {:.0f} m) gives {:.3g} "
        "pixels, {} to write the envelopes: more than half the memory this process may use "
        "({}); choose a coarser resolution",
        case_.file, r, hi.x() - lo.x(), hi.y() - lo.y(), pixels, format_bytes(bytes),
        format_bytes(usable_memory()));
  return RasterGrid::covering(lo, hi, r, case_.crs_wkt);
}

void Simulation::run() {
  initialize();
  Progress progress(time_, case_.time.end);
  while (!done()) {
    step();
    if (options_.progress) {
      int active = 0;
      for (auto s : bodies_.state) active += s != BodyState::gone;
      progress.update(
          time_, step_count_,
          has_bodies_ ? fmt::format("bodies {} in, {} out", active, bodies_.outflow_count) : "");
    }
  }
  progress.finish();
  write_final_output();
}

void Simulation::write_final_output() {
  synchronize_flows();  // what the last output, the rasters and the summary read
  if (!output_) return;
  if (output_->times().back() < time_)
    write_output_if_due(true);  // the final state, when the last interval was not complete
  output_->close();
}

void Simulation::synchronize_flows() {
  flow_->synchronize();
  if (reference_flow_) reference_flow_->synchronize();
}

JamStatistics Simulation::jam_statistics() const {
  JamStatistics statistics =
      compute_jam_statistics(bodies_, contacts_->report(walls_, bodies_.size()), jam_geometry_);
  const FlowField& flow = flow_->field();
  int hint = -1;
  const auto level = [&](const Vec2& p) {
    const FlowSample f = flow.sample(p, time_, hint);
    return f.inside ? GapLevel{f.eta, f.eta - f.H} : GapLevel{};  // outside: no opening
  };
  measure_opening_closure(statistics, jam_geometry_, gap_levels(jam_geometry_, level));
  return statistics;
}

std::vector<double> Simulation::backwater_rise() const {
  if (!reference_flow_) return {};
  return backwater_probe_->rise(flow_->eta(), reference_flow_->eta());
}

// What each open boundary let out in the last step [m^3/s] (negative: in), and their sum: with
// steady boundaries a settled flow lets out what comes in (docs/model.md "Reading the summary").
std::string Simulation::discharge_summary() const {
  const std::vector<double>& rate = flow_->water_balance().group_rate;
  const Mesh& mesh = flow_->mesh();
  std::vector<int> groups;  // open boundaries' groups, in the case's order, each once
  for (const BoundaryCondition& c : case_.flow.boundaries) {
    const int g = mesh.find_group(c.group);
    const bool open =
        c.kind != BoundaryCondition::Kind::wall && c.kind != BoundaryCondition::Kind::noslip;
    if (open && g >= 0 && g < static_cast<int>(rate.size()) &&
        std::find(groups.begin(), groups.end(), g) == groups.end())
      groups.push_back(g);
  }
  if (groups.empty() || step_count_ == 0 || case_.time.mode == CouplingMode::frozen) return "";
  std::string s = "discharges out   in the last step:";
  double net = 0.0;  // [m^3/s]
  for (int g : groups) {
    s += fmt::format(" {} {:.4g},", mesh.group_names[g], rate[g]);
    net += rate[g];
  }
  return s + fmt::format(" in all {:.4g} m^3/s\n", net);
}

std::string Simulation::summary() const {
  std::string s;
  const WaterBalance& b = flow_->water_balance();
  s += fmt::format("simulated        {:.1f} s in {} steps of {} s ({} mode)\n", time_, step_count_,
                   case_.time.step,
                   case_.time.mode == CouplingMode::frozen    ? "frozen"
                   : case_.time.mode == CouplingMode::one_way ? "one-way"
                                                              : "two-way");
  s += fmt::format(
      "water volume     {:.6g} m^3 (start {:.6g} m^3), net outflow {:.6g} m^3{}{}{}\n", b.volume,
      b.initial_volume, b.outflow,
      case_.flow.rain.enabled
          ? fmt::format(", rain {:.6g} m^3, infiltrated {:.6g} m^3", b.rain, b.infiltration)
          : "",
      case_.flow.sources.empty() ? "" : fmt::format(", sources {:.6g} m^3", b.sources),
      b.lag != 0.0 ? fmt::format(", in BDF2's time lag {:.6g} m^3", b.lag) : "");
  s += fmt::format("water balance    {:.3g} m^3, relative {:.3g}\n", b.error(), b.relative_error());
  s += discharge_summary();
  if (has_bodies_) {
    int floating = 0, grounded = 0;
    for (auto st : bodies_.state) {
      floating += st == BodyState::floating;
      grounded += st == BodyState::grounded;
    }
    s += fmt::format("bodies           {} in all: {} floating, {} grounded, {} left\n",
                     bodies_.size(), floating, grounded, bodies_.outflow_count);
    s += fmt::format("RKF45 sub-steps  {} accepted, {} rejected\n", integration_totals_.accepted,
                     integration_totals_.rejected);
    s += format_jam_summary(jam_statistics(), jam_geometry_, backwater_rise());
  }
  s += flow_->summary();
  // The contacts' time is part of the bodies' (advance_bodies).
  s += "wall time       ";
  for (int k = 0; k < static_cast<int>(Stage::count); ++k) {
    const auto stage = static_cast<Stage>(k);
    const std::string item = fmt::format("{} {:.2f} s", stage_names[k], timer_.seconds(stage));
    s += stage == Stage::contacts ? " (of which " + item + ")" : " " + item;
  }
  s += "\n";
  if (threads_ && threads_->most() > 1) {
    const long fewer = threads_->reduced_steps(), all = threads_->steps();
    s += fmt::format("threads          {}", threads_->most());
    s += fewer == 0 ? "\n"
                    : fmt::format(", fewer in {} of {} steps ({:.0f} %: {})\n", fewer, all,
                                  100.0 * static_cast<double>(fewer) / static_cast<double>(all),
                                  threads_->threads() < threads_->most()
                                      ? "the machine is shared, fewer were faster"
                                      : "trials, or the machine was shared for a while");
  }
  if (output_) s += fmt::format("results in       {}\n", output_->directory().string());
  return s;
}

}  // namespace flotsam
