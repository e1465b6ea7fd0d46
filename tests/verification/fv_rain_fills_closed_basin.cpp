// Verifies that rain on a closed flat basin (walls all round) raises its level by exactly the
// hyetograph's depth minus the infiltration, h(t) = h0 + int_0^t i - f t (the continuity
// equation (M-17) of a basin whose surface stays flat: no flux anywhere), starting wet and
// starting dry, and that the water balance closes. Tolerances: the depth within 1e-12 of
// itself in every cell at every coupling step, the balance within 1e-12 relative; both are
// sums of ~10^4 sub-steps, each rounding at ~1e-16.
//
// With a rain raster of two weights (flow.rain.raster, 0.5 over one half, 2 over the other): on
// two closed basins side by side each cell's level rises by exactly w times the hyetograph's
// depth, less the infiltration, h0 + w int_0^t i - f t (same tolerances); in one basin, where
// the two rains make the water flow, the balance closes to 1e-12 and the rain fallen is
// sum_i A_i w_i int i to 1e-12.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "../support/fv_cases.hpp"
#include "../support/scratch_path.hpp"
#include "core/constants.hpp"
#include "geo/raster.hpp"

namespace flotsam {
namespace {

// A storm [mm/h] over 40 minutes: from 20 to 120 mm/h in 10 minutes, down to 30 mm/h, then
// stopping at 30 minutes; f = 10 mm/h soaks away all along. The intensity starts above f, so a
// basin that starts dry is wet after its first sub-step, and h0 + int i - f t stays > 0.
const TimeSeries storm({{0.0, 20.0}, {600.0, 120.0}, {1200.0, 30.0}, {1800.0, 0.0}});
constexpr double infiltration = 10.0;  // f [mm/h]
constexpr double end = 2400.0;         // [s]
constexpr double step = 60.0;          // [s] coupling step

// h0 + w int_0^t i - f t [m], with the storm's integral by hand: trapezoids of its rows.
double exact_depth(double h0, double t, double w = 1.0) {
  double rain = 0.0;  // [mm h^-1 s]
  const auto& rows = storm.points();
  for (std::size_t k = 0; k + 1 < rows.size(); ++k) {
    const double t0 = rows[k].first, t1 = std::min(rows[k + 1].first, t);
    if (t1 <= t0) break;
    const double i0 = rows[k].second, i1 = storm(t1);
    rain += 0.5 * (t1 - t0) * (i0 + i1);
  }
  return h0 + (w * rain - infiltration * t) * millimetres_per_hour;
}

struct BasinRun {
  double depth_error = 0.0;  // [-] largest |h - h_exact| / h_exact over cells and steps
  double balance = 0.0;      // [-] largest |relative balance error| over the steps
  double rain = 0.0;         // [m^3] rain fallen
  double expected_rain = 0.0;
  long sub_steps = 0;
};

BasinRun rain_on_basin(double h0) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 20.0, 10.0, 10, 5, true});
  Case c = test::fv_case({"left", "right", "bottom", "top"});
  c.flow.initial_eta_start = c.flow.initial_eta_end = h0 > 0.0 ? h0 : -1.0;  // -1: dry
  c.flow.rain.enabled = true;
  c.flow.rain.intensity = storm;
  c.flow.rain.infiltration = infiltration;
  FvEngine engine(mesh, c);
  engine.initialize();
  BasinRun r;
  while (engine.time() < end - 1e-9) {
    engine.step(step);
    const double exact = exact_depth(h0, engine.time());
    for (double h : engine.solver().state().h)
      r.depth_error = std::max(r.depth_error, std::abs(h - exact) / exact);
    r.balance = std::max(r.balance, std::abs(engine.water_balance().relative_error()));
  }
  r.rain = engine.water_balance().rain;
  r.expected_rain = (exact_depth(0.0, end) + infiltration * end * millimetres_per_hour) * 200.0;
  r.sub_steps = engine.solver().sub_steps().count;
  return r;
}

TEST(FvRainFillsClosedBasin, LevelRisesByTheRainLessTheInfiltration) {
  for (double h0 : {0.5, 0.0}) {  // [m] wet, then dry
    const BasinRun r = rain_on_basin(h0);
    EXPECT_LE(r.depth_error, 1e-12) << "h0 = " << h0;
    EXPECT_LE(r.balance, 1e-12) << "h0 = " << h0;
    EXPECT_NEAR(r.rain, r.expected_rain, 1e-12 * r.expected_rain) << "h0 = " << h0;
    std::printf(
        "FV rain on a closed basin, h0 = %g m: depth error %.2e, balance %.2e, rain %.12g m^3 "
        "(relative error %.1e), %ld sub-steps\n",
        h0, r.depth_error, r.balance, r.rain, r.rain / r.expected_rain - 1.0, r.sub_steps);
  }
}

// ---- a rain raster of two weights -------------------------------------------------------------

