// Point location (spec 4.4): the neighbour walk from the last element (warm), from the bucket
// grid (cold), and a scan of all elements (brute force), on the holey rectangle of the tests
// (tests/mesh/holey_mesh.hpp) at 36 cells per metre: 206,960 P2 triangles.
//
//   cmake --build <build> --target bench_point_location
//   <build>/bench/bench_point_location --benchmark_min_time=0.2
//
// Each iteration is one query; the counter `steps` is the average number of elements stepped
// across (plus elements tested in a bucket) per query. Figures: docs/performance.md.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "../tests/mesh/holey_mesh.hpp"
#include "mesh/point_locator.hpp"

namespace flotsam {
namespace {

constexpr int cells_per_metre = 36;
constexpr double cell = 1.0 / cells_per_metre;  // [m] element size (legs of the triangles)

const Mesh& bench_mesh() {
  static const Mesh mesh = fixtures::make_holey_mesh(cells_per_metre);
  return mesh;
}

const PointLocator& bench_locator() {
  static const PointLocator locator(bench_mesh());
  return locator;
}

// Points spread uniformly over the box [0, 12] x [0, 8] m (about 17 % in the holes).
std::vector<Vec2> random_points(int count) {
  std::mt19937 random(1);
  std::uniform_real_distribution<double> x(0.0, 12.0), y(0.0, 8.0);
  std::vector<Vec2> points(count);
  for (Vec2& p : points) p = Vec2(x(random), y(random));
  return points;
}

// Bodies scattered over the domain, each moving 0.3 element sizes per step in a straight line,
// turned to a random direction when the next position would leave the domain. Queried step by
// step, body after body, as a simulation does: positions[step * bodies + body].
std::vector<Vec2> moving_points(int bodies, int steps) {
  const PointLocator& locator = bench_locator();
  std::mt19937 random(2);
  std::uniform_real_distribution<double> angle(0.0, 2 * std::numbers::pi);
  std::vector<Vec2> start;
  for (const Vec2& p : random_points(4 * bodies))
    if (static_cast<int>(start.size()) < bodies && locator.locate(p).inside) start.push_back(p);
  std::vector<Vec2> positions(static_cast<std::size_t>(bodies) * steps);
  for (int b = 0; b < bodies; ++b) {
    Vec2 p = start[b];
    double a = angle(random);
    for (int step = 0; step < steps; ++step) {
      Vec2 next = p + 0.3 * cell * Vec2(std::cos(a), std::sin(a));
      while (!locator.locate(next).inside) {
        a = angle(random);
        next = p + 0.3 * cell * Vec2(std::cos(a), std::sin(a));
      }
      positions[static_cast<std::size_t>(step) * bodies + b] = p = next;
    }
  }
  return positions;
}

void report(benchmark::State& state, long steps) {
  state.counters["steps"] =
      benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kAvgIterations);
  state.counters["elements"] = bench_mesh().element_count();
}

void BM_WalkWarm(benchmark::State& state) {
  const PointLocator& locator = bench_locator();
  const int bodies = 4096, steps = 32;
  static const std::vector<Vec2> positions = moving_points(bodies, steps);
  std::vector<int> hint(bodies, -1);
  for (int b = 0; b < bodies; ++b) hint[b] = locator.locate(positions[b]).element;
  long total = 0;
  std::size_t i = 0;
  for (auto _ : state) {
    const int b = static_cast<int>(i % bodies);
    const Location location = locator.locate(positions[i], hint[b]);
    hint[b] = location.element;
    total += location.steps;
    benchmark::DoNotOptimize(location);
    if (++i == positions.size()) i = 0;  // the wrap jumps back: one long walk per body
  }
  report(state, total);
}
BENCHMARK(BM_WalkWarm);

void BM_ColdGrid(benchmark::State& state) {
  const PointLocator& locator = bench_locator();
  static const std::vector<Vec2> points = random_points(1 << 16);
  long total = 0;
  std::size_t i = 0;
  for (auto _ : state) {
    const Location location = locator.locate(points[i]);
    total += location.steps;
    benchmark::DoNotOptimize(location);
    if (++i == points.size()) i = 0;
  }
  report(state, total);
}
BENCHMARK(BM_ColdGrid);

void BM_BruteForce(benchmark::State& state) {
  const PointLocator& locator = bench_locator();
  static const std::vector<Vec2> points = random_points(1 << 10);
  long total = 0;
  std::size_t i = 0;
  for (auto _ : state) {
    const Location location = locator.locate_brute_force(points[i]);
    total += location.steps;
    benchmark::DoNotOptimize(location);
    if (++i == points.size()) i = 0;
  }
  report(state, total);
}
BENCHMARK(BM_BruteForce)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace flotsam

BENCHMARK_MAIN();
