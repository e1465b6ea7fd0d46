// Unit tests of rain and infiltration in the finite-volume engine (flow/fv/rain_source.hpp,
// docs/model.md (M-17)): the rain depth of a sub-step is the hyetograph's exact integral in
// metres, infiltration takes f dt or all a cell holds and keeps its velocity, and in the solver
// rain wets a dry basin, infiltration drains one to exactly dry, and the balance counts both so
// that it closes to round-off (1e-12 relative: each sub-step adds a rounding of ~1e-16 of the
// volume, over a few thousand sub-steps).
#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "flow/fv/fv_solver.hpp"
#include "flow/fv/rain_source.hpp"
#include "fv_test_cases.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

constexpr double mm_h = millimetres_per_hour;  // [m/s] in 1 mm/h

Mesh basin_mesh() {
  return make_rectangle_mesh({0.0, 0.0, 10.0, 4.0, 10, 4, true});
}

RainConfig rain(TimeSeries intensity, double infiltration = 0.0) {
  RainConfig r;
  r.enabled = true;
  r.intensity = std::move(intensity);
  r.infiltration = infiltration;
  return r;
}

TEST(RainSource, DepthIsTheHyetographsIntegralInMetres) {
  const Mesh mesh = basin_mesh();
  const CellMesh cells = build_cell_mesh(mesh, FvCells::elements);
  // 36 mm/h for 100 s is 1 mm.
  EXPECT_NEAR(RainSource(rain(TimeSeries(36.0)), cells).depth(50.0, 150.0), 1e-3, 1e-18);
  // A triangle rising to 72 mm/h at 100 s and falling to 0 at 200 s: 3.6 mm/h x 200 s = 2 mm.
  const RainSource storm(rain(TimeSeries({{0.0, 0.0}, {100.0, 72.0}, {200.0, 0.0}})), cells);
  EXPECT_NEAR(storm.depth(0.0, 200.0), 2e-3, 1e-18);
  EXPECT_NEAR(storm.depth(0.0, 100.0), 1e-3, 1e-18);
  EXPECT_NEAR(storm.depth(90.0, 110.0), 20.0 * 0.5 * (64.8 + 72.0) * mm_h, 1e-18);
  EXPECT_EQ(storm.depth(200.0, 500.0), 0.0);
  EXPECT_FALSE(storm.infiltrating());
  // No rain configured: nothing falls.
  EXPECT_EQ(RainSource(RainConfig{}, cells).depth(0.0, 100.0), 0.0);
  EXPECT_FALSE(RainSource(RainConfig{}, cells).raining());
}

TEST(RainSource, WeightsScaleTheWeightedArea) {
  const Mesh mesh = basin_mesh();
  const CellMesh cells = build_cell_mesh(mesh, FvCells::elements);
  RainSource source(rain(TimeSeries(10.0)), cells);
  EXPECT_NEAR(source.weighted_area(), 40.0, 1e-12);  // every weight 1: the domain's area
  std::vector<double> w(cells.cell_count, 0.0);
  double expected = 0.0;
  for (int i = 0; i < cells.cell_count; ++i) {
    w[i] = cells.centroid[i].x() < 5.0 ? 2.0 : 0.0;  // twice the rain on the left half
    expected += cells.area[i] * w[i];
  }
  source.set_weights(w);
  EXPECT_NEAR(source.weighted_area(), 40.0, 1e-12);
  EXPECT_EQ(source.weighted_area(), expected);
  EXPECT_EQ(source.weights(), w);
}

// A raster of 5 m pixels over [0, 10] x [0, 4] m (2 x 1, values `left` and `right`).
std::shared_ptr<const Raster> two_pixel_raster(double left, double right, double y0 = 0.0) {
  RasterGrid g;
  g.columns = 2;
  g.rows = 1;
  g.transform = {0.0, 5.0, 0.0, y0 + 4.0, 0.0, -4.0};
  return std::make_shared<const Raster>(g, std::vector{left, right}, -9999.0);
}

TEST(RainSource, WeightsAreTheRasterPixelUnderEachCentroid) {
  const Mesh mesh = basin_mesh();
  const CellMesh cells = build_cell_mesh(mesh, FvCells::elements);
  RainConfig r = rain(TimeSeries(10.0));
  r.raster = two_pixel_raster(0.5, 2.0);
  const RainSource source(r, cells);
  for (int i = 0; i < cells.cell_count; ++i)  // exact: the weights are the pixels' values
    EXPECT_EQ(source.weights()[i], cells.centroid[i].x() < 5.0 ? 0.5 : 2.0) << "cell " << i;
  EXPECT_NEAR(source.weighted_area(), 20.0 * 0.5 + 20.0 * 2.0, 1e-12);
}

