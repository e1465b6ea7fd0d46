// Verifies that a log held at its centre in a uniform current, starting 20 degrees from the
// flow, turns broadside and settles at 90 degrees: the drag acts at the centre of pressure
// upstream of G (M-7), whose torque vanishes only broadside, and the rotation resistance (M-8,
// C_r > 0) damps the turn. As elongated bodies at high Reynolds numbers (Yin et al. 2003).
// The post through the log's centre is played by the contact hook, which puts G back and
// stops its translation after every 0.1 s interval, as a contact with a post would.
#include <gtest/gtest.h>

#include <cmath>

#include "bodies/analytic_flow.hpp"
#include "bodies/body_integrator.hpp"
#include "core/constants.hpp"

namespace flotsam {
namespace {

constexpr double deg = pi / 180.0;

TEST(LogTurnsBroadside, FromTwentyDegreesToNinety) {
  const AnalyticFlow flow = uniform_flow({0.5, 0.0}, 10.0);
  BodySet bodies;
  bodies.add(BodySpec{.angle = 20 * deg});
  ForceModel model;  // Ganser drag, centre of pressure on, C_r = 1
  BodyIntegrator integrator(model);
  const auto post = [](const ContactInterval&, BodySet& b) {
    b.position[0] = Vec2::Zero();
    b.velocity[0] = Vec2::Zero();
  };
  // The restoring torque near 90 deg is cubic in the offset (|cos alpha|^3 in (M-7)) and the
  // damping quadratic (M-8): the log swings about 90 deg with a slowly decaying amplitude.
  double reached_85 = -1.0;                    // [s]
  double swing_early = 0.0, swing_late = 0.0;  // max |theta - 90 deg| over 500-1000, 2000-3000 s
  for (int n = 0; n < 30000; ++n) {            // 3000 s
    const double t = (n + 1) * 0.1;
    integrator.advance(bodies, flow, n * 0.1, t, ContactSchedule::one_group(bodies), post);
    const double offset = std::abs(bodies.angle[0] - 90 * deg);
    if (reached_85 < 0 && bodies.angle[0] > 85 * deg) reached_85 = t;
    if (t >= 500 && t <= 1000) swing_early = std::max(swing_early, offset);
    if (t >= 2000) swing_late = std::max(swing_late, offset);
  }
  EXPECT_GT(reached_85, 0.0);
  EXPECT_LT(reached_85, 60.0);  // turned broadside within a minute
  EXPECT_LT(swing_late, 2.5 * deg);
  EXPECT_LT(swing_late, 0.6 * swing_early);  // and settling
  std::printf("85 deg after %.1f s; swing %.2f deg (500-1000 s), %.2f deg (2000-3000 s)\n",
              reached_85, swing_early / deg, swing_late / deg);
}

}  // namespace
}  // namespace flotsam
