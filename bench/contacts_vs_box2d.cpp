// flotsam's contact stage, with each of its solvers (sequential impulses, soft step), and Box2D
// 2.4 (Debian's libbox2d-dev) side by side on one scene (issue 18, item 1): the packed jam of
// bench_contacts (src/contact/jam_scene.hpp: logs 10 m x 0.5 m in rows against a line of circular
// piers in a walled channel, about 50 logs per gap), pushed downstream by a force of 0.2 m/s^2 per
// unit mass standing in for the drag, N = 1k, 10k, 50k. Both engines step the same 0.02 s steps
// from the same poses: flotsam moves the logs under the push and runs its contact stage
// (ContactWorld::step); Box2D steps its world (8 velocity and 3 position iterations, its defaults;
// sleeping on). After the warm-up and the timed steps, the poses of both are measured with
// flotsam's narrow phase: the largest and the 99th-percentile overlap between bodies and into
// walls, and the logs whose centre is past the piers (must be 0).
//
//   cmake --build <build> --target bench_contacts_vs_box2d
//   <build>/bench/bench_contacts_vs_box2d      # about 10 minutes idle; figures: performance.md
//   <build>/bench/bench_contacts_vs_box2d 10000 --no-sequential
#include <box2d/box2d.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <limits>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "contact/contact_world.hpp"
#include "contact/jam_scene.hpp"

