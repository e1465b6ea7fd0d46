#include "ensemble/ensemble_runner.hpp"

#include <fmt/format.h>
#include <omp.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <fstream>
#include <mutex>
#include <sstream>
#include <system_error>
#include <thread>

#include "contact/boundary_segments.hpp"
#include "core/error.hpp"
#include "coupling/jam_statistics.hpp"
#include "coupling/progress.hpp"
#include "coupling/shared_flow.hpp"
#include "ensemble/ensemble_pictures.hpp"
#include "ensemble/ensemble_statistics.hpp"
#include "ensemble/member_case.hpp"
#include "ensemble/member_runner.hpp"
#include "io/case_digest.hpp"
#include "io/case_file.hpp"
#include "mesh/mesh_generator.hpp"

namespace fs = std::filesystem;

namespace flotsam {

namespace {

constexpr const char* manifest_file = "ensemble.txt";

/// FNV-1a, 64 bits: the fingerprint of the case an ensemble folder holds.
std::uint64_t fingerprint(const std::string& text) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : text) h = (h ^ c) * 0x100000001b3ULL;
  return h;
}

// What differs between the manifest held and the new one, for the message: " (changed: case,
// input bed.raster)", the first word or two of each line of `now` that `held` lacks.
std::string changed_lines(const std::string& held, const std::string& now) {
  std::vector<std::string> changed;
  std::istringstream lines(now);
  for (std::string line; std::getline(lines, line);) {
    if (held.find(line + "\n") != std::string::npos) continue;
    const std::size_t first = line.find(' ');
    const std::size_t second = line.starts_with("input ") ? line.find(' ', first + 1) : first;
    changed.push_back(line.substr(0, second));
  }
  return changed.empty() ? "" : fmt::format(" (changed: {})", fmt::join(changed, ", "));
}

bool ours(const fs::path& entry) {
  const std::string name = entry.filename().string();
  return name.starts_with("member_") || name.starts_with("ensemble") || name.ends_with(".png") ||
         name == ".flotsam-output";
}

/// Creates the folder, or finds an earlier ensemble of the same case in it (resume), or empties
/// an earlier ensemble's files (`overwrite`). Returns how the folder was found, for the log.
std::string prepare_ensemble_directory(const fs::path& directory, const std::string& manifest,
                                       bool overwrite) {
  if (fs::exists(directory) && !fs::is_directory(directory))
    throw_input_error("output folder '{}' exists and is not a folder", directory.string());
  fs::create_directories(directory);
  const fs::path path = directory / manifest_file;
  bool empty = true;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory))
    empty = empty && entry.path().filename() == ".flotsam-output";
  if (!empty) {
    if (!fs::exists(path))
      throw_input_error(
          "output folder '{}' is not empty and holds no ensemble ({} is missing); choose another "
          "folder",
          directory.string(), manifest_file);
    std::ifstream in(path, std::ios::binary);
    std::ostringstream held;
    held << in.rdbuf();
    if (held.str() == manifest && !overwrite) return "resumed";
    if (!overwrite)
      throw_input_error(
          "output folder '{}' holds an ensemble of another case, member count or input files{}; "
          "add --overwrite to replace it, or choose another folder",
          directory.string(), changed_lines(held.str(), manifest));
    for (const fs::directory_entry& entry : fs::directory_iterator(directory))
      if (ours(entry.path())) fs::remove_all(entry.path());
  }
  std::ofstream out(path, std::ios::binary);
  out << manifest;
  if (!out) throw_input_error("cannot write in output folder '{}'", directory.string());
  return "new";
}

/// The progress line over the members of every rank (rank 0): done of all, failed, elapsed and
/// the time left at the pace of the members run so far.
class MemberProgress {
 public:
  MemberProgress(int total, int ranks, bool show)
      : total_(total),
        tallies_(static_cast<std::size_t>(ranks)),
        show_(show),
        terminal_(isatty(2) != 0) {}

