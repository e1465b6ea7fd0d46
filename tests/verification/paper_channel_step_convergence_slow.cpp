// ctest-label: slow
// Verifies that the paper's channel (examples/bridge_piers.yaml) gives the same answer at the
// examples' step as at dt = 0.1 s (issue 19 item 3), on a shortened channel: the first 750 m of
// the reach with its first bridge (two piers of radius 30 m at x = 300 m), the same slope
// (eta 10 m in, 9.9 m out), mesh sizes, friction and viscosity (Re = 1000), from still water
// for 1,200 s. Compared over the last 600 s (the flow is still accelerating, so the comparison
// covers the transient as well as the eddying flow behind the piers):
//   - the mean inflow discharge [m^3/s] within 2 % of the dt = 0.1 s run's;
//   - the mean surface at four gauges one pier diameter upstream of the bridge (x = 250 m; y =
//     10, 42.5, 85, 127.5 m: bank gap, pier axis, middle gap, pier axis) within 2 % of the 0.1 m
//     fall over the reach (2 mm; 2 % of the depth, 20 cm, would be the whole fall).
// The examples' case as it is (the segregated step with the paper's mixing length) there and on
// the whole channel (1 h, the last 20 minutes, gauges one pier diameter upstream of both
// bridges, 2 % of its 0.2 m fall); and on the shortened channel without the closure, both steps
// (flow.scheme) with the theta-scheme and the segregated step with BDF2, each against its own
// dt = 0.1 s run.
// docs/validation.md "Step convergence on the paper's channel" has the figures.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <string>
#include <vector>

#include "../support/time_schemes.hpp"
#include "flow/fem/shallow_water_solver.hpp"
#include "io/case_file.hpp"
#include "mesh/interpolation.hpp"
#include "mesh/mesh_generator.hpp"
#include "mesh/point_locator.hpp"