namespace flotsam {
namespace {

struct Result {
  double ms_per_step = 0.0;      // [ms] wall time of one step
  double cpu_ms_per_step = 0.0;  // [ms] CPU time of the process per step (all its threads)
  double largest = 0.0;          // [m] largest overlap, bodies and walls
  double percentile_99 = 0.0;    // [m] 99th percentile of the overlaps of the contact points
  int past_piers = 0;            // logs whose centre is downstream of the piers' line
  double sweeps = 0.0;           // flotsam: mean velocity sweeps per step (its cap: 200)
  double second_solves = 0.0;    // flotsam: share of the steps solved twice (docs/model.md)
  double islands = 0.0;          // flotsam: islands per step (contact/islands.hpp)
  double detect_ms = 0.0;        // flotsam: boxes, broad and narrow phase per step [ms]
  double pairs_ms = 0.0;         // flotsam: of which boxes and broad phase [ms]
  double solve_ms = 0.0;         // flotsam: the solver per step [ms]
  double positions_ms = 0.0;     // flotsam: the position stage per step [ms]
  double sleeping = 0.0;         // flotsam: islands asleep per step (not solved)
  std::uint64_t state_hash = 0;  // FNV-1a of the final poses' and velocities' bits
};

// FNV-1a over the bits of every body's pose and velocity: two builds, or two thread counts, that
// print the same hash ended in the same state.
std::uint64_t state_hash(const BodySet& b) {
  std::uint64_t h = 14695981039346656037ull;
  const auto add = [&](double x) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    for (int k = 0; k < 8; ++k) h = (h ^ ((bits >> (8 * k)) & 0xff)) * 1099511628211ull;
  };
  for (int i = 0; i < b.size(); ++i) {
    add(b.position[i].x()), add(b.position[i].y()), add(b.angle[i]);
    add(b.velocity[i].x()), add(b.velocity[i].y()), add(b.angular_velocity[i]);
  }
  return h;
}

// Overlaps of the scene's poses, measured with flotsam's narrow phase (margin 0: touching only).
Result measure(const JamScene& scene) {
  ContactConfig config = jam_contact_config();
  config.allowed_overlap = 0.0;
  ContactWorld world(config);
  world.detect(scene.bodies, scene.walls);
  std::vector<double> overlaps;
  for (const ContactConstraint& c : world.contacts())
    for (int k = 0; k < c.point_count; ++k)
      overlaps.push_back(std::max(0.0, -c.points[static_cast<std::size_t>(k)].separation));
  Result r;
  if (!overlaps.empty()) {
    std::sort(overlaps.begin(), overlaps.end());
    r.largest = overlaps.back();
    r.percentile_99 = overlaps[static_cast<std::size_t>(0.99 * (overlaps.size() - 1))];
  }
  for (int i = 0; i < scene.bodies.size(); ++i)
    if (scene.bodies.position[i].x() > scene.pier_x) ++r.past_piers;
  return r;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// [s] of CPU used by the process: on a loaded machine, read with one thread, it is the fairer
// measure of the work (the wall time includes the time the process waited for a core).
double cpu_seconds() {
  return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

Result run_flotsam(JamScene scene, int warm_up, int timed, ContactSolverKind solver, bool sleep) {
  ContactConfig config = jam_contact_config();
  config.solver = solver;
  config.sleep_time = sleep ? soft_step_sleep_time : 0.0;
  ContactWorld world(config);
  for (int k = 0; k < warm_up; ++k) world.step(scene.bodies, scene.walls, move_jam_logs(scene));
  double sweeps = 0.0, second_solves = 0.0, islands = 0.0, sleeping = 0.0;
  double detect = 0.0, pairs = 0.0, solve = 0.0,
         positions = 0.0;  // [s] of the last solve of each step
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = cpu_seconds();
  for (int k = 0; k < timed; ++k) {
    world.step(scene.bodies, scene.walls, move_jam_logs(scene));
    sweeps += world.profile().velocity_sweeps;
    second_solves += world.profile().second_solves;
    islands += world.profile().islands;
    sleeping += world.profile().sleeping_islands;
    const ContactProfile& p = world.profile();
    detect += p.boxes + p.broad_phase + p.narrow_phase;
    pairs += p.boxes + p.broad_phase;
    solve += p.solve;
    positions += p.positions;
  }
  const double seconds = seconds_since(start), cpu = cpu_seconds() - cpu_start;
  Result r = measure(scene);
  r.state_hash = state_hash(scene.bodies);
  r.ms_per_step = 1e3 * seconds / timed;
  r.cpu_ms_per_step = 1e3 * cpu / timed;
  r.sweeps = sweeps / timed;
  r.second_solves = second_solves / timed;
  r.islands = islands / timed;
  r.sleeping = sleeping / timed;
  r.detect_ms = 1e3 * detect / timed;
  r.pairs_ms = 1e3 * pairs / timed;
  r.solve_ms = 1e3 * solve / timed;
  r.positions_ms = 1e3 * positions / timed;
  return r;
}

// The same scene in a Box2D world: banks as edges, piers as circles (flotsam's are 64-gons on
// the circle), logs as boxes of the same mass and moment of inertia about the vertical.
Result run_box2d(JamScene scene, int warm_up, int timed, bool sleep) {
  const ContactConfig config = jam_contact_config();
  auto world = std::make_unique<b2World>(b2Vec2(0.0f, 0.0f));
  b2BodyDef ground_def;
  b2Body* ground = world->CreateBody(&ground_def);
  const BoundarySegments& walls = scene.walls;
  for (int s = 0; s < walls.size(); ++s) {
    if (walls.group[s] >= 2) continue;  // the piers' segments: circles below
    b2EdgeShape edge;
    edge.SetTwoSided(
        b2Vec2(static_cast<float>(walls.start[s].x()), static_cast<float>(walls.start[s].y())),
        b2Vec2(static_cast<float>(walls.end[s].x()), static_cast<float>(walls.end[s].y())));
    ground->CreateFixture(&edge, 0.0f);
  }
  const int piers = static_cast<int>(walls.group_names.size()) - 2;
  for (int j = 0; j < piers; ++j) {
    b2CircleShape circle;
    circle.m_p.Set(static_cast<float>(scene.pier_x), static_cast<float>(6.0 + 8.0 * j));
    circle.m_radius = static_cast<float>(scene.pier_radius);
    ground->CreateFixture(&circle, 0.0f);
  }
  BodySet& b = scene.bodies;
  std::vector<b2Body*> logs;
  for (int i = 0; i < b.size(); ++i) {
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(static_cast<float>(b.position[i].x()), static_cast<float>(b.position[i].y()));
    def.angle = static_cast<float>(b.angle[i]);
    b2Body* body = world->CreateBody(&def);
    b2PolygonShape box;
    box.SetAsBox(static_cast<float>(0.5 * b.length[i]), static_cast<float>(0.5 * b.width[i]));
    b2FixtureDef fixture;
    fixture.shape = &box;
    fixture.density = static_cast<float>(b.mass[i] / (b.length[i] * b.width[i]));  // [kg/m^2]
    fixture.friction = static_cast<float>(config.friction);
    fixture.restitution = static_cast<float>(config.restitution);
    body->CreateFixture(&fixture);
    logs.push_back(body);
  }
  constexpr float dt = static_cast<float>(jam_max_step);
  const auto step = [&] {
    for (b2Body* body : logs)
      body->ApplyForceToCenter(b2Vec2(body->GetMass() * static_cast<float>(jam_push), 0.0f),
                               !sleep);
    world->Step(dt, 8, 3);
  };
  for (int k = 0; k < warm_up; ++k) step();
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = cpu_seconds();
  for (int k = 0; k < timed; ++k) step();
  const double seconds = seconds_since(start), cpu = cpu_seconds() - cpu_start;
  for (int i = 0; i < b.size(); ++i) {
    b.position[i] = {logs[i]->GetPosition().x, logs[i]->GetPosition().y};
    b.angle[i] = logs[i]->GetAngle();
  }
  Result r = measure(scene);
  r.ms_per_step = 1e3 * seconds / timed;
  r.cpu_ms_per_step = 1e3 * cpu / timed;
  return r;
}

}  // namespace
}  // namespace flotsam

// Arguments: the log counts (default 1000 10000 50000); `--no-sequential` leaves out flotsam's
// sequential impulses (minutes at 50k); `--sleep`: both engines let resting islands sleep
// (Box2D's push no longer wakes a sleeping body; flotsam's soft step with sleep_time 0.5 s, as a
// case file's default: docs/model.md "Sleeping islands"), else every body is solved every step;
// `--warm-up N`: N steps before the timed ones (default 100); `--no-box2d` leaves out Box2D (to
// compare two builds of flotsam: no ratios then).
// A positive integer of at most 9 digits (a log count or a number of steps).
static bool positive(const char* text) {
  const std::string t(text);
  return !t.empty() && t.size() <= 9 && t.find_first_not_of("0123456789") == std::string::npos &&
         std::stoi(t) > 0;
}

int main(int argc, char** argv) {
  using namespace flotsam;
  std::vector<int> counts;
  bool sequential = true, sleep = false, box2d = true;
  int warm_up = 100;  // steps of 0.02 s before the timed ones
  for (int k = 1; k < argc; ++k) {
    if (std::string(argv[k]) == "--no-sequential") {
      sequential = false;
    } else if (std::string(argv[k]) == "--no-box2d") {
      box2d = false;
    } else if (std::string(argv[k]) == "--sleep") {
      sleep = true;
    } else if (std::string(argv[k]) == "--warm-up" && k + 1 < argc && positive(argv[k + 1])) {
      warm_up = std::stoi(argv[++k]);
    } else if (positive(argv[k])) {
      counts.push_back(std::stoi(argv[k]));
    } else {
      std::fprintf(stderr,
                   "bench_contacts_vs_box2d: '%s' is not a log count (a positive integer) or one "
                   "of --no-sequential, --no-box2d, --sleep, --warm-up N\n",
                   argv[k]);
      return 2;
    }
  }
  if (counts.empty()) counts = {1000, 10000, 50000};
  std::printf("sleeping %s\n", sleep ? "on" : "off");
  std::printf("%7s %-10s %12s %12s %14s %14s %11s\n", "logs", "engine", "ms/step", "cpu ms/step",
              "largest [mm]", "p99 [mm]", "past piers");
  for (const int n : counts) {
    JamSceneSpec spec;
    spec.log_count = n;
    spec.pier_count = std::max(2, n / 50 + 1);
    spec.row_gap = 0.0;
    const JamScene scene = make_jam_scene(spec);
    const int timed = n >= 50000 ? 20 : 50;  // steps of 0.02 s
    const Result b = box2d ? run_box2d(scene, warm_up, timed, sleep) : Result{};
    const Result f = sequential ? run_flotsam(scene, warm_up, timed,
                                              ContactSolverKind::sequential_impulses, sleep)
                                : Result{};
    const Result s = run_flotsam(scene, warm_up, timed, ContactSolverKind::soft_step, sleep);
    // The engines that ran, then flotsam's solvers relative to Box2D.
    for (const auto& [name, r, ran] :
         {std::tuple{"box2d", b, box2d}, std::tuple{"sequential", f, sequential},
          std::tuple{"soft", s, true}}) {
      if (!ran) continue;
      std::printf("%7d %-10s %12.2f %12.2f %14.2f %14.2f %11d\n", n, name, r.ms_per_step,
                  r.cpu_ms_per_step, 1e3 * r.largest, 1e3 * r.percentile_99, r.past_piers);
    }
    const auto ratio = [&](double x, double y) {  // nan without Box2D
      return box2d ? x / y : std::numeric_limits<double>::quiet_NaN();
    };
    for (const auto& [name, r, ran] :
         {std::tuple{"sequential", f, sequential}, std::tuple{"soft", s, true}}) {
      if (!ran) continue;
      std::printf(
          "%7d %-10s %12.2f %12.2f %14.2f %14.2f   (/ box2d; %.0f islands, %.0f asleep, %.0f "
          "velocity sweeps per step, %.0f %% of steps solved twice; last solve per step: "
          "detection %.2f ms (pairs %.2f), solver %.2f ms, positions %.2f ms; final state "
          "%016llx)\n",
          n, name, ratio(r.ms_per_step, b.ms_per_step), ratio(r.cpu_ms_per_step, b.cpu_ms_per_step),
          ratio(r.largest, b.largest), ratio(r.percentile_99, b.percentile_99), r.islands,
          r.sleeping, r.sweeps, 100.0 * r.second_solves, r.detect_ms, r.pairs_ms, r.solve_ms,
          r.positions_ms, static_cast<unsigned long long>(r.state_hash));
    }
    std::fflush(stdout);
  }
  return 0;
}
