// The flow engine on the paper's channel (spec 8.2, examples/bridge_piers.yaml): a timed harness
// (not Google Benchmark's loop: one run is seconds to minutes). Figures: docs/performance.md
// "Flow engine".
//
//   cmake --build <build> --target bench_flow_channel
//   <build>/bench/bench_flow_channel steady [mesh_size] [viscosity]
//   <build>/bench/bench_flow_channel unsteady DT [T_END] [mesh_size] [state_file] [viscosity]
//   <build>/bench/bench_flow_channel compare STATE_A STATE_B
//   <build>/bench/bench_flow_channel scaling MESH_SIZE STEPS [DT]
//   <build>/bench/bench_flow_channel section STATE X [Y ...]
//   <build>/bench/bench_flow_channel fv MESH_SIZE SECONDS
//
// steady: solve_steady from still water (at the case's viscosity, or the one given [m^2/s]; mesh
// size 0: the case's), wall time, residual history and discharge. unsteady: T_END [s] (default
// 3600) of flow from still water (eta linear 10 -> 9.8 m) at step DT [s], wall time, time per step,
// Newton iterations, the discharge at the end and its mean over the last third; writes the final
// state to state_file when given ("-": none) and the time-mean over the last third (eta, and |u| as
// u with v = 0) to state_file.mean; viscosity [m^2/s] replaces the case's when given. compare: max
// |(eta - eta_out)_A - (eta - eta_out)_B| / max |eta - eta_out|_B and the same for |u| of two saved
// states of the same mesh. scaling: STEPS steps at DT (default 1 s) on the channel with far-field
// size MESH_SIZE [m] (pier size and refinement distance scaled with it): time per step and peak
// memory (getrusage ru_maxrss). section: eta, u, v of a saved state (of the case's own mesh) every
// 5 m across the channel at x = X [m], or at the given Y [m] only (gauges). fv: the finite-volume
// engine on the scaling's mesh, SECONDS s of flow after the first (advanced a second at a time):
// CPU time per simulated second and per Courant sub-step, peak memory. OMP_NUM_THREADS sets the
// threads; FLOTSAM_FLOW_ITERATIONS=n the Newton iterations per step (unsteady),
// FLOTSAM_FLOW_SOLVER=klu KLU instead of UMFPACK (scaling), FLOTSAM_FLOW_REUSE_LU=1|0 the LU kept
// across solves as the approximate inverse of an iterative refinement, or not (all modes; unset:
// FlowSolverOptions' default), FLOTSAM_FLOW_SCHEME=coupled|segregated the step (flow.scheme; all
// modes but steady), FLOTSAM_FLOW_TIME_SCHEME=bdf2|theta the time scheme and
// FLOTSAM_FLOW_TURBULENCE=none|smagorinsky|mixing-length the eddy viscosity (all modes; unset:
// the case's: the segregated step with the mixing length), FLOTSAM_FLOW_TRACE=S a line every S
// seconds of simulated time with the discharges and the fastest node (unsteady); every mode prints
// the linear solver's counts.
#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "flow/fem/shallow_water_solver.hpp"
#include "flow/fv/fv_solver.hpp"
#include "mesh/interpolation.hpp"
#include "mesh/point_locator.hpp"
#include "paper_channel.hpp"

namespace flotsam {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// CPU time of the process so far [s] (user + system): with one thread, the wall time an idle
// machine would show, which a loaded one does not.
double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

double peak_memory_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

void write_state(const std::string& path, const FlowState& s) {
  std::ofstream out(path, std::ios::binary);
  const auto write = [&](const std::vector<double>& v) {
    const size_t n = v.size();
    out.write(reinterpret_cast<const char*>(&n), sizeof n);
    out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(n * 8));
  };
  write(s.eta);
  write(s.u);
  write(s.v);
}

FlowState read_state(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read the state file " + path);
  const auto read = [&](std::vector<double>& v) {
    size_t n = 0;
    in.read(reinterpret_cast<char*>(&n), sizeof n);
    if (!in || n > (size_t{1} << 32)) throw std::runtime_error(path + ": not a saved state");
    v.resize(n);
    in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * 8));
  };
  FlowState s;
  read(s.eta);
  read(s.u);
  read(s.v);
  return s;
}

