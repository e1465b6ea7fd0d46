// Body forces and integration (issue 4 item 7, issue 18 item 3): 100,000 logs in a frozen flow
// resembling the paper's channel (0.5 m/s, 10 m deep, 1500 m x 170 m), time per 0.1 s flow step
// of forces (M-5)-(M-8) plus RKF45 integration, no contacts. Arguments: threads, drag points,
// whether the logs start at rest (0: first steps of the transient) or after 20 s of drift
// (1: the steady regime where every body takes one 0.1 s sub-step), and the field the logs
// sample: 0 the analytic flow (uniform), 1 the FEM engine's, 2 the finite-volume engine's, both
// on a structured channel mesh of 10 m triangles (5,100 elements) holding that flow after one
// 1 s step from it, so that sampling (point location, interpolation in space and time) is
// timed too. Each iteration stands for a flow step: in the FEM's field it includes the copy of
// the states into the elements' packs (FemFlowField::pack_states), which a run pays once per
// flow step (the finite-volume field's copy of its states, FvFlowField::advance_to_state, is
// part of the engine's step and not timed).
//   cmake --build build --target bench_bodies_forces && build/bench/bench_bodies_forces
#include <benchmark/benchmark.h>
#include <omp.h>

#include <memory>
#include <random>

#include "bodies/analytic_flow.hpp"
#include "bodies/body_integrator.hpp"
#include "core/constants.hpp"
#include "coupling/flow_engines.hpp"
#include "flow/fem/fem_flow_field.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

constexpr int body_count = 100000;
constexpr double flow_step = 0.1;                                               // [s]
constexpr double channel_length = 1500.0, channel_width = 170.0, depth = 10.0;  // [m]
constexpr double speed = 0.5;                                                   // [m/s]

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

/// The channel's flow in an engine: 0.5 m/s, 10 m deep over a flat bed, the discharge in at
/// the left, the surface held at the right, walls at the sides, stepped once by 1 s.
struct EngineFlow {
  Mesh mesh;
  Case flow_case;
  std::unique_ptr<FlowEngine> engine;

  /// `steps` of 1 s (0: the initial state only), on nx x ny rectangles cut in two.
  explicit EngineFlow(FlowEngineKind kind, int nx = 150, int ny = 17, int steps = 1) {
    mesh =
        make_rectangle_mesh({.length = channel_length, .width = channel_width, .nx = nx, .ny = ny});
    flow_case.name = "bench_bodies_forces";
    flow_case.mesh.kind = MeshSource::Kind::file;
    flow_case.flow.engine = kind;
    flow_case.flow.initial_eta_start = flow_case.flow.initial_eta_end = depth;
    flow_case.flow.initial_u = Expression("0.5", "bench");
    flow_case.flow.initial_v = Expression("0", "bench");
    flow_case.flow.viscosity = 0.01;
    flow_case.flow.friction = FrictionLaw::manning;
    flow_case.flow.friction_coefficient = 0.03;
    const TimeSeries Q(speed * depth * channel_width);  // [m^3/s]
    flow_case.flow.boundaries = {
        {BoundaryCondition::Kind::discharge, "left", Q, TimeSeries(0.0)},
        {BoundaryCondition::Kind::elevation, "right", TimeSeries(depth), TimeSeries(0.0)},
        {BoundaryCondition::Kind::wall, "bottom", TimeSeries(0.0), TimeSeries(0.0)},
        {BoundaryCondition::Kind::wall, "top", TimeSeries(0.0), TimeSeries(0.0)}};
    flow_case.time = {.end = 10.0, .step = 1.0, .mode = CouplingMode::one_way};
    engine = make_flow_engine(mesh, flow_case);
    engine->initialize();
    for (int i = 0; i < steps; ++i) engine->step(1.0);
  }
};

void BM_BodyStep(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  ForceModel model;
  model.physics.drag_points = static_cast<int>(state.range(1));
  const bool steady = state.range(2) != 0;
  const int field = static_cast<int>(state.range(3));
  AnalyticFlowSpec spec;
  spec.velocity = {speed, 0.0};
  spec.eta = depth;
  spec.domain_min = {0.0, 0.0};
  spec.domain_max = {channel_length, channel_width};
  const AnalyticFlow analytic(spec);
  std::unique_ptr<EngineFlow> engine;
  if (field != 0)
    engine = std::make_unique<EngineFlow>(field == 1 ? FlowEngineKind::fem : FlowEngineKind::fv);
  omp_set_num_threads(static_cast<int>(state.range(0)));
  const FlowField& flow =
      engine ? engine->engine->field() : static_cast<const FlowField&>(analytic);
  auto* fem = engine ? dynamic_cast<FemFlowField*>(&engine->engine->field()) : nullptr;
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
    if (fem) fem->pack_states();  // the same states: what a new flow step costs
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
    ->ArgNames({"threads", "drag_points", "steady", "field"})
    ->Args({1, 1, 1, 0})
    ->Args({2, 1, 1, 0})
    ->Args({2, 5, 1, 0})
    ->Args({2, 1, 0, 0})
    ->Args({1, 1, 1, 1})
    ->Args({2, 1, 1, 1})
    ->Args({1, 1, 1, 2})
    ->Args({2, 1, 1, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);

// What the FEM's field pays once per flow step for the bodies: the copy of the two states and
// the bed into the nodes' packs (FemFlowField::pack_states). Arguments: threads, rectangles
// along and across the channel (elements = 2 nx ny).
void BM_PackStates(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  EngineFlow flow(FlowEngineKind::fem, static_cast<int>(state.range(1)),
                  static_cast<int>(state.range(2)), 0);
  omp_set_num_threads(static_cast<int>(state.range(0)));
  auto& field = dynamic_cast<FemFlowField&>(flow.engine->field());
  for (auto _ : state) field.pack_states();
  state.counters["nodes"] = flow.mesh.node_count();
}

BENCHMARK(BM_PackStates)
    ->ArgNames({"threads", "nx", "ny"})
    ->Args({1, 150, 17})
    ->Args({2, 150, 17})
    ->Args({1, 500, 50})
    ->Args({2, 500, 50})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

}  // namespace
}  // namespace flotsam

BENCHMARK_MAIN();
