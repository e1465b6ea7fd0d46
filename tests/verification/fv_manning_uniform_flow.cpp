// Verifies that the finite-volume engine marches to the steady uniform flow of a sloping straight
// channel with Manning friction held between two levels (Chow 1959, Open-channel hydraulics,
// ch. 6): the depth is the normal depth h_n everywhere and the unit discharge Manning's
// q = h_n^(5/3) sqrt(S) / n, each within 0.5 % (5 % in the cells at the two ends), and so is
// the discharge through the inlet; the inflow equals the outflow to 1e-4. Both ends
// are elevation boundaries, so the subcritical inflow's velocity comes from the outgoing
// Riemann invariant (docs/model.md "Boundaries"): extrapolating it instead fed energy into the
// paper's channel until the flow blew up after 25 minutes.
//
// With roughness zones (flow.friction.zones, docs/model.md "Friction over the domain"): a zone
// covering the whole channel over another default n gives the same flow, with the zone's n, to
// the same tolerances; and two halves side by side of different n, under the same levels, each
// carry their own Manning discharge at the one normal depth (0.5 % away from the line between
// them and 50 m from the ends, where the two flows shear and settle).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "flow/fv/fv_engine.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

constexpr double L = 1000.0, B = 20.0;  // [m]
constexpr double S = 1e-3;              // bed slope [-]
constexpr double h_n = 1.0;             // [m]

// Manning's unit discharge at the normal depth [m^2/s] (1.054 for n = 0.03).
double manning_q(double n) {
  return std::pow(h_n, 5.0 / 3.0) * std::sqrt(S) / n;
}

Mesh channel_mesh(int ny) {
  return make_rectangle_mesh({0.0, 0.0, L, B, 40, ny, true});
}

// Still water at the normal depth's levels, marched to the steady state.
Case channel_case(double n) {
  Case c;
  c.flow.engine = FlowEngineKind::fv;
  c.bed.kind = BedConfig::Kind::slope;
  c.bed.slope = Vec2(S, 0.0);
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = n;
  c.flow.initial_eta_start = h_n;
  c.flow.initial_eta_end = h_n - S * L;
  c.flow.boundaries = {{BoundaryCondition::Kind::elevation, "left", TimeSeries(h_n), {}},
                       {BoundaryCondition::Kind::elevation, "right", TimeSeries(h_n - S * L), {}},
                       {BoundaryCondition::Kind::wall, "bottom", {}, {}},
                       {BoundaryCondition::Kind::wall, "top", {}, {}}};
  c.time.spin_up_step = 20.0;
  c.time.spin_up_end = 20000.0;
  return c;
}

struct UniformFlowErrors {
  double depth = 0.0;      // [-] largest |h - h_n| / h_n
  double discharge = 0.0;  // [-] largest |hu - q| / q away from the ends (and from `shear_y`)
  double ends = 0.0;       // [-] the same in the cells near the ends
  double in = 0.0;         // [m^3/s] the discharge through the inlet
  double imbalance = 0.0;  // [-] |in + out| / |in|
};

// The settled flow against h_n and the unit discharge q(p) expected at each cell's centroid;
// the discharge of the cells within `end_length` [m] of the ends is `ends`, and the cells within
// `shear_width` [m] of y = B/2 are left out of it (0: none).
UniformFlowErrors settle_and_measure(const Mesh& mesh, const Case& c, double (*q)(const Vec2& p),
                                     double end_length = 25.0, double shear_width = 0.0) {
  FvEngine engine(mesh, c);
  engine.initialize();
  engine.settle(c.time);
  const ConservedState& s = engine.solver().state();
  UniformFlowErrors r;
  for (std::size_t i = 0; i < s.h.size(); ++i) {
    r.depth = std::max(r.depth, std::abs(s.h[i] - h_n) / h_n);
    const Vec2& p = engine.solver().cells().centroid[i];
    const double e = std::abs(s.hu[i] - q(p)) / q(p);
    if (p.x() <= end_length || p.x() >= L - end_length)  // the boundaries' layer
      r.ends = std::max(r.ends, e);
    else if (std::abs(p.y() - 0.5 * B) >= shear_width)
      r.discharge = std::max(r.discharge, e);
  }
  // One more step: the flow out is the flow in.
  engine.step(10.0);
  const auto& rate = engine.water_balance().group_rate;
  const double in = rate[mesh.find_group("left")], out = rate[mesh.find_group("right")];
  r.in = -in;
  r.imbalance = std::abs(in + out) / std::abs(in);
  return r;
}