// FLOTSAM_FLOW_REUSE_LU=1|0: the LU kept across solves or not (unset: the options' default).
void set_reuse_from_environment(FlowSolverOptions& options) {
  if (const char* e = std::getenv("FLOTSAM_FLOW_REUSE_LU"))
    options.reuse_factorisation = std::string(e) == "1";
}

// FLOTSAM_FLOW_SCHEME, FLOTSAM_FLOW_TIME_SCHEME and FLOTSAM_FLOW_TURBULENCE replace the case's;
// false, with a message, for any other value.
bool set_case_from_environment(Case& c) {
  if (const char* e = std::getenv("FLOTSAM_FLOW_SCHEME")) {
    const std::string scheme = e;
    if (scheme != "coupled" && scheme != "segregated") {
      std::fprintf(stderr, "FLOTSAM_FLOW_SCHEME=%s: expected coupled or segregated\n", e);
      return false;
    }
    c.flow.scheme = scheme == "segregated" ? FlowScheme::segregated : FlowScheme::coupled;
  }
  if (const char* e = std::getenv("FLOTSAM_FLOW_TIME_SCHEME")) {
    const std::string scheme = e;
    if (scheme != "bdf2" && scheme != "theta") {
      std::fprintf(stderr, "FLOTSAM_FLOW_TIME_SCHEME=%s: expected bdf2 or theta\n", e);
      return false;
    }
    c.time.scheme = scheme == "bdf2" ? TimeScheme::bdf2 : TimeScheme::theta;
  }
  if (const char* e = std::getenv("FLOTSAM_FLOW_TURBULENCE")) {
    const std::string model = e;
    if (model == "none") {
      c.flow.turbulence = TurbulenceModel::none;
    } else if (model == "smagorinsky") {
      c.flow.turbulence = TurbulenceModel::smagorinsky;
    } else if (model == "mixing-length") {
      c.flow.turbulence = TurbulenceModel::mixing_length;
    } else {
      std::fprintf(stderr,
                   "FLOTSAM_FLOW_TURBULENCE=%s: expected none, smagorinsky or mixing-length\n", e);
      return false;
    }
  }
  return true;
}

void print_linear_solver_counts(const ShallowWaterSolver& solver) {
  const auto& counts = solver.linear_solver_counts();
  std::printf(
      "linear solves %ld: %ld factorisations, %ld refinement iterations with a reused LU, %ld "
      "refactorisations after the refinement stalled\n",
      counts.solves, counts.factorisations, counts.refinement_iterations,
      counts.refinement_failures);
  if (const SegregatedStep* segregated = solver.segregated_step())
    std::printf(
        "segregated: %ld GMRES iterations of the elevation system, %ld Cholesky factorisations, "
        "%ld CG iterations of the momentum predictor (u and v), %ld incomplete factorisations\n",
        segregated->elevation_iterations(), segregated->factorisations(),
        segregated->momentum_iterations(), segregated->predictor_factorisations());
}

int run_steady(double mesh_size, double viscosity) {
  Case c = paper_channel_case(mesh_size);
  if (viscosity > 0.0) c.flow.viscosity = viscosity;
  if (!set_case_from_environment(c)) return 2;
  const Mesh mesh = paper_channel_mesh(c);
  FlowSolverOptions options;
  set_reuse_from_environment(options);
  ShallowWaterSolver solver(mesh, c, options);
  const auto start = Clock::now();
  solver.initialize();
  const SteadyReport report = solver.solve_steady();
  const double wall = seconds_since(start);
  std::printf(
      "steady: %d elements, %d threads, nu %g m^2/s: converged %d after %d iterations, %.3f s "
      "wall; lowest viscosity reached %g m^2/s\n",
      mesh.element_count(), omp_get_max_threads(), c.flow.viscosity, report.converged ? 1 : 0,
      report.iterations, wall, report.viscosity);
  for (size_t k = 0; k < report.residuals.size(); ++k)
    std::printf("  %zu nu %.4g: %.3e\n", k, report.viscosities[k], report.residuals[k]);
  const auto& rate = solver.water_balance().group_rate;  // [m^3/s] out
  std::printf("peak memory %.1f MiB; discharge in %.2f m^3/s, out %.2f m^3/s\n", peak_memory_mib(),
              -rate[mesh.find_group("inflow")], rate[mesh.find_group("outflow")]);
  print_linear_solver_counts(solver);
  return report.converged ? 0 : 1;
}

