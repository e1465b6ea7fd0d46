// The finite-volume engine's throughput (docs/performance.md "Finite-volume engine"): a dam
// break onto a dry bed in a square basin, so that wet/dry fronts are on, at about 50k, 500k and
// 2M triangles (cells), first and second order, 1 and 2 threads. A timed harness (one run is
// seconds): triangle-steps per second (one cell advanced one whole sub-step, both Runge-Kutta
// stages) and bytes of memory per triangle (resident memory added by the engine).
//
//   cmake --build <build> --target bench_fv_dam_break
//   <build>/bench/bench_fv_dam_break [TRIANGLES ...]      (default 50000 500000 2000000)
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "flow/fv/fv_solver.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

long resident_kib() {  // VmRSS of this process [KiB]
  std::ifstream status("/proc/self/status");
  std::string key;
  long value = 0;
  while (status >> key) {
    if (key == "VmRSS:") {
      status >> value;
      return value;
    }
    status.ignore(1 << 12, '\n');
  }
  return 0;
}

// A 1 km square basin, walls all round, 10 m of water behind a dam at x = 400 m, dry beyond.
Case dam_break_case(int order) {
  Case c;
  c.name = "fv_dam_break_bench";
  c.flow.engine = FlowEngineKind::fv;
  c.flow.fv.order = order;
  c.flow.initial_eta = Expression("x < 400 ? 10 : 0", "bench");
  for (const char* side : {"left", "right", "bottom", "top"}) {
    BoundaryCondition wall;
    wall.group = side;
    c.flow.boundaries.push_back(wall);
  }
  return c;
}

void run(int triangles) {
  // cells = 4 (sub-triangles) x 2 (triangles per square) x n^2
  const int n = std::max(1, static_cast<int>(std::lround(std::sqrt(triangles / 8.0))));
  const long before = resident_kib();
  const Mesh mesh = make_rectangle_mesh({.length = 1000, .width = 1000, .nx = n, .ny = n});
  const long with_mesh = resident_kib();
  for (int order : {1, 2}) {
    const Case c = dam_break_case(order);
    FiniteVolumeSolver solver(mesh, c);
    solver.initialize();
    solver.advance(solver.courant_step());  // first touch of every array
    const long with_engine = resident_kib();
    const double cells = solver.cells().cell_count;
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      const long steps_before = solver.sub_steps().count;
      const auto start = std::chrono::steady_clock::now();
      double seconds = 0.0;
      while (seconds < 2.0) {  // at least 2 s of work, whole coupling steps of 20 sub-steps
        solver.advance(20 * solver.courant_step());
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      }
      const long steps = solver.sub_steps().count - steps_before;
      std::printf(
          "%9.0f triangles  order %d  threads %d: %6ld sub-steps in %.2f s, %7.2f M "
          "triangle-steps/s, %.0f bytes/triangle (mesh %.0f), wet %.0f %%\n",
          cells, order, threads, steps, seconds, cells * steps / seconds / 1e6,
          1024.0 * (with_engine - with_mesh) / cells, 1024.0 * (with_mesh - before) / cells,
          100.0 * solver.wet_fraction());
      std::fflush(stdout);
    }
  }
}

}  // namespace
}  // namespace flotsam

int main(int argc, char** argv) {
  std::vector<int> sizes;
  for (int k = 1; k < argc; ++k) sizes.push_back(std::atoi(argv[k]));
  if (sizes.empty()) sizes = {50000, 500000, 2000000};
  for (int triangles : sizes) flotsam::run(triangles);
}
