// Outflow (spec 5): bodies leave through outflow boundaries and are counted; a body outside
// through a wall is reported, not removed.
#include "bodies/outflow.hpp"

#include <gtest/gtest.h>

#include "bodies/analytic_flow.hpp"
#include "bodies/body_integrator.hpp"

namespace flotsam {
namespace {

AnalyticFlow box_channel() {
  AnalyticFlowSpec spec;
  spec.velocity = {2.0, 0.0};
  spec.eta = 3.0;
  spec.domain_min = {0, 0};
  spec.domain_max = {100, 20};
  return AnalyticFlow(spec);
}

TEST(Outflow, BodiesLeavingThroughTheOutflowAreGoneAndCounted) {
  BodySet bodies;
  bodies.add(BodySpec{.length = 4, .position = {50, 10}});
  bodies.add(BodySpec{.length = 4, .position = {101, 10}});  // beyond x_max: group 1
  bodies.add(BodySpec{.length = 4, .position = {60, 21}});   // beyond y_max: group 3, a wall
  const OutflowResult r = remove_outflowing_bodies(bodies, box_channel(), 0.0, {1});
  EXPECT_EQ(r.left, 1);
  EXPECT_EQ(bodies.outflow_count, 1);
  EXPECT_EQ(bodies.state[0], BodyState::floating);
  EXPECT_EQ(bodies.state[1], BodyState::gone);
  EXPECT_EQ(r.stray, std::vector<int>{2});
  // Counted once: a second pass finds nothing new.
  EXPECT_EQ(remove_outflowing_bodies(bodies, box_channel(), 0.0, {1}).left, 0);
  EXPECT_EQ(bodies.outflow_count, 1);
}

TEST(Outflow, ABodyCarriedDownstreamLeavesOnce) {
  BodySet bodies;
  bodies.add(BodySpec{.length = 4, .position = {90, 10}, .velocity = {2.0, 0.0}});
  const AnalyticFlow flow = box_channel();
  BodyIntegrator integrator(ForceModel{});
  int left = 0;
  for (int n = 0; n < 100; ++n) {  // 10 s at 2 m/s: 20 m, out at x = 100 after 5 s
    integrator.advance(bodies, flow, n * 0.1, (n + 1) * 0.1);
    left += remove_outflowing_bodies(bodies, flow, (n + 1) * 0.1, {1}).left;
    if (n == 48) {
      EXPECT_EQ(bodies.state[0], BodyState::floating);
    }
  }
  EXPECT_EQ(left, 1);
  EXPECT_EQ(bodies.state[0], BodyState::gone);
}

}  // namespace
}  // namespace flotsam