// t, discharge in and out, and the fastest node with its velocity (FLOTSAM_FLOW_TRACE).
void print_trace(const ShallowWaterSolver& solver, double inflow_rate, double outflow_rate) {
  const auto& u = solver.u();
  const auto& v = solver.v();
  size_t fastest = 0;
  for (size_t i = 0; i < u.size(); ++i)
    if (std::hypot(u[i], v[i]) > std::hypot(u[fastest], v[fastest])) fastest = i;
  const Vec2& p = solver.mesh().nodes[fastest];
  std::printf(
      "t %.0f s: discharge in %.1f, out %.1f m^3/s; fastest %.3f m/s at (%.1f, %.1f), u %.2f v "
      "%.2f\n",
      solver.time(), -inflow_rate, outflow_rate, std::hypot(u[fastest], v[fastest]), p.x(), p.y(),
      u[fastest], v[fastest]);
  std::fflush(stdout);
}

int run_unsteady(double dt, double t_end, double mesh_size, const std::string& state_file,
                 double viscosity) {
  Case c = paper_channel_case(mesh_size);
  if (viscosity > 0.0) c.flow.viscosity = viscosity;
  const Mesh mesh = paper_channel_mesh(c);
  FlowSolverOptions options;
  if (const char* e = std::getenv("FLOTSAM_FLOW_ITERATIONS")) options.max_iterations = std::atoi(e);
  if (!set_case_from_environment(c)) return 2;
  const char* trace = std::getenv("FLOTSAM_FLOW_TRACE");
  const double trace_interval = trace ? std::atof(trace) : 0.0;  // [s]
  set_reuse_from_environment(options);
  ShallowWaterSolver solver(mesh, c, options);
  const auto start = Clock::now();
  const double cpu_start = cpu_seconds();
  solver.initialize();
  const int steps = static_cast<int>(std::lround(t_end / dt));
  long iterations = 0;
  const auto& rate = solver.water_balance().group_rate;  // [m^3/s] out, last step
  const int inflow = mesh.find_group("inflow");
  double mean_in = 0.0, mean_time = 0.0;  // discharge in averaged over the last third [m^3/s]
  // The time-mean over the last third: eta [m] per vertex and |u| [m/s] per node (in u; v = 0).
  FlowState mean{t_end, std::vector<double>(mesh.vertex_count, 0.0),
                 std::vector<double>(mesh.node_count(), 0.0),
                 std::vector<double>(mesh.node_count(), 0.0)};
  for (int n = 0; n < steps; ++n) {
    iterations += solver.step(dt).iterations;
    if (trace_interval > 0.0 && std::fmod(solver.time() + 1e-9, trace_interval) < dt)
      print_trace(solver, rate[inflow], rate[mesh.find_group("outflow")]);
    if (3 * (n + 1) > 2 * steps) {
      mean_in -= dt * rate[inflow];
      mean_time += dt;
      for (int j = 0; j < mesh.vertex_count; ++j) mean.eta[j] += dt * solver.eta()[j];
      for (int i = 0; i < mesh.node_count(); ++i)
        mean.u[i] += dt * std::hypot(solver.u()[i], solver.v()[i]);
    }
  }
  const double wall = seconds_since(start), cpu = cpu_seconds() - cpu_start;
  std::printf(
      "unsteady: %s, %d elements, %d threads, dt %g s, %d steps to t = %g s: %.2f s wall (%.2f s "
      "CPU), %.2f ms per step, %.2f Newton iterations per step, balance %.2e, peak memory %.1f "
      "MiB\n",
      c.flow.scheme == FlowScheme::segregated ? "segregated" : "coupled", mesh.element_count(),
      omp_get_max_threads(), dt, steps, solver.time(), wall, cpu, 1e3 * wall / steps,
      static_cast<double>(iterations) / steps, solver.water_balance().relative_error(),
      peak_memory_mib());
  std::printf(
      "discharge in %.2f m^3/s, out %.2f m^3/s at the end; in %.2f m^3/s on average over "
      "the last third\n",
      -rate[inflow], rate[mesh.find_group("outflow")], mean_in / mean_time);
  print_linear_solver_counts(solver);
  if (!state_file.empty() && state_file != "-") {
    write_state(state_file, solver.state());
    for (double& eta : mean.eta) eta /= mean_time;
    for (double& speed : mean.u) speed /= mean_time;
    write_state(state_file + ".mean", mean);
  }
  return 0;
}

