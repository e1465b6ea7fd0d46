// The finite-volume engine's throughput (docs/performance.md "Finite-volume engine"): a dam
// break onto a dry bed in a square basin, so that wet/dry fronts are on, at about 50k, 500k and
// 2M triangles (cells = the mesh's triangles), first and second order, 1 and 2 threads. A timed
// harness (one run is seconds): triangle-steps per second (one cell advanced one whole
// sub-step, both Runge-Kutta stages), the best of three, and bytes of memory per triangle
// (resident memory the engine adds once it has stepped; the mesh's own given apart). Each
// configuration runs with and without the flood envelopes the engine keeps after every sub-step
// (flow/flood_envelope.hpp, with the hazard of flow/hazard.hpp), alternating, to give their cost
// as a ratio measured side by side. With --orders, the same mesh's cells in the numbering every
// mesh gets (elements in Cuthill-McKee order, mesh/element_order.hpp) and along the Hilbert curve
// (mesh/curve_order.hpp), second order, alternated seven times, medians (docs/performance.md
// "On a Gmsh mesh"): on the rectangle, or on the circular dam break's Gmsh mesh written by
// `flotsam mesh bench/circular_dam_break.yaml -o FILE.msh` (its initial state).
//
//   cmake --build <build> --target bench_fv_dam_break
//   <build>/bench/bench_fv_dam_break [TRIANGLES ...]      (default 50000 500000 2000000)
//   <build>/bench/bench_fv_dam_break --orders [TRIANGLES | FILE.msh] (default 250000)
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <algorithm>

#include "flow/flood_envelope.hpp"
#include "flow/fv/fv_solver.hpp"
#include "mesh/curve_order.hpp"
#include "mesh/msh_reader.hpp"
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

// A 1 km square basin, walls all round, 10 m of water behind a dam at x = 700 m, dry beyond.
Case dam_break_case(int order) {
  Case c;
  c.name = "fv_dam_break_bench";
  c.flow.engine = FlowEngineKind::fv;
  c.flow.fv.order = order;
  c.flow.initial_eta = Expression("x < 700 ? 10 : 0", "bench");
  for (const char* side : {"left", "right", "bottom", "top"}) {
    BoundaryCondition wall;
    wall.group = side;
    c.flow.boundaries.push_back(wall);
  }
  return c;
}

// Each measurement starts from the same state (the dam broken 2 s before, so that the front is
// on the dry bed: about 70 % of the cells wet) and covers the same simulated time: the runs on 1
// and 2 threads do the same work, bit for bit.
void run(int triangles) {
  // cells = the mesh's triangles, 2 per square of the n x n grid
  const int n = std::max(1, static_cast<int>(std::lround(std::sqrt(triangles / 2.0))));
  const long before = resident_kib();
  const Mesh mesh = make_rectangle_mesh({.length = 1000, .width = 1000, .nx = n, .ny = n});
  const long with_mesh = resident_kib();
  for (int order : {1, 2}) {
    const Case c = dam_break_case(order);
    FiniteVolumeSolver solver(mesh, c);
    solver.initialize();
    const double cells = solver.cells().cell_count;
    solver.advance(2.0);
    const long with_engine = resident_kib();
    const ConservedState start = solver.state();
    const double span = 40 * solver.courant_step();  // [s] about 40 sub-steps
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      FloodEnvelope envelope;
      double seconds[2] = {0.0, 0.0};  // [s] without, with the envelopes
      long steps = 0;
      for (int repeat = 0; repeat < 3; ++repeat)  // the best of three, alternating
        for (int with : {0, 1}) {
          solver.set_state(start);
          envelope.reset(solver.cells().cell_count, 0.01);
          solver.set_sub_step_observer(
              with ? std::function<void(double, double)>([&](double t, double dt) {
                const ConservedState& U = solver.state();
                envelope.update(U.h, U.hu, U.hv, t, dt);
              })
                   : nullptr);
          const long count = solver.sub_steps().count;
          const auto t0 = std::chrono::steady_clock::now();
          solver.advance(span);
          const double s =
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          if (repeat == 0 || s < seconds[with]) seconds[with] = s;
          steps = solver.sub_steps().count - count;
        }
      std::printf(
          "%9.0f triangles  order %d  threads %d: %4ld sub-steps in %6.3f s, %6.2f M "
          "triangle-steps/s, %.0f bytes/triangle (mesh %.0f), wet %.0f %%; with the envelopes "
          "%6.3f s (x%.3f)\n",
          cells, order, threads, steps, seconds[0], cells * steps / seconds[0] / 1e6,
          1024.0 * (with_engine - with_mesh) / cells, 1024.0 * (with_mesh - before) / cells,
          100.0 * solver.wet_fraction(), seconds[1], seconds[1] / seconds[0]);
      std::fflush(stdout);
    }
  }
}

