// Verifies that building footprints become walls the finite-volume engine respects exactly
// (issue 16: "footprints become holes"), on a domain meshed from geodata (mesh.region):
//   1. a lake at rest over a bumpy bed around six buildings (holes, one wall group "buildings")
//      stays at rest: after 1,000 sub-steps max|Hu|, max|Hv| <= 1e-12 m^2/s and
//      max|eta - eta_0| <= 1e-12 m on every cell, the balance to 1e-12;
//   2. a dam break around one square building in a closed basin (walls all round): after 60 s
//      of waves reflecting off the building and the walls the water volume is the initial one
//      to 1e-12 relative (nothing leaves through a wall), no depth is negative, and the water
//      has reached the building's lee side.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support/fv_cases.hpp"
#include "mesh/mesh_generator.hpp"

namespace flotsam {
namespace {

std::vector<Vec2> square(const Vec2& lo, double side) {
  return {lo, lo + Vec2(side, 0), lo + Vec2(side, side), lo + Vec2(0, side)};
}

RegionGeometry basin(std::vector<NamedRing> buildings) {
  RegionGeometry g;
  g.outline = {{{0, 0}, {120, 0}, {120, 60}, {0, 60}}, "basin"};
  g.default_group = "wall";
  g.buildings = std::move(buildings);
  g.mesh_size = 4.0;
  g.building_mesh_size = 1.5;
  g.refine_distance = 8.0;
  return g;
}

TEST(FvAroundBuildings, LakeAtRestStaysAtRest) {
  std::vector<NamedRing> town;
  for (int k = 0; k < 6; ++k)
    town.push_back({square({15.0 + 17.0 * k, k % 2 ? 12.0 : 32.0}, 10.0 - k),
                    fmt::format("building {}", k + 1)});
  const Mesh mesh = build_mesh(generate_region_mesh(basin(town)));
  Case c = test::fv_case({"wall", "buildings"});
  c.bed.kind = BedConfig::Kind::expression;
  c.bed.expression = Expression("0.3 * sin(0.15 * x) * cos(0.2 * y)", "bumpy bed");
  c.flow.initial_eta_start = c.flow.initial_eta_end = 1.0;
  FvEngine engine(mesh, c);
  engine.initialize();
  const FiniteVolumeSolver& solver = engine.solver();
  const double dt = solver.courant_step();
  for (int n = 0; n < 1000; ++n) engine.step(dt);
  const ConservedState& U = solver.state();
  double hu = 0.0, hv = 0.0, eta = 0.0;
  for (int i = 0; i < solver.cells().cell_count; ++i) {
    hu = std::max(hu, std::abs(U.hu[i]));
    hv = std::max(hv, std::abs(U.hv[i]));
    eta = std::max(eta, std::abs(U.h[i] + solver.bed()[i] - 1.0));
  }
  std::printf(
      "lake at rest around 6 buildings: %d cells, max|Hu| %.1e, max|Hv| %.1e m^2/s, "
      "max|eta - eta0| %.1e m, balance %.1e\n",
      solver.cells().cell_count, hu, hv, eta, engine.water_balance().relative_error());
  EXPECT_LE(hu, 1e-12);
  EXPECT_LE(hv, 1e-12);
  EXPECT_LE(eta, 1e-12);
  EXPECT_LE(std::abs(engine.water_balance().relative_error()), 1e-12);
}

TEST(FvAroundBuildings, DamBreakAroundABuildingKeepsTheWater) {
  const Mesh mesh = build_mesh(generate_region_mesh(basin({{square({55, 25}, 10), "house"}})));
  Case c = test::fv_case({"wall", "buildings"});
  c.flow.initial_eta = Expression("x < 30 ? 2 : 0.2", "dam break");
  FvEngine engine(mesh, c);
  engine.initialize();
  const double V0 = engine.volume();
  test::run_to(engine, 60.0, 1.0);
  const FiniteVolumeSolver& solver = engine.solver();
  double behind = 0.0;  // the depth in the building's lee, 2 m downstream of its centre line
  int hint = -1;
  const int lee = engine.field_cell_of({67.0, 30.0}, hint);
  ASSERT_GE(lee, 0);
  behind = solver.state().h[lee];
  const double drift = (engine.volume() - V0) / V0;
  std::printf("dam break around a building: volume drift %.1e, balance %.1e, lee depth %.3f m\n",
              drift, engine.water_balance().relative_error(), behind);
  EXPECT_LE(std::abs(drift), 1e-12);
  EXPECT_LE(std::abs(engine.water_balance().relative_error()), 1e-12);
  EXPECT_GE(test::smallest_depth(engine), 0.0);
  EXPECT_GT(behind, 0.3);  // the wave went round the building
}

}  // namespace
}  // namespace flotsam