int run_compare(const std::string& a_file, const std::string& b_file) {
  const FlowState a = read_state(a_file), b = read_state(b_file);
  if (a.eta.size() != b.eta.size() || a.u.size() != b.u.size())
    throw std::runtime_error(a_file + " and " + b_file + " are states of different meshes");
  const double eta_out = 9.8;  // [m] the outflow level of examples/bridge_piers.yaml
  double d_eta = 0.0, m_eta = 0.0, d_u = 0.0, m_u = 0.0;
  for (size_t j = 0; j < b.eta.size(); ++j) {
    d_eta = std::max(d_eta, std::abs(a.eta[j] - b.eta[j]));
    m_eta = std::max(m_eta, std::abs(b.eta[j] - eta_out));
  }
  for (size_t i = 0; i < b.u.size(); ++i) {
    const double speed_a = std::hypot(a.u[i], a.v[i]), speed_b = std::hypot(b.u[i], b.v[i]);
    d_u = std::max(d_u, std::abs(speed_a - speed_b));
    m_u = std::max(m_u, speed_b);
  }
  std::printf("eta - eta_out: max difference %.3e m of max %.3e m (%.3f %%)\n", d_eta, m_eta,
              100 * d_eta / m_eta);
  std::printf("|u|: max difference %.3e m/s of max %.3e m/s (%.3f %%)\n", d_u, m_u,
              100 * d_u / m_u);
  return 0;
}

// eta, u and v of a saved state at 35 points every 5 m across the channel at x [m], or at ys
// [m] when given.
int run_section(const std::string& file, double x, std::vector<double> ys) {
  const FlowState state = read_state(file);
  const Case c = paper_channel_case(0.0);
  const Mesh mesh = paper_channel_mesh(c);
  if (state.u.size() != static_cast<size_t>(mesh.node_count()))
    throw std::runtime_error(file + " is not a state of the case's own mesh");
  const PointLocator locator(mesh);
  if (ys.empty())
    for (int k = 0; k <= 34; ++k) ys.push_back(5.0 * k);
  for (double y_k : ys) {
    const double y = std::clamp(y_k, 1e-6, c.mesh.channel.width - 1e-6);  // [m]
    const Location at = locator.locate(Vec2(x, y));
    if (!at.inside) continue;
    const Vec2 u = interpolate_p2(mesh, at, state.u, state.v);
    std::printf("x %7.1f y %6.1f: eta %.4f m, u %.3f, v %.3f m/s\n", x, y,
                interpolate_p1(mesh, at, state.eta), u.x(), u.y());
  }
  return 0;
}

