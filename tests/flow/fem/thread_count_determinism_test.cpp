// Verifies that the flow state does not depend on the number of OpenMP threads (issue 3 item 2:
// "same result for 1 and 2 threads"): element colours share no node, so every matrix entry is
// summed in the same order whatever the threads, and the direct solvers' BLAS runs on one thread
// (serial_blas.hpp). A few steps of an unsteady flow with every term that depends on the state
// (advection, Manning, Smagorinsky, hydrograph inflow) on 1 thread and on 2 threads (one every
// other step) give bit-identical states (exact comparison, tolerance 0), with either step. The mesh
// is fine enough (3,840 elements) for the factors' dense blocks to pass OpenBLAS's threshold for a
// second thread: on the 240 elements this test had before, it passed with a threaded BLAS too.
#include <gtest/gtest.h>
#include <omp.h>

#include <vector>

#include "../../support/flow_schemes.hpp"
#include "core/thread_governor.hpp"
#include "flow/fem/shallow_water_solver.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

// Step n on threads[n % threads.size()] threads.
FlowState run_on_threads(const Mesh& mesh, const Case& c, const std::vector<int>& threads) {
  const ThreadCountScope restore(threads.front());
  FlowSolverOptions options;
  options.parallel_min_colour = 1;  // every colour in parallel, however small
  ShallowWaterSolver solver(mesh, c, options);
  solver.initialize();
  for (std::size_t n = 0; n < 4; ++n) {
    omp_set_num_threads(threads[n % threads.size()]);
    solver.step(5.0);
  }
  return solver.state();
}

class ThreadCountDeterminism : public testing::TestWithParam<FlowScheme> {};

TEST_P(ThreadCountDeterminism, OneAndTwoThreadsGiveBitIdenticalStates) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 200.0, 40.0, 80, 24, true});
  Case c;
  c.flow.scheme = GetParam();
  c.flow.initial_eta_start = c.flow.initial_eta_end = 2.0;  // [m] over a flat bed
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = 0.03;  // [s m^-1/3]
  c.flow.turbulence = TurbulenceModel::smagorinsky;
  c.flow.boundaries = {
      {BoundaryCondition::Kind::discharge, "left", TimeSeries({{0.0, 0.0}, {20.0, 30.0}}), {}},
      {BoundaryCondition::Kind::elevation, "right", TimeSeries(2.0), {}}};
  // Two threads, and one every other step as `flotsam run` may choose on a shared machine
  // (core/thread_governor.hpp): the state a 2-thread step leaves goes on on one thread.
  const FlowState one = run_on_threads(mesh, c, {1});
  const FlowState two = run_on_threads(mesh, c, {2, 1});
  ASSERT_GT(std::abs(one.u[0]) + std::abs(one.eta[0] - 2.0), 0.0);  // the flow has moved
  EXPECT_EQ(one.eta, two.eta);
  EXPECT_EQ(one.u, two.u);
  EXPECT_EQ(one.v, two.v);
}

// The segregated step's element sweeps and characteristics run on the threads, its solves serial.
INSTANTIATE_TEST_SUITE_P(FlowSchemes, ThreadCountDeterminism, test::both_flow_schemes,
                         test::flow_scheme_name);

}  // namespace
}  // namespace flotsam
