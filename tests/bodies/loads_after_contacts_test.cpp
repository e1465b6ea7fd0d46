// Verifies the loads recorded for bodies held by contacts (bodies/loads_after_contacts.hpp)
// against (M-5), (M-6) and spec 5 step 3 by hand: a log held at rest broadside in a uniform
// stream gives the water its whole drag, 0.5 rho C_d h_s L |u| u; one the contacts stopped
// within the step adds the added mass's share of its stop, -C_a m_f a_p with
// a_p = (u_p(t1) - u_p(t0)) / dt; bodies not listed, and anchored ones, keep their loads.
#include "bodies/loads_after_contacts.hpp"

#include <gtest/gtest.h>

#include "bodies/analytic_flow.hpp"
#include "core/constants.hpp"

namespace flotsam {
namespace {

constexpr double L = 10.0, D = 0.6, density = 800.0;  // [m], [m], [kg m^-3]

BodySet held_logs(int count) {
  BodySet bodies;
  for (int k = 0; k < count; ++k) {
    BodySpec spec;
    spec.shape = Shape::log;
    spec.length = L;
    spec.width = D;
    spec.height = D;
    spec.density = density;
    spec.position = Vec2(5.0, 3.0 + 2.0 * k);
    spec.angle = pi / 2;  // across the stream
    bodies.add(spec);
  }
  return bodies;
}

ForceModel constant_drag() {
  ForceModel model;
  model.physics.drag_law = DragLaw::constant;
  model.physics.drag_coefficient = 1.2;
  return model;
}

TEST(LoadsAfterContacts, AHeldLogGivesTheWaterItsWholeDragAndAStoppedOneItsAddedMass) {
  BodySet bodies = held_logs(4);
  const ForceModel model = constant_drag();
  const AnalyticFlow flow = uniform_flow({1.5, 0.0}, 3.0);
  const double dt = 0.5;  // [s]
  // Body 0 held at rest all the step; body 1 stopped from 0.4 m/s; body 2 not listed; body 3
  // anchored. Their recorded loads before: a marker.
  std::vector<Vec2> start(4, Vec2::Zero());
  start[1] = Vec2(0.4, 0.0);
  bodies.anchored[3] = 1;
  for (int i = 0; i < 4; ++i) bodies.reaction_force[i] = Vec2(-7.0, 0.0);
  record_loads_after_contacts(bodies, {0, 1, 3}, start, flow, model, 2.0, dt);

  const double h_s = bodies.draft[0];                               // [m] floating: its draft
  const double drag = 0.5 * model.rho * 1.2 * h_s * L * 1.5 * 1.5;  // [N] (M-6), broadside
  EXPECT_NEAR(bodies.drag_force[0].x(), drag, 1e-9 * drag);
  EXPECT_NEAR(bodies.reaction_force[0].x(), drag, 1e-9 * drag);  // Du_f/Dt = 0, a_p = 0
  EXPECT_NEAR(bodies.reaction_force[0].y(), 0.0, 1e-9 * drag);
  const double C_a = model.physics.added_mass_coefficient, m_f = bodies.mass[1];  // floating
  const double a_p = (0.0 - 0.4) / dt;                                            // [m/s^2]
  EXPECT_NEAR(bodies.reaction_force[1].x(), drag - C_a * m_f * a_p, 1e-9 * drag);
  EXPECT_EQ(bodies.reaction_force[2], Vec2(-7.0, 0.0));
  EXPECT_EQ(bodies.reaction_force[3], Vec2(-7.0, 0.0));
  EXPECT_EQ(bodies.state[0], BodyState::floating);
}

}  // namespace
}  // namespace flotsam