  /// The latest tally of `rank`; true when it changed.
  bool update(int rank, const RankTally& tally) {
    RankTally& t = tallies_.at(static_cast<std::size_t>(rank));
    const bool changed = t != tally;
    t = tally;
    return changed;
  }
  bool all_finished() const {
    return std::all_of(tallies_.begin(), tallies_.end(),
                       [](const RankTally& t) { return t[3] != 0; });
  }
  void print() {
    int done = 0, kept = 0, failed = 0;
    for (const RankTally& t : tallies_) done += t[0], kept += t[1], failed += t[2];
    if (!show_ || done == last_done_) return;
    last_done_ = done;
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const int ran = done - kept;
    const double left = ran > 0 ? wall / ran * (total_ - done) : 0.0;
    fmt::print(stderr, "{}members {}/{} done ({} failed)  elapsed {}  left {}{}",
               terminal_ ? "\r" : "", done, total_, failed, Progress::format_duration(wall),
               Progress::format_duration(left), terminal_ ? "\x1b[K" : "\n");
    std::fflush(stderr);
    printed_ = true;
  }
  void finish() const {
    if (show_ && terminal_ && printed_) fmt::print(stderr, "\n");
  }

 private:
  int total_;
  std::vector<RankTally> tallies_;
  bool show_, terminal_, printed_ = false;
  int last_done_ = 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

struct Plan {
  EnsembleConfig config;
  Case base;
  YAML::Node base_yaml;
  Mesh mesh;
  JamGeometry geometry;
  MemberCaseContext context;
  std::string manifest;
};

Plan make_plan(const EnsembleOptions& options) {
  Plan plan;
  const std::string text = read_case_text(options.case_file);
  const SplitCaseText split = split_ensemble_text(text);
  plan.config = parse_ensemble(split.ensemble_text, options.case_file);
  if (options.members > 0) plan.config.members = options.members;
  plan.base = parse_case(split.case_text, options.case_file);
  if (plan.base.bodies.bodies.empty() && plan.base.bodies.releases.empty())
    throw_input_error("{}: an ensemble needs bodies (bodies.list or bodies.release)",
                      options.case_file);
  plan.base_yaml = YAML::Load(split.case_text);
  plan.mesh = generate_mesh(plan.base.mesh);
  check_case_against_mesh(plan.base, plan.mesh.group_names);
  plan.geometry = jam_geometry_for(plan.base.mesh, plan.mesh,
                                   solid_group_indices(plan.mesh, plan.base.flow.boundaries),
                                   plan.base.bridges);
  const fs::path directory = options.output.empty()
                                 ? fs::path(plan.base.output.directory) / plan.base.name
                                 : fs::path(options.output);
  plan.context.case_folder = fs::path(options.case_file).parent_path();
  plan.context.directory = fs::absolute(directory).lexically_normal();
  plan.context.source = options.case_file;
  if (!plan.geometry.bridges.empty())
    for (const Gap& gap : plan.geometry.bridges.front().gaps)
      plan.context.gap_width = std::max(plan.context.gap_width, gap.width());
  // Inputs that cannot apply to this case are the ensemble's error, not a member's failure.
  (void)member_case_text(
      plan.base_yaml,
      draw_member_inputs(plan.config, 0, static_cast<int>(plan.base.bodies.releases.size())),
      plan.context);
  plan.manifest = fmt::format("flotsam ensemble 1\ncase {}\nfingerprint {:016x}\nmembers {}\n",
                              fs::absolute(options.case_file).lexically_normal().string(),
                              fingerprint(text), plan.config.total_members());
  // The files the case reads, by the checksums of their contents its settings hold: a member
  // run after one changed would belong to another study.
  for (const CaseSetting& s : plan.base.settings)
    if (s.key.ends_with(file_contents_suffix))
      plan.manifest += fmt::format(
          "input {} {}\n", s.key.substr(0, s.key.size() - file_contents_suffix.size()), s.value);
  return plan;
}

/// Runs `runs` on `jobs` threads, each taking the next member not yet taken. The calling thread
/// keeps the progress: it sends this rank's tally to rank 0 as members finish (a last one when
/// all are done), and on rank 0 gathers every rank's and prints the line, until every rank is
/// done. Only this thread calls MPI (MPI_THREAD_FUNNELED).
std::vector<MemberResult> run_members(const std::vector<MemberRun>& runs, const MemberSetup& setup,
                                      int jobs, int kept, const RankWorld& world,
                                      MemberProgress& progress) {
  std::vector<MemberResult> results(runs.size());
  std::atomic<std::size_t> next{0};
  std::atomic<int> done{kept}, failed{0}, workers{0};
  std::mutex mutex;
  std::condition_variable member_finished;
  auto worker = [&] {
    for (std::size_t k = next++; k < runs.size(); k = next++) {
      results[k] = run_member(runs[k], setup);
      failed += results[k].failed;
      ++done;
      member_finished.notify_one();
    }
    --workers;
    member_finished.notify_one();
  };
  // As many jobs as the system lets start (each thread takes a stack): fewer is a warning, none
  // an error, never a thread left unjoined.
  std::vector<std::thread> threads;
  for (int t = 0; t < jobs; ++t) {
    ++workers;
    try {
      threads.emplace_back(worker);
    } catch (const std::system_error& e) {
      --workers;
      if (threads.empty())
        throw_run_error("could not start a job for the members ({}); try fewer --jobs", e.what());
      spdlog::warn("started {} of {} jobs ({}); the members run on those", threads.size(), jobs,
                   e.what());
      break;
    }
  }
  RankTally sent{-1, 0, 0, 0};
  for (bool finished = false; !finished;) {
    {
      std::unique_lock lock(mutex);
      member_finished.wait_for(lock, std::chrono::milliseconds(200));
    }
    const bool mine_done = workers == 0;
    const RankTally tally{done.load(), kept, failed.load(), mine_done ? 1 : 0};
    if (world.rank() == 0) {
      progress.update(0, tally);
      for (const auto& [rank, received] : world.receive_tallies()) progress.update(rank, received);
      progress.print();
      finished = progress.all_finished();
    } else {
      if (tally != sent) world.send_tally(tally);
      sent = tally;
      finished = mine_done;
    }
  }
  for (std::thread& t : threads) t.join();
  return results;
}

/// Records the shared flow of this rank's members (from the first one's case, whose flow is
/// every member's) in DIR/ensemble_flow_R.bin; returns its path.
fs::path record_members_flow(const MemberRun& first, const Mesh& mesh, const fs::path& directory,
                             int rank) {
  const Case member_case = parse_case(first.case_text, first.case_path.string());
  const fs::path path = directory / fmt::format("ensemble_flow_{}.bin", rank);
  record_shared_flow(member_case, mesh, path.string(), true);
  return path;
}

}  // namespace

