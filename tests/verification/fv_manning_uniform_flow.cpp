// Verifies that the finite-volume engine marches to the steady uniform flow of a sloping straight
// channel with Manning friction held between two levels (Chow 1959, Open-channel hydraulics,
// ch. 6): the depth is the normal depth h_n everywhere and the unit discharge Manning's
// q = h_n^(5/3) sqrt(S) / n, each within 0.5 % (5 % in the cells at the two ends), and so is
// the discharge through the inlet; the inflow equals the outflow to 1e-4. Both ends
// are elevation boundaries, so the subcritical inflow's velocity comes from the outgoing
// Riemann invariant (docs/model.md "Boundaries"): extrapolating it instead fed energy into the
// paper's channel until the flow blew up after 25 minutes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "flow/fv/fv_engine.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

TEST(FvManningUniformFlow, MarchesToTheNormalDepthAndManningsDischarge) {
  const double L = 1000.0, B = 20.0;  // [m]
  const double S = 1e-3, n = 0.03;    // bed slope [-], Manning [s m^-1/3]
  const double h_n = 1.0;             // [m]
  const double q = std::pow(h_n, 5.0 / 3.0) * std::sqrt(S) / n;  // [m^2/s] 1.054
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, L, B, 40, 2, true});
  Case c;
  c.flow.engine = FlowEngineKind::fv;
  c.bed.kind = BedConfig::Kind::slope;
  c.bed.slope = Vec2(S, 0.0);
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = n;
  c.flow.initial_eta_start = h_n;  // still water at the normal depth's levels
  c.flow.initial_eta_end = h_n - S * L;
  c.flow.boundaries = {{BoundaryCondition::Kind::elevation, "left", TimeSeries(h_n), {}},
                       {BoundaryCondition::Kind::elevation, "right", TimeSeries(h_n - S * L), {}},
                       {BoundaryCondition::Kind::wall, "bottom", {}, {}},
                       {BoundaryCondition::Kind::wall, "top", {}, {}}};
  c.time.spin_up_step = 20.0;
  c.time.spin_up_end = 20000.0;
  FvEngine engine(mesh, c);
  engine.initialize();
  engine.settle(c.time);
  const ConservedState& s = engine.solver().state();
  double depth_error = 0.0, discharge_error = 0.0, end_error = 0.0;
  for (std::size_t i = 0; i < s.h.size(); ++i) {
    depth_error = std::max(depth_error, std::abs(s.h[i] - h_n) / h_n);
    const double x = engine.solver().cells().centroid[i].x();
    const double e = std::abs(s.hu[i] - q) / q;
    if (x > 25.0 && x < L - 25.0)  // the cells at the two ends carry the boundaries' layer
      discharge_error = std::max(discharge_error, e);
    else
      end_error = std::max(end_error, e);
  }
  EXPECT_LE(depth_error, 0.005);
  EXPECT_LE(discharge_error, 0.005);
  EXPECT_LE(end_error, 0.05);  // measured 3.2 %: the level is imposed at the face, not the cell
  // One more step: the flow out is the flow in.
  engine.step(10.0);
  const auto& rate = engine.water_balance().group_rate;
  const double in = rate[mesh.find_group("left")], out = rate[mesh.find_group("right")];
  EXPECT_NEAR(-in, q * B, 0.005 * q * B);
  // The march stops when the velocity changes by less than 1e-5 of itself in 20 s: what is
  // left of the transient shows as a difference of in- and outflow of that order.
  EXPECT_LE(std::abs(in + out) / std::abs(in), 1e-4);
  std::printf(
      "FV Manning: max depth error %.3e, max discharge error %.3e (end cells %.3e), Q in %.6g "
      "m^3/s, in + out %.2e of it\n",
      depth_error, discharge_error, end_error, -in, std::abs(in + out) / std::abs(in));
}

}  // namespace
}  // namespace flotsam