constexpr double w_left = 0.5, w_right = 2.0;  // [-] the raster's two pixels

// Two pixels of 10.5 m x 10 m over [0, 21] x [0, 10] m holding w_left and w_right, written as a
// GeoTIFF and read back as a case reads it.
std::shared_ptr<const Raster> two_weight_raster() {
  RasterGrid g;
  g.columns = 2;
  g.rows = 1;
  g.transform = {0.0, 10.5, 0.0, 10.0, 0.0, -10.0};
  const std::string path = test::scratch_path("rain_weights.tif").string();
  write_geotiff(path, g, {w_left, w_right});
  return std::make_shared<const Raster>(Raster::read(path, "test: flow.rain.raster"));
}

// Two closed basins of 10 m x 10 m, [0, 10] and [11, 21] x [0, 10] m, in one mesh: walls all
// round each.
Mesh two_basins_mesh() {
  RawMesh raw = make_rectangle_raw({0.0, 0.0, 10.0, 10.0, 5, 5, true});
  const RawMesh right = make_rectangle_raw({11.0, 0.0, 10.0, 10.0, 5, 5, true});
  const int offset = static_cast<int>(raw.nodes.size());
  raw.nodes.insert(raw.nodes.end(), right.nodes.begin(), right.nodes.end());
  for (std::vector<int> t : right.triangles) {
    for (int& k : t) k += offset;
    raw.triangles.push_back(t);
  }
  for (RawMesh::Line line : right.lines) {
    for (int& k : line.nodes) k += offset;
    raw.lines.push_back(line);
  }
  return build_mesh(raw);
}

struct WeightedRun {
  double depth_error = 0.0;  // [-] largest |h - h_exact(w_i)| / h_exact over cells and steps
  double balance = 0.0;      // [-] largest |relative balance error| over the steps
  double rain = 0.0, expected_rain = 0.0;  // [m^3]
};

WeightedRun weighted_rain(const Mesh& mesh, double h0, bool exact_per_cell) {
  Case c = test::fv_case({"left", "right", "bottom", "top"});
  c.flow.initial_eta_start = c.flow.initial_eta_end = h0;
  c.flow.rain.enabled = true;
  c.flow.rain.intensity = storm;
  c.flow.rain.infiltration = infiltration;
  c.flow.rain.raster = two_weight_raster();
  c.flow.rain.raster_origin = "test: flow.rain.raster";
  FvEngine engine(mesh, c);
  engine.initialize();
  const CellMesh& cells = engine.solver().cells();
  double weighted_area = 0.0;  // sum_i A_i w_i [m^2]
  for (int i = 0; i < cells.cell_count; ++i)
    weighted_area += cells.area[i] * (cells.centroid[i].x() < 10.5 ? w_left : w_right);
  WeightedRun r;
  while (engine.time() < end - 1e-9) {
    engine.step(step);
    for (int i = 0; exact_per_cell && i < cells.cell_count; ++i) {
      const double w = cells.centroid[i].x() < 10.5 ? w_left : w_right;
      const double exact = exact_depth(h0, engine.time(), w);
      r.depth_error =
          std::max(r.depth_error, std::abs(engine.solver().state().h[i] - exact) / exact);
    }
    r.balance = std::max(r.balance, std::abs(engine.water_balance().relative_error()));
  }
  r.rain = engine.water_balance().rain;
  r.expected_rain =
      (exact_depth(0.0, end) + infiltration * end * millimetres_per_hour) * weighted_area;
  return r;
}

TEST(FvRainFillsClosedBasin, RasterWeightsRaiseEachCellByItsShareOfTheRain) {
  const WeightedRun r = weighted_rain(two_basins_mesh(), 0.5, true);
  EXPECT_LE(r.depth_error, 1e-12);
  EXPECT_LE(r.balance, 1e-12);
  EXPECT_NEAR(r.rain, r.expected_rain, 1e-12 * r.expected_rain);
  std::printf(
      "FV rain raster of weights %g and %g on two basins: depth error %.2e, balance %.2e, rain "
      "%.12g m^3 (relative error %.1e)\n",
      w_left, w_right, r.depth_error, r.balance, r.rain, r.rain / r.expected_rain - 1.0);
}

TEST(FvRainFillsClosedBasin, RasterWeightsKeepTheBalanceWhereTheWaterFlows) {
  const WeightedRun r =
      weighted_rain(make_rectangle_mesh({0.0, 0.0, 21.0, 10.0, 21, 10, true}), 0.5, false);
  EXPECT_LE(r.balance, 1e-12);
  EXPECT_NEAR(r.rain, r.expected_rain, 1e-12 * r.expected_rain);
  std::printf(
      "FV rain raster of weights %g and %g on one basin: balance %.2e, rain %.12g m^3 (relative "
      "error %.1e)\n",
      w_left, w_right, r.balance, r.rain, r.rain / r.expected_rain - 1.0);
}

}  // namespace
}  // namespace flotsam