TEST(RainSource, RasterMustGiveEveryCellAWeight) {
  const Mesh mesh = basin_mesh();
  const CellMesh cells = build_cell_mesh(mesh, FvCells::elements);
  const auto error_of = [&](std::shared_ptr<const Raster> raster) {
    RainConfig r = rain(TimeSeries(10.0));
    r.raster = std::move(raster);
    r.raster_origin = "storm.yaml:7: flow.rain.raster";
    try {
      RainSource source(r, cells);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // The message names the first cell in the numbering that has no weight: the first whose
  // centroid lies in the left pixel (x < 5 m), or below the raster's extent (y < 0.9 m).
  const auto first_cell = [&](auto outside) {
    int i = 0;  // the last cell when none is (the expectation then fails)
    while (i + 1 < cells.cell_count && !outside(cells.centroid[i])) ++i;
    const Vec2 p = cells.centroid[i];
    return fmt::format("cell {} at ({:.3f}, {:.3f}) m: ", i, p.x(), p.y());
  };
  const std::string at = first_cell([](const Vec2& p) { return p.x() < 5.0; });
  const std::string below = first_cell([](const Vec2& p) { return p.y() < 0.9; });
  EXPECT_EQ(error_of(two_pixel_raster(-9999.0, 1.0)),
            "storm.yaml:7: flow.rain.raster: the rain raster '' gives no weight to " + at +
                "its pixel (column 0, row 0) holds nodata; the raster must cover every cell with "
                "a weight >= 0 (0: no rain)");
  EXPECT_EQ(error_of(two_pixel_raster(-0.5, 1.0)),
            "storm.yaml:7: flow.rain.raster: the rain raster '' gives no weight to " + at +
                "its pixel (column 0, row 0) holds -0.5; a weight must be finite and >= 0; the "
                "raster must cover every cell with a weight >= 0 (0: no rain)");
  EXPECT_EQ(error_of(two_pixel_raster(1.0, 1.0, 0.9)),  // it starts at y = 0.9 m
            "storm.yaml:7: flow.rain.raster: the rain raster '' gives no weight to " + below +
                "it lies outside the raster's extent; the raster must cover every cell with a "
                "weight >= 0 (0: no rain)");
  EXPECT_EQ(error_of(two_pixel_raster(0.0, 1.0)), "no error");  // 0: no rain there
}

TEST(RainSource, InfiltrationTakesAtMostWhatACellHolds) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 2.0, 1.0, 1, 1, true});  // two cells
  const CellMesh cells = build_cell_mesh(mesh, FvCells::elements);
  ASSERT_EQ(cells.cell_count, 2);
  RainSource source(rain(TimeSeries(0.0), 36.0), cells);  // f = 1e-5 m/s
  ASSERT_TRUE(source.infiltrating());
  EXPECT_NEAR(source.infiltration_rate(), 1e-5, 1e-20);
  std::vector<double> h = {0.5, 2e-4}, hu = {0.25, 1e-4}, hv = {-0.1, 3e-5};
  const double dt = 100.0;  // [s]: f dt = 1 mm
  const double volume = source.infiltrate(h, hu, hv, dt);
  EXPECT_NEAR(h[0], 0.499, 1e-15);
  EXPECT_NEAR(hu[0] / h[0], 0.5, 1e-15);  // the velocity is kept
  EXPECT_NEAR(hv[0] / h[0], -0.2, 1e-15);
  EXPECT_EQ(h[1], 0.0);  // held less than f dt: emptied, at rest
  EXPECT_EQ(hu[1], 0.0);
  EXPECT_EQ(hv[1], 0.0);
  EXPECT_NEAR(volume, cells.area[0] * 1e-3 + cells.area[1] * 2e-4, 1e-16);
}

// One sub-step on a lake at rest: the fluxes cancel (well balanced), so every cell rises by the
// sub-step's rain depth exactly, and the water stays still.
TEST(FvRain, OneSubStepRaisesALakeAtRestByTheRainDepth) {
  const Mesh mesh = basin_mesh();
  Case c = test::closed_basin_case(1.0);
  c.flow.rain = rain(TimeSeries(180.0));  // 5e-5 m/s
  FiniteVolumeSolver s(mesh, c);
  s.initialize();
  const double dt = 0.5 * s.courant_step();
  s.advance(dt);
  ASSERT_EQ(s.sub_steps().count, 1);
  for (int i = 0; i < s.cells().cell_count; ++i) {
    EXPECT_NEAR(s.state().h[i], 1.0 + 180.0 * mm_h * dt, 1e-15) << "cell " << i;
    EXPECT_LE(std::abs(s.state().hu[i]) + std::abs(s.state().hv[i]), 1e-15) << "cell " << i;
  }
  EXPECT_NEAR(s.water_balance().rain, 180.0 * mm_h * dt * 40.0, 1e-15);
  EXPECT_LT(std::abs(s.water_balance().relative_error()), 1e-14);
}

