// The scatter of element matrices into the flow system (LinearSystem::add, spec 1): every
// element's 15 x 15 matrix and 15-vector added into the global pattern, colour by colour in one
// thread as the engine does, on the paper's channel (examples/bridge_piers.yaml) at far-field
// mesh size 14.5 m (4.5k elements) and 4.4 m (35k elements).
//
//   cmake --build <build> --target bench_linear_system_scatter
//   <build>/bench/bench_linear_system_scatter --benchmark_min_time=0.5
//
// scatter_by_search is the scatter as it was before the stored block positions, for comparison.
// Each iteration is one whole scatter (set_zero not included); the counter `per_element` is
// its time per element. Figures: docs/performance.md "Flow engine".
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <map>

#include "flow/linear_system.hpp"
#include "io/case_file.hpp"
#include "mesh/mesh_generator.hpp"

namespace flotsam {
namespace {

const Mesh& channel_mesh(double mesh_size) {  // [m]
  static std::map<double, Mesh> meshes;
  auto found = meshes.find(mesh_size);
  if (found != meshes.end()) return found->second;
  Case c = read_case(FLOTSAM_SOURCE_DIR "/examples/bridge_piers.yaml");
  const double scale = mesh_size / c.mesh.channel.mesh_size;
  c.mesh.channel.mesh_size = mesh_size;
  c.mesh.channel.pier_mesh_size *= scale;
  c.mesh.channel.refine_distance *= mesh_size / 14.5;
  const int threads = omp_get_max_threads();
  Mesh mesh = generate_mesh(c.mesh);
  omp_set_num_threads(threads);  // Gmsh sets its own
  return meshes.emplace(mesh_size, std::move(mesh)).first->second;
}

void scatter(benchmark::State& state) {
  const Mesh& mesh = channel_mesh(static_cast<double>(state.range(0)) / 10.0);
  LinearSystem system;
  system.setup(mesh, {}, {});
  const auto colours = element_colours(mesh);
  LocalMatrix K = LocalMatrix::Random();
  LocalVector F = LocalVector::Random();
  for (auto _ : state)
    for (const auto& colour : colours)
      for (int e : colour) system.add(e, system.element_rows(mesh, e), K, F);
  benchmark::DoNotOptimize(system.A.valuePtr()[0]);
  state.counters["elements"] = mesh.element_count();
  state.counters["per_element"] = benchmark::Counter(
      static_cast<double>(mesh.element_count()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(scatter)->Arg(145)->Arg(44)->Unit(benchmark::kMillisecond);

// For comparison, the scatter before the stored block positions: a binary search in the column
// for each of the 225 entries.
void scatter_by_search(benchmark::State& state) {
  const Mesh& mesh = channel_mesh(static_cast<double>(state.range(0)) / 10.0);
  LinearSystem system;
  system.setup(mesh, {}, {});
  const auto colours = element_colours(mesh);
  LocalMatrix K = LocalMatrix::Random();
  LocalVector F = LocalVector::Random();
  const int* outer = system.A.outerIndexPtr();
  const int* inner = system.A.innerIndexPtr();
  double* values = system.A.valuePtr();
  for (auto _ : state)
    for (const auto& colour : colours)
      for (int e : colour) {
        const auto rows = system.element_rows(mesh, e);
        for (int j = 0; j < 15; ++j)
          for (int i = 0; i < 15; ++i)
            values[std::lower_bound(inner + outer[rows[j]], inner + outer[rows[j] + 1], rows[i]) -
                   inner] += K(i, j);
        for (int i = 0; i < 15; ++i) system.b[rows[i]] += F(i);
      }
  benchmark::DoNotOptimize(system.A.valuePtr()[0]);
  state.counters["elements"] = mesh.element_count();
  state.counters["per_element"] = benchmark::Counter(
      static_cast<double>(mesh.element_count()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(scatter_by_search)->Arg(145)->Arg(44)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace flotsam

BENCHMARK_MAIN();
