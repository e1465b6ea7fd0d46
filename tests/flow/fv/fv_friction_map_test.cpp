// Friction over the domain in the finite-volume engine (flow/friction_map.hpp, docs/model.md
// "Friction over the domain"): a cell whose centroid lies in a zone takes the zone's coefficient,
// the others the default, with zones written in the case or read from a GeoPackage (exact:
// coefficients are copied, not computed); and each cell's implicit friction (M-14) uses its own
// coefficient (1e-10 relative, as the uniform-law tests of fv_solver_test.cpp); the output holds
// the coefficients and the rain weights the cells took.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "../../support/scratch_path.hpp"
#include "flow/fv/fv_engine.hpp"
#include "flow/fv/fv_solver.hpp"
#include "fv_test_cases.hpp"
#include "geo/vector_layer.hpp"
#include "io/case_file.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

constexpr double n_default = 0.02;  // [s m^-1/3]

// 20 m x 10 m of 1 m squares cut in two: the cells' centroids are a third of the way into the
// squares, never on the zones' sides at whole metres.
Mesh channel_mesh() {
  return make_rectangle_mesh({0.0, 0.0, 20.0, 10.0, 20, 10, true});
}

std::vector<Vec2> rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

bool inside(const Vec2& p, double x0, double y0, double x1, double y1) {
  return p.x() > x0 && p.x() < x1 && p.y() > y0 && p.y() < y1;
}

// The coefficient each cell must have: zone A [3, 9] x [2, 7] m at 0.08, then zone B
// [7, 15] x [5, 10] m at 0.05, which wins where they overlap; elsewhere the default.
double expected_coefficient(const Vec2& p) {
  if (inside(p, 7, 5, 15, 10)) return 0.05;
  if (inside(p, 3, 2, 9, 7)) return 0.08;
  return n_default;
}

void expect_zones_cell_by_cell(const FiniteVolumeSolver& s) {
  const std::vector<double>& k = s.friction_coefficients();
  ASSERT_EQ(static_cast<int>(k.size()), s.cells().cell_count);
  int in_a = 0, in_b = 0;
  for (int i = 0; i < s.cells().cell_count; ++i) {
    const Vec2& p = s.cells().centroid[i];
    EXPECT_EQ(k[i], expected_coefficient(p)) << "cell " << i << " at " << p.transpose();
    in_a += k[i] == 0.08;
    in_b += k[i] == 0.05;
  }
  EXPECT_EQ(in_a, 6 * 5 * 2 - 2 * 2 * 2);  // A's squares, less the 2 x 2 that B covers
  EXPECT_EQ(in_b, 8 * 5 * 2);
}

TEST(FvFrictionMap, CellsWhoseCentroidIsInAZoneTakeItsCoefficient) {
  const Mesh mesh = channel_mesh();
  Case c = test::closed_basin_case(1.0);
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = n_default;
  c.flow.friction_map.zones = {{rectangle(3, 2, 9, 7), {}, 0.08, "zone A"},
                               {rectangle(7, 5, 15, 10), {}, 0.05, "zone B"}};
  const FiniteVolumeSolver s(mesh, c);
  expect_zones_cell_by_cell(s);
}

TEST(FvFrictionMap, ZonesFromAGeoPackageGiveEachPolygonItsAttribute) {
  const auto folder = test::fresh_test_folder("flotsam_friction");
  write_polygon_layer((folder / "landuse.gpkg").string(), "landuse",
                      {rectangle(3, 2, 9, 7), rectangle(7, 5, 15, 10)},
                      coordinate_system_wkt("EPSG:32633", "test"), "manning_n", {0.08, 0.05});
  const std::string text = R"(mesh:
  channel: {length: 20, width: 10}
flow:
  engine: fv
  friction:
    law: manning
    coefficient: 0.02
    zones: {file: landuse.gpkg, layer: landuse, field: manning_n}
  initial: {eta: 1.0}
  boundaries:
    left: {type: wall}
    right: {type: wall}
    bottom: {type: wall}
    top: {type: wall}
time: {end: 10}
)";
  const Case c = parse_case(text, (folder / "case.yaml").string());
  ASSERT_EQ(c.flow.friction_map.zones.size(), 2u);
  const Mesh mesh = channel_mesh();
  const FiniteVolumeSolver s(mesh, c);
  expect_zones_cell_by_cell(s);
}

TEST(FvFrictionMap, EachCellSlowsWithItsOwnCoefficient) {
  // Uniform flow u0 along x in a closed flat basin, a zone of n = 0.1 over the left half: for
  // one sub-step the cells away from the walls see no gradient, only friction, (M-14)
  //   u1 = u0 2 / (1 + sqrt(1 + 4 dt gamma)),  gamma = g n^2 |u0| / h^(4/3),
  // with the n of their zone or the default.
  const double g = 9.81, h = 0.5, u0 = 1.0, n_zone = 0.1;  // [m s^-2], [m], [m/s], [s m^-1/3]
  const Mesh mesh = channel_mesh();
  Case c = test::closed_basin_case(h);
  c.flow.initial_u = Expression("1.0", "test: flow.initial.u");
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = n_default;
  c.flow.friction_map.zones = {{rectangle(-1, -1, 10, 11), {}, n_zone, "left half"}};
  FiniteVolumeSolver s(mesh, c);
  s.initialize();
  const double dt = 0.5 * s.courant_step();
  s.advance(dt);
  ASSERT_EQ(s.sub_steps().count, 1);
  int checked = 0;
  for (int i = 0; i < s.cells().cell_count; ++i) {
    const Vec2& p = s.cells().centroid[i];
    if (!inside(p, 4, 4, 16, 6)) continue;  // 4 m from the walls
    const double n = p.x() < 10.0 ? n_zone : n_default;
    const double gamma = g * n * n * u0 / std::pow(h, 4.0 / 3.0);  // [1/s]
    const double u1 = u0 * 2.0 / (1.0 + std::sqrt(1.0 + 4.0 * dt * gamma));
    EXPECT_NEAR(s.state().hu[i] / s.state().h[i], u1, 1e-10 * u1) << "cell at " << p.transpose();
    ++checked;
  }
  EXPECT_EQ(checked, 12 * 2 * 2);
}

TEST(FvFrictionMap, OutputHoldsTheCellsCoefficientsAndRainWeights) {
  const Mesh mesh = channel_mesh();
  Case c = test::closed_basin_case(1.0);
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = n_default;
  c.flow.friction_map.zones = {{rectangle(3, 2, 9, 7), {}, 0.08, "zone A"}};
  c.flow.rain.enabled = true;
  c.flow.rain.intensity = TimeSeries(10.0);
  RasterGrid g;
  g.columns = g.rows = 1;
  g.transform = {0.0, 20.0, 0.0, 10.0, 0.0, -10.0};
  c.flow.rain.raster = std::make_shared<const Raster>(g, std::vector{0.75}, -9999.0);
  FvEngine engine(mesh, c);
  engine.initialize();
  const auto path = test::fresh_test_folder("flotsam_friction") / "fields.vtu";
  engine.write_fields(path.string(), 0.0);
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  const std::string vtu = text.str();
  EXPECT_NE(vtu.find("Name=\"n [s m^-1/3]\""), std::string::npos);
  EXPECT_NE(vtu.find("Name=\"rain weight [-]\""), std::string::npos);
  for (double w : engine.solver().rain().weights()) EXPECT_EQ(w, 0.75);
}

}  // namespace
}  // namespace flotsam
