// Body forces and integration (issue 4 item 7): 100,000 logs in a frozen flow resembling the
// paper's channel (uniform 0.5 m/s, 10 m deep, 1500 m x 170 m), time per 0.1 s flow step of
// forces (M-5)-(M-8) plus RKF45 integration, no contacts. Arguments: threads, drag points,
// and whether the logs start at rest (0: first steps of the transient) or after 20 s of drift
// (1: the steady regime where every body takes one 0.1 s sub-step).
//   cmake --build build --target bench_bodies_forces && build/bench/bench_bodies_forces
#include <benchmark/benchmark.h>
#include <omp.h>

#include <random>

#include "bodies/analytic_flow.hpp"
#include "bodies/body_integrator.hpp"
#include "core/constants.hpp"

namespace flotsam {
namespace {

constexpr int body_count = 100000;
constexpr double flow_step = 0.1;  // [s]

BodySet channel_logs() {
  BodySet bodies;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> x(10.0, 1490.0), y(10.0, 160.0), angle(0.0, 2 * pi);
  for (int i = 0; i < body_count; ++i) {
    BodySpec spec;  // 20 m x 1 m logs, density 600
    spec.position = {x(random), y(random)};
    spec.angle = angle(random);
    bodies.add(spec);
  }
  return bodies;
}

void BM_BodyStep(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  ForceModel model;
  model.physics.drag_points = static_cast<int>(state.range(1));
  const bool steady = state.range(2) != 0;
  AnalyticFlowSpec spec;
  spec.velocity = {0.5, 0.0};
  spec.eta = 10.0;
  spec.domain_min = {0.0, 0.0};
  spec.domain_max = {1500.0, 170.0};
  const AnalyticFlow flow(spec);
  const BodyIntegrator integrator(model);
  BodySet bodies = channel_logs();
  double t = 0.0;
  if (steady)
    for (; t < 20.0 - 1e-9; t += flow_step) integrator.advance(bodies, flow, t, t + flow_step);
  const BodySet start = bodies;
  const double t_start = t;
  long accepted = 0, rejected = 0, steps = 0;
  for (auto _ : state) {
    state.PauseTiming();
    if (!steady) {  // every timed step is the first one from rest
      bodies = start;
      t = t_start;
    }
    state.ResumeTiming();
    const IntegrationStats s = integrator.advance(bodies, flow, t, t + flow_step);
    t += flow_step;
    accepted += s.accepted;
    rejected += s.rejected;
    ++steps;
  }
  state.counters["substeps_per_body"] =
      static_cast<double>(accepted) / static_cast<double>(steps * body_count);
  state.counters["rejected_per_body"] =
      static_cast<double>(rejected) / static_cast<double>(steps * body_count);
}

BENCHMARK(BM_BodyStep)
    ->ArgNames({"threads", "drag_points", "steady"})
    ->Args({1, 1, 1})
    ->Args({2, 1, 1})
    ->Args({2, 5, 1})
    ->Args({2, 1, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);

}  // namespace
}  // namespace flotsam

BENCHMARK_MAIN();
