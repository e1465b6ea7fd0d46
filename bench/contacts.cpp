// Contacts (spec 4.2-4.3): one contact stage (detection + impulses + position correction) per
// step on the jam scene of the jam test (src/contact/jam_scene.hpp) scaled up to 1k, 3k and 10k
// logs packed in rows against a line of piers, pushed downstream as in the test; and detection
// alone, by sort-and-sweep and by brute force (all pairs), on the same poses.
//
//   cmake --build <build> --target bench_contacts
//   <build>/bench/bench_contacts --benchmark_min_time=0.3
//
// Counters: contacts (manifolds), sweeps (velocity sweeps of the last step, the most an island
// took), islands and the contacts of the largest, and the share of
// each stage in the step (boxes, broad, narrow, solve, positions [ms]). Figures:
// docs/performance.md, "Contacts".
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "contact/contact_world.hpp"
#include "contact/jam_scene.hpp"

namespace flotsam {
namespace {

// About 50 logs per gap between two piers, the rows packed (no free space between them).
JamScene packed_scene(int logs) {
  JamSceneSpec spec;
  spec.log_count = logs;
  spec.pier_count = std::max(2, logs / 50 + 1);
  spec.row_gap = 0.0;
  return make_jam_scene(spec);
}

void BM_ContactStep(benchmark::State& state) {
  JamScene scene = packed_scene(static_cast<int>(state.range(0)));
  ContactWorld world(jam_contact_config());
  for (int k = 0; k < 20; ++k) {  // warm-up: the first contacts, the sweep order
    const double dt = move_jam_logs(scene);
    world.step(scene.bodies, scene.walls, dt);
  }
  ContactProfile total;
  for (auto _ : state) {
    state.PauseTiming();
    const double dt = move_jam_logs(scene);  // the jam test's step
    state.ResumeTiming();
    world.step(scene.bodies, scene.walls, dt);
    const ContactProfile& p = world.profile();
    total.boxes += p.boxes, total.broad_phase += p.broad_phase;
    total.narrow_phase += p.narrow_phase, total.solve += p.solve, total.positions += p.positions;
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["contacts"] = world.profile().contacts;
  state.counters["sweeps"] = world.profile().velocity_sweeps;
  state.counters["islands"] = world.profile().islands;
  state.counters["largest_island"] = world.profile().largest_island;
  state.counters["broad_ms"] = 1e3 * (total.boxes + total.broad_phase) / n;
  state.counters["narrow_ms"] = 1e3 * total.narrow_phase / n;
  state.counters["solve_ms"] = 1e3 * total.solve / n;
  state.counters["positions_ms"] = 1e3 * total.positions / n;
}

void detect(benchmark::State& state, BroadPhase method) {
  JamScene scene = packed_scene(static_cast<int>(state.range(0)));
  ContactWorld world{ContactConfig{}};
  world.set_broad_phase(method);
  world.detect(scene.bodies, scene.walls);  // the sweep order
  for (auto _ : state) {
    world.detect(scene.bodies, scene.walls);
    benchmark::DoNotOptimize(world.contacts().data());
  }
  state.counters["pairs"] = static_cast<double>(world.body_pairs().size());
  state.counters["contacts"] = static_cast<double>(world.contacts().size());
}

void BM_DetectSweepAndPrune(benchmark::State& state) {
  detect(state, BroadPhase::sweep_and_prune);
}

void BM_DetectBruteForce(benchmark::State& state) {
  detect(state, BroadPhase::brute_force);
}

BENCHMARK(BM_ContactStep)->Arg(1000)->Arg(3000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DetectSweepAndPrune)->Arg(1000)->Arg(3000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DetectBruteForce)->Arg(1000)->Arg(3000)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace flotsam

BENCHMARK_MAIN();