namespace flotsam {
namespace {

constexpr double reference_step = 0.1;  // [s] the paper's step

// A reach, how long it runs, the window at its end over which the means are taken, and its
// gauges.
struct Reach {
  Case c;
  double t_end, window;      // [s]
  std::vector<Vec2> gauges;  // [m]
  double fall;               // [m] eta in - eta out
};

constexpr std::array<double, 4> gauge_y{10.0, 42.5, 85.0, 127.5};  // [m]

std::vector<Vec2> gauges_at(std::initializer_list<double> xs) {
  std::vector<Vec2> g;
  for (double x : xs)
    for (double y : gauge_y) g.emplace_back(x, y);
  return g;
}

// The first 750 m with the first bridge (at x = 300 m), 1,200 s, the last 600 s.
Reach shortened_channel() {
  Reach r{read_case(FLOTSAM_SOURCE_DIR "/examples/bridge_piers.yaml"), 1200.0, 600.0,
          gauges_at({250.0}), 0.1};
  Case& c = r.c;
  c.mesh.channel.length = 750.0;
  c.mesh.channel.piers = {{.centre = Vec2(300.0, 42.5), .radius = 30.0},
                          {.centre = Vec2(300.0, 127.5), .radius = 30.0}};
  std::erase_if(c.flow.boundaries,
                [](const auto& b) { return b.group == "pier_3" || b.group == "pier_4"; });
  for (auto& b : c.flow.boundaries)
    if (b.group == "outflow") b.value = TimeSeries(10.0 - r.fall);  // [m] the same slope
  c.flow.initial_eta_end = 10.0 - r.fall;
  return r;
}

// The whole channel as the example has it, one hour, the last 20 minutes; gauges one pier
// diameter upstream of each bridge.
Reach whole_channel() {
  return {read_case(FLOTSAM_SOURCE_DIR "/examples/bridge_piers.yaml"), 3600.0, 1200.0,
          gauges_at({550.0, 850.0}), 0.2};
}

struct Means {
  double discharge = 0.0;       // [m^3/s] into the reach
  std::vector<double> surface;  // [m] eta at the gauges
};

Means run(const Reach& r, const Mesh& mesh, double dt) {
  ShallowWaterSolver solver(mesh, r.c);
  solver.initialize();
  const PointLocator locator(mesh);
  std::vector<Location> gauges;
  for (const Vec2& p : r.gauges) gauges.push_back(locator.locate(p));
  int inflow = 0;
  while (mesh.group_names[inflow] != "inflow") ++inflow;
  Means m;
  m.surface.assign(gauges.size(), 0.0);
  const int steps = static_cast<int>(std::lround(r.t_end / dt));
  const int first = static_cast<int>(std::lround((r.t_end - r.window) / dt));
  for (int n = 1; n <= steps; ++n) {
    solver.step(dt);
    if (n <= first) continue;
    m.discharge -= solver.water_balance().group_rate[inflow] * dt / r.window;
    for (size_t k = 0; k < gauges.size(); ++k)
      m.surface[k] += interpolate_p1(mesh, gauges[k], solver.eta()) * dt / r.window;
  }
  return m;
}

// The example's step against dt = 0.1 s: discharge within 2 %, each gauge within 2 % of the fall.
void expect_step_converged(const Reach& r, const std::string& name) {
  const Mesh mesh = generate_mesh(r.c.mesh);
  const double step = r.c.time.step;  // [s] the examples' step
  const Means coarse = run(r, mesh, step), fine = run(r, mesh, reference_step);
  const double dQ = coarse.discharge / fine.discharge - 1.0;
  std::printf("%s, %d elements: Q(dt = %g s) = %.1f, Q(dt = 0.1 s) = %.1f m^3/s: %+.2f %%\n",
              name.c_str(), mesh.element_count(), step, coarse.discharge, fine.discharge, 100 * dQ);
  EXPECT_LE(std::abs(dQ), 0.02);
  for (size_t k = 0; k < r.gauges.size(); ++k) {
    const double d_eta = coarse.surface[k] - fine.surface[k];
    std::printf("  gauge (%5.1f, %5.1f) m: eta = %.4f / %.4f m: %+.2f %% of the fall\n",
                r.gauges[k].x(), r.gauges[k].y(), coarse.surface[k], fine.surface[k],
                100 * d_eta / r.fall);
    EXPECT_LE(std::abs(d_eta), 0.02 * r.fall);
  }
}

class PaperChannelStep : public testing::TestWithParam<test::StepAndTime> {};

// Each step and time scheme without the case's turbulence closure: the least damped flow, where
// the step's own error shows most.
TEST_P(PaperChannelStep, ExamplesStepWithinTwoPercentOfTheReference) {
  Reach r = shortened_channel();
  r.c.flow.scheme = GetParam().flow;
  r.c.time.scheme = GetParam().time;
  r.c.flow.turbulence = TurbulenceModel::none;
  expect_step_converged(r, test::scheme_name(GetParam().flow) + ", " +
                               test::scheme_name(GetParam().time) +
                               ", no closure, shortened channel");
}

INSTANTIATE_TEST_SUITE_P(
    Schemes, PaperChannelStep,
    testing::Values(test::StepAndTime{FlowScheme::coupled, TimeScheme::theta},
                    test::StepAndTime{FlowScheme::segregated, TimeScheme::theta},
                    test::StepAndTime{FlowScheme::segregated, TimeScheme::bdf2}),
    test::step_and_time_name);

// The examples' case as it is (the segregated step with the paper's mixing length, its
// equations (6)-(7)), on the shortened channel and on the whole channel for an hour.
TEST(PaperChannelExample, ShortenedChannelWithinTwoPercentOfTheReference) {
  expect_step_converged(shortened_channel(), "the example's case, shortened channel");
}

TEST(PaperChannelExample, WholeChannelHourWithinTwoPercentOfTheReference) {
  expect_step_converged(whole_channel(), "the example's case, whole channel");
}

}  // namespace
}  // namespace flotsam