// A mesh's cells as build_mesh numbers them against the same cells along the curve: the same 40
// sub-steps of simulated time from the state 2 s after the break, alternated. `what`: a number of
// triangles (the rectangle's dam break) or a .msh file (the circular dam break).
void compare_orders(const std::string& what) {
  const bool file = what.ends_with(".msh");
  const int n =
      file ? 0 : std::max(1, static_cast<int>(std::lround(std::sqrt(std::stoi(what) / 2.0))));
  const Mesh built = file ? read_msh(what)
                          : make_rectangle_mesh({.length = 1000, .width = 1000, .nx = n, .ny = n});
  const Mesh along_curve = ordered_along_curve(built);
  Case c = dam_break_case(2);
  if (file) {  // walls all round (groups without a condition)
    c.flow.boundaries.clear();
    c.flow.initial_eta = Expression("x^2 + y^2 < 100 ? 2 : 1", "bench");  // all wet
  }
  FiniteVolumeSolver a(built, c), b(along_curve, c);
  FiniteVolumeSolver* solvers[2] = {&a, &b};
  ConservedState start[2];
  double span = 0.0;  // [s]
  for (int k = 0; k < 2; ++k) {
    solvers[k]->initialize();
    solvers[k]->advance(2.0);
    start[k] = solvers[k]->state();
    if (k == 0) span = 40 * solvers[k]->courant_step();
  }
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    std::vector<double> rate[2];  // [M triangle-steps/s]
    for (int repeat = 0; repeat < 7; ++repeat)
      for (int k = 0; k < 2; ++k) {
        solvers[k]->set_state(start[k]);
        const long count = solvers[k]->sub_steps().count;
        const auto t0 = std::chrono::steady_clock::now();
        solvers[k]->advance(span);
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const long steps = solvers[k]->sub_steps().count - count;
        rate[k].push_back(solvers[k]->cells().cell_count * static_cast<double>(steps) / s / 1e6);
      }
    double median[2];
    for (int k = 0; k < 2; ++k) {
      std::sort(rate[k].begin(), rate[k].end());
      median[k] = rate[k][rate[k].size() / 2];
    }
    std::printf(
        "%d triangles  threads %d: Cuthill-McKee %.2f M triangle-steps/s (%.2f-%.2f), along the "
        "curve %.2f (%.2f-%.2f), ratio %.3f\n",
        a.cells().cell_count, threads, median[0], rate[0].front(), rate[0].back(), median[1],
        rate[1].front(), rate[1].back(), median[0] / median[1]);
    std::fflush(stdout);
  }
}

}  // namespace
}  // namespace flotsam

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--orders") {
    flotsam::compare_orders(argc > 2 ? argv[2] : "250000");
    return 0;
  }
  std::vector<int> sizes;
  for (int k = 1; k < argc; ++k) sizes.push_back(std::atoi(argv[k]));
  if (sizes.empty()) sizes = {50000, 500000, 2000000};
  for (int triangles : sizes) flotsam::run(triangles);
}