// A dry, still basin has no wave speed: the first sub-step takes the whole step, and the rain
// makes a film of depth i t everywhere, which then stays flat.
TEST(FvRain, RainWetsADryBasin) {
  const Mesh mesh = basin_mesh();
  Case c = test::closed_basin_case(-1.0);  // the surface below the bed: dry
  c.flow.rain = rain(TimeSeries(36.0));    // 1e-5 m/s
  FiniteVolumeSolver s(mesh, c);
  s.initialize();
  ASSERT_EQ(s.volume(), 0.0);
  s.advance(10.0);
  EXPECT_EQ(s.sub_steps().count, 1);
  for (int i = 0; i < s.cells().cell_count; ++i) EXPECT_NEAR(s.state().h[i], 1e-4, 1e-18);
  for (int n = 0; n < 9; ++n) s.advance(10.0);
  EXPECT_GT(s.sub_steps().count, 10);  // wet: Courant-limited sub-steps
  for (int i = 0; i < s.cells().cell_count; ++i) {
    EXPECT_NEAR(s.state().h[i], 1e-3, 1e-15) << "cell " << i;
    EXPECT_LE(std::abs(s.state().hu[i]) + std::abs(s.state().hv[i]), 1e-15) << "cell " << i;
  }
  EXPECT_NEAR(s.water_balance().rain, 1e-3 * 40.0, 1e-15);
  EXPECT_LT(std::abs(s.water_balance().relative_error()), 1e-12);
}

// Infiltration with no rain empties a basin of 2 cm at 72 mm/h in 1,000 s, to exactly dry, and
// what it took is the whole volume: a cell never gives more than it holds.
TEST(FvRain, InfiltrationDrainsABasinToExactlyDry) {
  const Mesh mesh = basin_mesh();
  Case c = test::closed_basin_case(0.02);
  c.flow.rain = rain(TimeSeries(0.0), 72.0);  // 2e-5 m/s
  FiniteVolumeSolver s(mesh, c);
  s.initialize();
  const double V0 = s.volume();
  for (int n = 0; n < 5; ++n) s.advance(100.0);
  for (int i = 0; i < s.cells().cell_count; ++i) EXPECT_NEAR(s.state().h[i], 0.01, 1e-14);
  EXPECT_NEAR(s.water_balance().infiltration, 0.5 * V0, 1e-12 * V0);
  for (int n = 0; n < 6; ++n) s.advance(100.0);
  for (int i = 0; i < s.cells().cell_count; ++i) {
    EXPECT_EQ(s.state().h[i], 0.0) << "cell " << i;
    EXPECT_EQ(s.state().hu[i], 0.0) << "cell " << i;
  }
  EXPECT_NEAR(s.water_balance().infiltration, V0, 1e-12 * V0);
  EXPECT_EQ(s.water_balance().rain, 0.0);
  EXPECT_LT(std::abs(s.water_balance().relative_error()), 1e-12);
}

// Rain weighted per cell (twice on the left half, none on the right), infiltration, a sloping
// bed, water leaving at an elevation boundary: the water moves, and the balance still closes.
TEST(FvRain, WaterBalanceClosesWithWeightedRainInfiltrationAndOutflow) {
  const Mesh mesh = basin_mesh();
  Case c = test::closed_basin_case(0.0);
  c.bed.kind = BedConfig::Kind::slope;
  c.bed.slope = Vec2(0.01, 0.002);
  c.flow.initial_eta = Expression("x < 5 ? 0.1 : -1", "test: flow.initial.eta");  // half dry
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = 0.03;
  c.flow.rain = rain(TimeSeries({{0.0, 0.0}, {20.0, 3600.0}, {40.0, 0.0}}), 360.0);
  test::condition_of(c, "right") = {BoundaryCondition::Kind::free, "right", {}, {}};
  FiniteVolumeSolver s(mesh, c);
  s.initialize();
  std::vector<double> w(s.cells().cell_count);
  for (int i = 0; i < s.cells().cell_count; ++i) w[i] = s.cells().centroid[i].x() < 5.0 ? 2.0 : 0;
  s.set_rain_weights(w);
  for (int n = 0; n < 12; ++n) s.advance(5.0);
  const WaterBalance& b = s.water_balance();
  // The hyetograph's depth over 60 s is 20 mm (3600 mm/h over a triangle of 40 s), on twice the
  // left half's area (20 m^2 x 2).
  EXPECT_NEAR(b.rain, 0.02 * 40.0, 1e-14);
  EXPECT_GT(b.infiltration, 0.0);
  EXPECT_GT(b.outflow, 0.0);
  EXPECT_LT(std::abs(b.relative_error()), 1e-12);
}

}  // namespace
}  // namespace flotsam
