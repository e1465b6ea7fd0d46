// Unit tests of the HLLC Riemann flux (flow/fv/hllc_flux.hpp; Toro 2001 ch. 10): consistency with
// the physical flux, mirror symmetry, walls, dry beds, supercritical upwinding and the wave-speed
// bound the Courant step relies on.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "flow/fv/hllc_flux.hpp"

namespace flotsam {
namespace {

constexpr double g = 9.81;  // [m s^-2]

// The physical flux of the state along the normal: (h u_n, h u_n^2 + g h^2 / 2, h u_n u_t).
EdgeFlux physical_flux(const EdgeState& s) {
  return {s.h * s.u_n, s.h * s.u_n * s.u_n + 0.5 * g * s.h * s.h, s.h * s.u_n * s.u_t, 0.0};
}

// The state seen from the other side of the edge: normal velocity flipped, tangent kept.
EdgeState mirrored(const EdgeState& s) {
  return {s.h, -s.u_n, s.u_t};
}

const std::vector<EdgeState> states = {
    {1.0, 0.0, 0.0}, {2.0, 0.5, -0.3}, {0.3, -1.2, 0.8}, {0.05, 2.0, 1.0}, {4.0, 12.0, -2.0}};

TEST(HllcFlux, EqualStatesGiveThePhysicalFluxExactly) {
  for (const EdgeState& s : states) {
    const EdgeFlux f = hllc_flux(s, s, g);
    const EdgeFlux p = physical_flux(s);
    EXPECT_EQ(f.mass, p.mass) << "h = " << s.h << ", u_n = " << s.u_n;
    EXPECT_EQ(f.momentum_n, p.momentum_n) << "h = " << s.h << ", u_n = " << s.u_n;
    EXPECT_NEAR(f.momentum_t, p.momentum_t, 1e-15 * std::abs(p.momentum_t))
        << "h = " << s.h << ", u_n = " << s.u_n;
  }
}

TEST(HllcFlux, MirroredProblemGivesTheOppositeMassFlux) {
  // Seen from the other side, (L, R) becomes (mirror R, mirror L): the mass and tangential
  // fluxes change sign, the normal momentum flux does not.
  const std::vector<std::pair<EdgeState, EdgeState>> problems = {
      {{2.0, 0.0, 0.0}, {1.0, 0.0, 0.0}},  {{1.0, 0.7, 0.2}, {0.4, -0.3, -0.5}},
      {{0.2, -1.5, 1.0}, {3.0, 2.0, 0.0}}, {{1.0, 0.5, 0.3}, {0.0, 0.0, 0.0}},
      {{0.0, 0.0, 0.0}, {0.7, -0.4, 0.9}}, {{1.0, 6.0, -1.0}, {0.5, 5.0, 1.0}}};
  for (const auto& [L, R] : problems) {
    const EdgeFlux f = hllc_flux(L, R, g);
    const EdgeFlux m = hllc_flux(mirrored(R), mirrored(L), g);
    const double scale = std::abs(f.momentum_n) + 1.0;
    EXPECT_NEAR(f.mass, -m.mass, 1e-14 * scale) << "h_L = " << L.h << ", h_R = " << R.h;
    EXPECT_NEAR(f.momentum_n, m.momentum_n, 1e-14 * scale) << "h_L = " << L.h;
    EXPECT_NEAR(f.momentum_t, -m.momentum_t, 1e-14 * scale) << "h_L = " << L.h;
    EXPECT_NEAR(f.max_speed, m.max_speed, 1e-14 * f.max_speed);
  }
}

TEST(HllcFlux, WallGivesNoMassFlux) {
  // The ghost of a wall is the inside state mirrored: nothing crosses, the wall only pushes.
  for (const EdgeState& s : states) {
    const EdgeFlux f = hllc_flux(s, mirrored(s), g);
    EXPECT_NEAR(f.mass, 0.0, 1e-15 * (std::abs(s.h * s.u_n) + 1.0)) << "u_n = " << s.u_n;
    // At rest the wall takes the hydrostatic pressure exactly.
    if (s.u_n == 0.0) {
      EXPECT_EQ(f.momentum_n, 0.5 * g * s.h * s.h);
    }
  }
}

TEST(HllcFlux, DryOnBothSidesGivesNothing) {
  const EdgeFlux f = hllc_flux({0.0, 1.0, 2.0}, {0.0, -3.0, 0.5}, g);
  EXPECT_EQ(f.mass, 0.0);
  EXPECT_EQ(f.momentum_n, 0.0);
  EXPECT_EQ(f.momentum_t, 0.0);
  EXPECT_EQ(f.max_speed, 0.0);
}

TEST(HllcFlux, SupercriticalFlowTakesTheUpstreamFlux) {
  // Both sides faster than their wave speed c = sqrt(g h): every wave goes right, F = F(U_L).
  const EdgeState L{1.0, 5.0, 0.4}, R{0.5, 4.0, -0.9};
  ASSERT_GT(L.u_n, std::sqrt(g * L.h));
  ASSERT_GT(R.u_n, std::sqrt(g * R.h));
  const EdgeFlux f = hllc_flux(L, R, g), p = physical_flux(L);
  EXPECT_EQ(f.mass, p.mass);
  EXPECT_EQ(f.momentum_n, p.momentum_n);
  EXPECT_NEAR(f.momentum_t, p.momentum_t, 1e-15 * std::abs(p.momentum_t));
  // And leftwards: F = F(U_R).
  const EdgeFlux b = hllc_flux(mirrored(R), mirrored(L), g), q = physical_flux(mirrored(L));
  EXPECT_EQ(b.mass, q.mass);
  EXPECT_EQ(b.momentum_n, q.momentum_n);
}

TEST(HllcFlux, MaxSpeedBoundsTheOutermostCharacteristics) {
  // Toro's estimate: s_L <= u_L - c_L and s_R >= u_R + c_R, so the Courant speed max(|s_L|,
  // |s_R|) bounds both (it need not bound u_L + c_L: e.g. L = (4, 12), R = (1, 0) gives
  // 16.83 m/s < 18.26 m/s, a wave that does not exist in that Riemann problem).
  for (const EdgeState& L : states)
    for (const EdgeState& R : states) {
      const EdgeFlux f = hllc_flux(L, R, g);
      const double bound =
          std::max(std::abs(L.u_n - std::sqrt(g * L.h)), std::abs(R.u_n + std::sqrt(g * R.h)));
      EXPECT_GE(f.max_speed, bound * (1.0 - 1e-15)) << "h_L = " << L.h << ", h_R = " << R.h;
    }
  // Equal states: exactly |u_n| + c.
  for (const EdgeState& s : states)
    EXPECT_NEAR(hllc_flux(s, s, g).max_speed, std::abs(s.u_n) + std::sqrt(g * s.h), 1e-14)
        << "h = " << s.h;
  // Onto a dry bed the front runs at u + 2 c (Ritter): the bound is the dry-bed speed.
  const EdgeFlux f = hllc_flux({1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, g);
  EXPECT_NEAR(f.max_speed, 2.0 * std::sqrt(g), 1e-14);
}

TEST(HllcFlux, TangentialMomentumIsCarriedFromTheUpwindSide) {
  // Mass flows left to right: the tangential velocity carried is the left one.
  const EdgeState L{1.0, 0.5, 0.7}, R{1.0, 0.5, -0.2};
  const EdgeFlux f = hllc_flux(L, R, g);
  EXPECT_GT(f.mass, 0.0);
  EXPECT_NEAR(f.momentum_t, f.mass * L.u_t, 1e-15);
  const EdgeFlux b = hllc_flux(mirrored(R), mirrored(L), g);
  EXPECT_NEAR(b.momentum_t, b.mass * L.u_t, 1e-15);
}

TEST(HllcFlux, ACompressionTakesHllsTangentialFlux) {
  // Water running into slower water (u_L - u_R = 1.5 m/s > 0.1 c): a shock. The tangential
  // momentum then takes HLL's flux, F = F_L + s_L (s_R (U_R - U_L) - (F_R - F_L)) / (s_R - s_L)
  // with U = h u_t, F = h u_n u_t, so that shocks along the mesh do not grow a transverse
  // instability; the mass flux is HLL's as everywhere.
  const EdgeState L{1.0, 2.0, 0.4}, R{0.5, 0.5, -0.3};
  const EdgeFlux f = hllc_flux(L, R, g);
  const double c_L = std::sqrt(g * L.h), c_R = std::sqrt(g * R.h);
  const double u_star = 0.5 * (L.u_n + R.u_n) + c_L - c_R;
  const double c_star = 0.5 * (c_L + c_R) + 0.25 * (L.u_n - R.u_n);
  const double s_L = std::min(L.u_n - c_L, u_star - c_star);
  const double s_R = std::max(R.u_n + c_R, u_star + c_star);
  ASSERT_LT(s_L, 0.0);  // a subcritical edge: the flux is the star region's
  const double F_L = L.h * L.u_n * L.u_t, F_R = R.h * R.u_n * R.u_t;
  const double hll = F_L + s_L * (s_R * (R.h * R.u_t - L.h * L.u_t) - (F_R - F_L)) / (s_R - s_L);
  EXPECT_NEAR(f.momentum_t, hll, 1e-14);
  EXPECT_GT(std::abs(f.momentum_t - f.mass * L.u_t), 1e-3);  // not the contact's upwinding
}

}  // namespace
}  // namespace flotsam
