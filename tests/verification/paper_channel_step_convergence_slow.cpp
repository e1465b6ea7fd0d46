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
// Both steps (flow.scheme) with the theta-scheme, and the segregated step with BDF2, each against
// its own dt = 0.1 s run.
// docs/validation.md "Step convergence on the paper's channel" has the figures.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "../support/time_schemes.hpp"
#include "flow/fem/shallow_water_solver.hpp"
#include "io/case_file.hpp"
#include "mesh/interpolation.hpp"
#include "mesh/mesh_generator.hpp"
#include "mesh/point_locator.hpp"

namespace flotsam {
namespace {

constexpr double t_end = 1200.0, window = 600.0;  // [s] run, averaging window at its end
constexpr double reference_step = 0.1;            // [s] the paper's step
constexpr std::array<double, 4> gauge_y{10.0, 42.5, 85.0, 127.5};  // [m]
constexpr double gauge_x = 250.0;                                  // [m]
constexpr double fall = 0.1;                                       // [m] eta in - eta out

Case shortened_channel() {
  Case c = read_case(FLOTSAM_SOURCE_DIR "/examples/bridge_piers.yaml");
  c.mesh.channel.length = 750.0;
  c.mesh.channel.piers = {{.centre = Vec2(300.0, 42.5), .radius = 30.0},
                          {.centre = Vec2(300.0, 127.5), .radius = 30.0}};
  std::erase_if(c.flow.boundaries,
                [](const auto& b) { return b.group == "pier_3" || b.group == "pier_4"; });
  for (auto& b : c.flow.boundaries)
    if (b.group == "outflow") b.value = TimeSeries(10.0 - fall);  // [m] the same slope
  c.flow.initial_eta_end = 10.0 - fall;
  return c;
}

struct Means {
  double discharge = 0.0;           // [m^3/s] into the reach
  std::array<double, 4> surface{};  // [m] eta at the gauges
};

Means run(const Case& c, const Mesh& mesh, double dt) {
  ShallowWaterSolver solver(mesh, c);
  solver.initialize();
  const PointLocator locator(mesh);
  std::array<Location, 4> gauges;
  for (size_t k = 0; k < gauges.size(); ++k) gauges[k] = locator.locate(Vec2(gauge_x, gauge_y[k]));
  int inflow = 0;
  while (mesh.group_names[inflow] != "inflow") ++inflow;
  Means m;
  const int steps = static_cast<int>(std::lround(t_end / dt));
  const int first = static_cast<int>(std::lround((t_end - window) / dt));
  for (int n = 1; n <= steps; ++n) {
    solver.step(dt);
    if (n <= first) continue;
    m.discharge -= solver.water_balance().group_rate[inflow] * dt / window;
    for (size_t k = 0; k < gauges.size(); ++k)
      m.surface[k] += interpolate_p1(mesh, gauges[k], solver.eta()) * dt / window;
  }
  return m;
}

class PaperChannelStep : public testing::TestWithParam<test::StepAndTime> {};

TEST_P(PaperChannelStep, ExamplesStepWithinTwoPercentOfTheReference) {
  Case c = shortened_channel();
  c.flow.scheme = GetParam().flow;
  c.time.scheme = GetParam().time;
  const Mesh mesh = generate_mesh(c.mesh);
  const double step = c.time.step;  // [s] the examples' step
  const Means coarse = run(c, mesh, step), fine = run(c, mesh, reference_step);
  const double dQ = coarse.discharge / fine.discharge - 1.0;
  std::printf("%s, %s, %d elements: Q(dt = %g s) = %.1f, Q(dt = 0.1 s) = %.1f m^3/s: %+.2f %%\n",
              test::scheme_name(GetParam().flow).c_str(),
              test::scheme_name(GetParam().time).c_str(), mesh.element_count(), step,
              coarse.discharge, fine.discharge, 100 * dQ);
  EXPECT_LE(std::abs(dQ), 0.02);
  for (size_t k = 0; k < gauge_y.size(); ++k) {
    const double d_eta = coarse.surface[k] - fine.surface[k];
    std::printf("  gauge y = %5.1f m: eta = %.4f / %.4f m: %+.2f %% of the fall\n", gauge_y[k],
                coarse.surface[k], fine.surface[k], 100 * d_eta / fall);
    EXPECT_LE(std::abs(d_eta), 0.02 * fall);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Schemes, PaperChannelStep,
    testing::Values(test::StepAndTime{FlowScheme::coupled, TimeScheme::theta},
                    test::StepAndTime{FlowScheme::segregated, TimeScheme::theta},
                    test::StepAndTime{FlowScheme::segregated, TimeScheme::bdf2}),
    test::step_and_time_name);

}  // namespace
}  // namespace flotsam
