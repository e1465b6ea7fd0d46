// Verifies that two-way coupling conserves momentum (spec 5 step 3): after every flow step the
// reaction the bodies put on the water, summed over the elements as rho * integral(H) times the
// element's acceleration F_e - c_e u_e (the added mass's part explicit, the drag -K (u - u_p)
// implicit at the element's mean velocity u_e), equals minus the sum of the forces the engine
// reports exchanged with the bodies to 1e-10 relative. Reference: the exact bookkeeping of spec
// 5, F_bodies = -F_x / (rho H A_fp).
#include <gtest/gtest.h>

#include <cmath>

#include "../support/straight_channel.hpp"
#include "core/constants.hpp"
#include "coupling/simulation.hpp"
#include "flow/fem/fem_engine.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

TEST(TwoWayMomentumExchange, ReactionOnTheWaterIsMinusTheForceOnTheBodies) {
  Case c = test::straight_channel_case("momentum", 40.0, 2.0);
  c.flow.viscosity = 0.01;
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = 0.03;
  c.time = {.end = 20.0, .step = 1.0, .mode = CouplingMode::two_way};
  // Logs of several sizes and angles, one of them across several elements, one smaller than an
  // element (its reaction goes to the element holding its centre).
  for (int k = 0; k < 6; ++k) {
    BodySpec log;
    log.length = 2.0 + 2.0 * k;
    log.width = 0.2 + 0.1 * k;
    log.position = Vec2(30.0 + 25.0 * k, 6.0 + 1.5 * k);
    log.angle = 0.25 * k;

    c.bodies.bodies.push_back(log);
  }
  const Mesh mesh = make_rectangle_mesh({.length = 200, .width = 20, .nx = 40, .ny = 8});
  Simulation s(
      c, mesh,
      {.output_directory = {}, .overwrite = false, .write_output = false, .progress = false});
  s.initialize();
  const double rho = c.flow.water_density;
  int steps = 0, loaded_steps = 0;  // steps, and those in which the bodies felt a force
  while (!s.done()) {
    s.step();
    const ShallowWaterSolver& flow = dynamic_cast<const FemEngine&>(s.flow()).solver();
    const auto& F_e = flow.element_forces();
    const auto& c_e = flow.element_drag_rates();
    ASSERT_EQ(static_cast<int>(F_e.size()), mesh.element_count());
    ASSERT_EQ(static_cast<int>(c_e.size()), mesh.element_count());
    Vec2 on_water = Vec2::Zero(), on_bodies = Vec2::Zero();
    for (int e = 0; e < mesh.element_count(); ++e) {
      const auto& el = mesh.elements[e];
      const double eta = (flow.eta()[el[0]] + flow.eta()[el[1]] + flow.eta()[el[2]]) / 3.0;
      const double z_b = (flow.bed()[el[3]] + flow.bed()[el[4]] + flow.bed()[el[5]]) / 3.0;
      const Vec2 u_e((flow.u()[el[3]] + flow.u()[el[4]] + flow.u()[el[5]]) / 3.0,
                     (flow.v()[el[3]] + flow.v()[el[4]] + flow.v()[el[5]]) / 3.0);
      on_water += rho * mesh.area[e] * (eta - z_b) * (F_e[e] - c_e[e] * u_e);  // [N]
    }
    for (const Vec2& f : s.flow().field().exchanged_forces()) on_bodies += f;
    EXPECT_LE((on_water + on_bodies).norm(), 1e-10 * on_bodies.norm()) << "step " << steps;
    loaded_steps += on_bodies.norm() > 0.0;
    ++steps;
  }
  EXPECT_EQ(steps, 20);
  EXPECT_GE(loaded_steps, 19);  // the first may see water still at rest
}

}  // namespace
}  // namespace flotsam