FlowSharing shared_flow_reason(const Case& base, const EnsembleConfig& config) {
  if (!flow_can_be_shared(base))
    return {false, "computed by each member (two-way mode: the bodies act on the water)"};
  const bool varied = std::any_of(config.vary.begin(), config.vary.end(), [](const auto& v) {
    return v.input == EnsembleInput::discharge_scale;
  });
  if (varied || (config.has_sweep && config.sweep_input == EnsembleInput::discharge_scale))
    return {false, "computed by each member (discharge_scale varies the flow)"};
  return {true, fmt::format("computed once and shared by the members ({} mode, no input varies "
                            "the flow)",
                            base.time.mode == CouplingMode::frozen ? "frozen" : "one-way")};
}

EnsembleReport run_ensemble(const EnsembleOptions& options, const RankWorld& world) {
  const auto start = std::chrono::steady_clock::now();
  Plan plan = make_plan(options);
  EnsembleReport report;
  report.directory = plan.context.directory;
  // Rank 0 prepares the folder; the others wait for its word (its error stops them too).
  std::string prepared;
  if (world.rank() == 0) {
    try {
      prepared = prepare_ensemble_directory(report.directory, plan.manifest, options.overwrite);
    } catch (const InputError& e) {
      prepared = std::string("error: ") + e.what();
    }
  }
  prepared = world.broadcast(prepared);
  if (prepared.starts_with("error: ")) throw_input_error("{}", prepared.substr(7));

  const int total = plan.config.total_members();
  const int releases = static_cast<int>(plan.base.bodies.releases.size());
  std::vector<MemberResult> mine;  // this rank's members, kept or run now
  std::vector<MemberRun> runs;
  for (int m = world.rank(); m < total; m += world.size()) {
    const fs::path folder = report.directory / member_name(m);
    if (std::optional<MemberResult> kept = read_member_result(folder);
        kept && kept->inputs.member == m) {
      mine.push_back(std::move(*kept));
      continue;
    }
    MemberRun run;
    run.inputs = draw_member_inputs(plan.config, m, releases);
    run.case_text = member_case_text(plan.base_yaml, run.inputs, plan.context);
    run.case_path = report.directory / (member_name(m) + ".yaml");
    run.folder = folder;
    runs.push_back(std::move(run));
  }
  report.kept = static_cast<int>(mine.size());
  report.ran = static_cast<int>(runs.size());
  MemberSetup setup{&plan.mesh, &plan.geometry, plan.config.blocking,
                    options.jobs > 1 || world.size() > 1 ? 1 : 0};
  if (!runs.empty())
    setup.mesh_setup = std::make_shared<const MeshSetup>(prepare_mesh_setup(plan.mesh, plan.base));
  FlowSharing sharing = shared_flow_reason(plan.base, plan.config);
  if (!options.share_flow && sharing.shared)
    sharing = {false, "computed by each member (--no-shared-flow)"};
  report.flow_shared = sharing.shared;
  report.flow_sharing = sharing.reason;
  if (world.rank() == 0 && options.progress) fmt::print(stderr, "flow: {}\n", sharing.reason);
  if (sharing.shared && !runs.empty()) {
    const auto flow_start = std::chrono::steady_clock::now();
    // On the members' thread count: with several jobs or ranks the cores are shared, and
    // OpenMP threads waiting for a busy core cost more than they give (docs/performance.md).
    if (setup.threads > 0) omp_set_num_threads(setup.threads);
    try {
      setup.shared_flow =
          record_members_flow(runs.front(), plan.mesh, report.directory, world.rank());
    } catch (const std::exception& e) {
      // A flow that stops (unstable) stops every member the same way: each then computes its
      // own and is reported failed with the message, and the ensemble still ends.
      fmt::print(stderr,
                 "flotsam: the shared flow could not be computed ({}); each member "
                 "computes its own\n",
                 e.what());
      report.flow_shared = false;
      report.flow_sharing = "computed by each member (the shared flow stopped)";
    }
    report.flow_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - flow_start).count();
  }
  MemberProgress progress(plan.config.total_members(), world.size(),
                          options.progress && world.rank() == 0);
  for (MemberResult& r :
       run_members(runs, setup, std::max(1, options.jobs), report.kept, world, progress)) {
    report.member_seconds += r.wall_seconds;
    report.step_seconds += r.step_seconds;
    mine.push_back(std::move(r));
  }
  progress.finish();
  if (!setup.shared_flow.empty()) remove_shared_flow(setup.shared_flow);

  std::string text;
  for (const MemberResult& r : mine) text += serialize_member(r);
  const std::vector<std::string> gathered = world.gather(text);
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (world.rank() != 0) return report;

  std::vector<MemberResult> results;
  for (const std::string& rank_text : gathered) {
    std::istringstream in(rank_text);
    std::string line, record;
    while (std::getline(in, line)) {
      record += line + "\n";
      if (line == "end") {
        results.push_back(parse_member(record));
        record.clear();
      }
    }
  }
  std::sort(results.begin(), results.end(), [](const MemberResult& a, const MemberResult& b) {
    return a.inputs.member < b.inputs.member;
  });
  const EnsembleStatistics statistics =
      compute_ensemble_statistics(results, plan.config, plan.geometry);
  report.summary = format_ensemble_summary(statistics, plan.config, plan.base.name);
  for (const MemberResult& r : results) report.failed += r.failed;
  const std::string directory = report.directory.string();
  {
    std::ofstream out(report.directory / "ensemble_summary.txt", std::ios::binary);
    out << report.summary;
    if (!out) throw_run_error("could not write '{}/ensemble_summary.txt'", directory);
  }
  write_ensemble_tables(directory, results, statistics, plan.config, plan.geometry);
  if (options.pictures)
    draw_ensemble_pictures(directory, results, statistics, plan.config, plan.mesh);
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace flotsam
