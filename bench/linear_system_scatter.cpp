// The scatter of element matrices into the flow system (LinearSystem::add, spec 1): every
// element's 15 x 15 matrix and 15-vector added into the global pattern, in the engine's order
// (coloured blocks of elements, element_blocks.hpp) in one thread, on the paper's channel
// (examples/bridge_piers.yaml) at far-field mesh size 14.5 m (4.5k elements) and 4.4 m (35k
// elements).
//
//   cmake --build <build> --target bench_linear_system_scatter
//   <build>/bench/bench_linear_system_scatter --benchmark_min_time=0.5
//
// scatter_by_search is the scatter as it was before the stored block positions, for comparison.
// Each iteration is one whole scatter (set_zero not included); the counter `per_element` is
// its time per element. Figures: docs/performance.md "Flow engine".
#include <benchmark/benchmark.h>

#include <algorithm>
#include <map>

#include "flow/fem/element_blocks.hpp"
#include "flow/fem/linear_system.hpp"
#include "paper_channel.hpp"

namespace flotsam {
namespace {

// The channel's mesh at far-field size mesh_size [m], generated once per size.
const Mesh& channel_mesh(double mesh_size) {
  static std::map<double, Mesh> meshes;
  auto found = meshes.find(mesh_size);
  if (found != meshes.end()) return found->second;
  Mesh mesh = paper_channel_mesh(paper_channel_case(mesh_size, true));
  return meshes.emplace(mesh_size, std::move(mesh)).first->second;
}

// What both scatters add: the system of the mesh of far-field size range(0) / 10 m, its coloured
// element blocks, and one random element matrix and vector.
struct Scatter {
  explicit Scatter(const benchmark::State& state)
      : mesh(channel_mesh(static_cast<double>(state.range(0)) / 10.0)),
        blocks(element_blocks(mesh)) {
    system.setup(mesh, {}, {});
  }
  // After the timed loop: keeps the sums alive and reports the time per element.
  void report(benchmark::State& state) const {
    benchmark::DoNotOptimize(system.A.valuePtr()[0]);
    state.counters["elements"] = mesh.element_count();
    state.counters["per_element"] = benchmark::Counter(
        static_cast<double>(mesh.element_count()),
        benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  }

  const Mesh& mesh;
  LinearSystem system;
  ElementBlocks blocks;
  LocalMatrix K = LocalMatrix::Random();
  LocalVector F = LocalVector::Random();
};

void scatter(benchmark::State& state) {
  Scatter s(state);
  for (auto _ : state)
    for (const auto& colour : s.blocks.colours)
      for (const auto& block : colour)
        for (int e = block[0]; e < block[1]; ++e)
          s.system.add(e, s.system.element_rows(s.mesh, e), s.K, s.F);
  s.report(state);
}
BENCHMARK(scatter)->Arg(145)->Arg(44)->Unit(benchmark::kMillisecond);

// For comparison, the scatter before the stored block positions: a binary search in the column
// for each of the 225 entries.
void scatter_by_search(benchmark::State& state) {
  Scatter s(state);
  const int* outer = s.system.A.outerIndexPtr();
  const int* inner = s.system.A.innerIndexPtr();
  double* values = s.system.A.valuePtr();
  for (auto _ : state)
    for (const auto& colour : s.blocks.colours)
      for (const auto& block : colour)
        for (int e = block[0]; e < block[1]; ++e) {
          const auto rows = s.system.element_rows(s.mesh, e);
          for (int j = 0; j < 15; ++j)
            for (int i = 0; i < 15; ++i)
              values[std::lower_bound(inner + outer[rows[j]], inner + outer[rows[j] + 1], rows[i]) -
                     inner] += s.K(i, j);
          for (int i = 0; i < 15; ++i) s.system.b[rows[i]] += s.F(i);
        }
  s.report(state);
}
BENCHMARK(scatter_by_search)->Arg(145)->Arg(44)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace flotsam

BENCHMARK_MAIN();