TEST(FvManningUniformFlow, MarchesToTheNormalDepthAndManningsDischarge) {
  const double n = 0.03;  // [s m^-1/3]
  const Mesh mesh = channel_mesh(2);
  const UniformFlowErrors r =
      settle_and_measure(mesh, channel_case(n), [](const Vec2&) { return manning_q(0.03); });
  EXPECT_LE(r.depth, 0.005);
  EXPECT_LE(r.discharge, 0.005);
  EXPECT_LE(r.ends, 0.05);  // measured 3.2 %: the level is imposed at the face, not the cell
  EXPECT_NEAR(r.in, manning_q(n) * B, 0.005 * manning_q(n) * B);
  // The march stops when the velocity changes by less than 1e-5 of itself in 20 s: what is
  // left of the transient shows as a difference of in- and outflow of that order.
  EXPECT_LE(r.imbalance, 1e-4);
  std::printf(
      "FV Manning: max depth error %.3e, max discharge error %.3e (end cells %.3e), Q in %.6g "
      "m^3/s, in + out %.2e of it\n",
      r.depth, r.discharge, r.ends, r.in, r.imbalance);
}

TEST(FvManningUniformFlow, AZoneOverTheWholeChannelSetsItsN) {
  const double n_zone = 0.03, n_default = 0.06;  // [s m^-1/3]
  const Mesh mesh = channel_mesh(2);
  Case c = channel_case(n_default);
  c.flow.friction_map.zones = {
      {{{-1.0, -1.0}, {L + 1.0, -1.0}, {L + 1.0, B + 1.0}, {-1.0, B + 1.0}}, {}, n_zone, "all"}};
  const UniformFlowErrors r =
      settle_and_measure(mesh, c, [](const Vec2&) { return manning_q(0.03); });
  EXPECT_LE(r.depth, 0.005);
  EXPECT_LE(r.discharge, 0.005);
  EXPECT_LE(r.ends, 0.05);
  EXPECT_NEAR(r.in, manning_q(n_zone) * B, 0.005 * manning_q(n_zone) * B);
  EXPECT_LE(r.imbalance, 1e-4);
  std::printf(
      "FV Manning, a zone of n = %g over the channel (default %g): max depth error %.3e, max "
      "discharge error %.3e (end cells %.3e), Q in %.6g m^3/s, in + out %.2e of it\n",
      n_zone, n_default, r.depth, r.discharge, r.ends, r.in, r.imbalance);
}

TEST(FvManningUniformFlow, TwoRoughnessHalvesCarryTheirOwnDischarges) {
  // y < B/2: the default n = 0.03; y > B/2: a zone of n = 0.045, two thirds of the discharge.
  const Mesh mesh = channel_mesh(8);
  Case c = channel_case(0.03);
  c.flow.friction_map.zones = {
      {{{-1.0, 0.5 * B}, {L + 1.0, 0.5 * B}, {L + 1.0, B + 1.0}, {-1.0, B + 1.0}},
       {},
       0.045,
       "rough half"}};
  const auto q = [](const Vec2& p) { return manning_q(p.y() < 0.5 * B ? 0.03 : 0.045); };
  // Measured: 0.18 % along the channel, 0.7 % in the second column of cells from the inlet,
  // where the levels imposed on both halves' inflow settle; so 50 m from the ends.
  const UniformFlowErrors r = settle_and_measure(mesh, c, q, 50.0, 2.5);
  const double Q = 0.5 * B * (manning_q(0.03) + manning_q(0.045));  // [m^3/s]
  EXPECT_LE(r.depth, 0.005);
  EXPECT_LE(r.discharge, 0.005);
  EXPECT_LE(r.ends, 0.1);  // measured 8.3 % in the first column, beside the halves' line
  EXPECT_NEAR(r.in, Q, 0.005 * Q);
  EXPECT_LE(r.imbalance, 1e-4);
  std::printf(
      "FV Manning, halves of n = 0.03 and 0.045: max depth error %.3e, max discharge error "
      "%.3e (50 m from the ends, 2.5 m from the halves' line; end cells %.3e), Q in %.6g of "
      "%.6g m^3/s, in + out %.2e of it\n",
      r.depth, r.discharge, r.ends, r.in, Q, r.imbalance);
}

}  // namespace
}  // namespace flotsam