int run_scaling(double mesh_size, int steps, double dt) {
  Case c = paper_channel_case(mesh_size, true);
  if (!set_case_from_environment(c)) return 2;
  const auto mesh_start = Clock::now();
  const Mesh mesh = paper_channel_mesh(c);
  const double mesh_wall = seconds_since(mesh_start);
  FlowSolverOptions options;
  const char* kind = std::getenv("FLOTSAM_FLOW_SOLVER");
  if (kind && std::string(kind) == "klu") options.linear_solver = LinearSolverKind::klu;
  set_reuse_from_environment(options);
  ShallowWaterSolver solver(mesh, c, options);
  const auto setup_start = Clock::now();
  solver.initialize();
  const double setup_wall = seconds_since(setup_start);
  solver.step(dt);  // the first step holds the symbolic analysis
  const auto start = Clock::now();
  const double cpu_start = cpu_seconds();
  long iterations = 0;
  for (int n = 0; n < steps; ++n) iterations += solver.step(dt).iterations;
  const double wall = seconds_since(start), cpu = cpu_seconds() - cpu_start;
  std::printf(
      "scaling: %s, mesh_size %g m, %d elements, %d unknowns, %d threads: mesh %.2f s, setup "
      "%.2f s, %.1f ms per step (%.1f ms CPU; %.2f iterations per step), peak memory %.1f MiB\n",
      c.flow.scheme == FlowScheme::segregated ? "segregated" : "coupled", mesh_size,
      mesh.element_count(), 2 * mesh.node_count() + mesh.vertex_count, omp_get_max_threads(),
      mesh_wall, setup_wall, 1e3 * wall / steps, 1e3 * cpu / steps,
      static_cast<double>(iterations) / steps, peak_memory_mib());
  print_linear_solver_counts(solver);
  return 0;
}

int run_fv(double mesh_size, int seconds) {
  Case c = paper_channel_case(mesh_size, true);
  c.flow.engine = FlowEngineKind::fv;
  const auto mesh_start = Clock::now();
  const Mesh mesh = paper_channel_mesh(c);
  const double mesh_wall = seconds_since(mesh_start);
  FiniteVolumeSolver solver(mesh, c);
  solver.initialize();
  solver.advance(1.0);
  const long sub_steps = solver.sub_steps().count;
  const auto start = Clock::now();
  const double cpu_start = cpu_seconds();
  for (int s = 0; s < seconds; ++s) solver.advance(1.0);
  const double wall = seconds_since(start), cpu = cpu_seconds() - cpu_start;
  const long taken = solver.sub_steps().count - sub_steps;
  std::printf(
      "fv: mesh_size %g m, %d elements, %d threads: mesh %.2f s, %.1f ms per simulated second "
      "(%.1f ms CPU; %.1f sub-steps, %.3f ms CPU each), peak memory %.1f MiB\n",
      mesh_size, mesh.element_count(), omp_get_max_threads(), mesh_wall, 1e3 * wall / seconds,
      1e3 * cpu / seconds, static_cast<double>(taken) / seconds,
      1e3 * cpu / static_cast<double>(std::max(taken, 1L)), peak_memory_mib());
  return 0;
}

}  // namespace
}  // namespace flotsam

int main(int argc, char** argv) {
  using namespace flotsam;
  const std::vector<std::string> args(argv + 1, argv + argc);
  const auto number = [&](size_t k, double fallback) {
    return args.size() > k ? std::atof(args[k].c_str()) : fallback;
  };
  try {
    if (!args.empty() && args[0] == "steady") return run_steady(number(1, 0.0), number(2, 0.0));
    if (args.size() >= 2 && args[0] == "unsteady")
      return run_unsteady(number(1, 1.0), number(2, 3600.0), number(3, 0.0),
                          args.size() > 4 ? args[4] : "", number(5, 0.0));
    if (args.size() >= 3 && args[0] == "compare") return run_compare(args[1], args[2]);
    if (args.size() >= 3 && args[0] == "section") {
      std::vector<double> ys;
      for (size_t k = 3; k < args.size(); ++k) ys.push_back(number(k, 0.0));
      return run_section(args[1], number(2, 20.0), ys);
    }
    if (args.size() >= 3 && args[0] == "scaling")
      return run_scaling(number(1, 14.5), static_cast<int>(number(2, 10)), number(3, 1.0));
    if (args.size() >= 3 && args[0] == "fv")
      return run_fv(number(1, 14.5), static_cast<int>(number(2, 10)));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  std::fprintf(stderr, "usage: see the comment at the top of bench/flow_channel.cpp\n");
  return 1;
}
