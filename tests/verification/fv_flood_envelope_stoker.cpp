// Verifies the flood envelopes (flow/flood_envelope.hpp) on a flow whose maxima are known:
// Stoker's dam break (tests/support/stoker.hpp), h_l = 1 m behind a dam at x0 = 10 m of the
// 20 m channel, h_r = 0.1 m in front, run for 2.5 s (the shock reaches x = 20 m at 2.9 s, the
// rarefaction's tail passes x = 12 m after 3.5 s). At the gauge x = 12 m the shock arrives at
// t_a = 2 m / s and the water then stays at the middle state (h_m, u_m) to the end, so:
//   max H = h_m, max |u| = u_m, max H|u| = h_m u_m; with output.wet_depth between h_r and h_m
//   the arrival time is t_a and the wet duration 2.5 s - t_a.
// Checked, through a whole run (Simulation) with a gauge and GeoTIFF rasters:
//   - the envelope's max H at the gauge's cell equals the maximum of the gauge's series to the
//     CSV's 9 digits (the coupling step, 0.01 s, is below the Courant step, so the gauge sees
//     every sub-step the envelope sees; at 0.05 s it misses the shock's 1.3 % overshoot), and
//     h_m within 2 %;
//     max |u| and max H|u| within 3 % of u_m and h_m u_m (the shock's numerical overshoot);
//   - arrival time within two cell widths / s of t_a, wet duration = end - arrival (1e-9 s);
//   - the GeoTIFF of max H read back with GDAL: the run's coordinate system, pixels aligned on
//     the resolution, and the pixel over the gauge holds its cell's value exactly;
//   - the hazard rating (M-H1) at the gauge within 3 % of the middle state's h_m (u_m + 0.5),
//     its class and the Australian class (M-H3) those of the middle state, and the hazard
//     rasters' pixel over the gauge its cell's values exactly.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "../support/fv_cases.hpp"
#include "../support/scratch_path.hpp"
#include "../support/stoker.hpp"
#include "coupling/simulation.hpp"
#include "flow/hazard.hpp"
#include "geo/raster.hpp"

namespace flotsam {
namespace {

using test::DamBreakChannel;

constexpr double g = 9.81, h_l = 1.0, h_r = 0.1, t_end = 2.5, x_gauge = 12.0;  // SI units
const test::Stoker stoker(g, h_l, h_r);

/// The largest depth in the gauge's series (column 2 of <name>_probes.csv).
double probe_maximum(const std::filesystem::path& csv_path) {
  std::ifstream csv(csv_path);
  std::string line;
  std::getline(csv, line);  // header
  double largest = 0.0;
  while (std::getline(csv, line)) {
    std::stringstream fields(line);
    std::string t, eta, H;
    std::getline(fields, t, ',');
    std::getline(fields, eta, ',');
    std::getline(fields, H, ',');
    largest = std::max(largest, std::stod(H));
  }
  return largest;
}

TEST(FvFloodEnvelope, StokerMaximaArrivalAndDurationMatchTheExactSolutionAndTheGauge) {
  const auto dir = test::fresh_test_folder("flotsam_flood_envelope");
  Case c = test::dam_break_case(h_l, h_r);
  c.name = "stoker";
  c.time.end = t_end;
  c.time.step = 0.01;
  c.time.mode = CouplingMode::one_way;
  c.output.interval = t_end;
  c.output.wet_depth = 0.5 * (h_r + stoker.h_m);
  c.output.probes = {{"gauge", Vec2(x_gauge, 0.2), 0}};
  c.output.raster_resolution = 0.04;
  c.crs_wkt = coordinate_system_wkt("EPSG:32633", "test");
  Simulation run(c, test::dam_break_mesh(1),
                 {.output_directory = dir, .overwrite = true, .progress = false});
  run.run();
  const auto& engine = dynamic_cast<const FvEngine&>(run.flow());
  const FloodEnvelope& e = engine.envelope();
  int hint = -1;
  const int cell = engine.field_cell_of({x_gauge, 0.2}, hint);
  ASSERT_GE(cell, 0);
  const double dx = test::cell_width(engine.solver().cells());
  const double t_a = (x_gauge - DamBreakChannel::x_dam) / stoker.s;
  const double gauge_max = probe_maximum(dir / "stoker_probes.csv");
  std::printf(
      "envelope at x = %.1f m: max H %.5f m (gauge %.5f m, exact %.5f m), max |u| %.4f m/s "
      "(exact %.4f), max H|u| %.4f m^2/s (exact %.4f), arrival %.4f s (exact %.4f s, %+.2f "
      "cells), wet %.4f s\n",
      x_gauge, e.max_depth[cell], gauge_max, stoker.h_m, e.max_speed[cell], stoker.u_m,
      e.max_unit_discharge[cell], stoker.h_m * stoker.u_m, e.arrival[cell], t_a,
      (e.arrival[cell] - t_a) * stoker.s / dx, e.wet_duration[cell]);
  std::printf("envelope / gauge maximum - 1 = %.2e\n", e.max_depth[cell] / gauge_max - 1.0);
  EXPECT_NEAR(e.max_depth[cell] / gauge_max, 1.0, 1e-8);
  EXPECT_NEAR(e.max_depth[cell] / stoker.h_m, 1.0, 0.02);
  EXPECT_NEAR(e.max_speed[cell] / stoker.u_m, 1.0, 0.03);
  EXPECT_NEAR(e.max_unit_discharge[cell] / (stoker.h_m * stoker.u_m), 1.0, 0.03);
  EXPECT_LE(std::abs(e.arrival[cell] - t_a), 2.0 * dx / stoker.s);
  EXPECT_NEAR(e.wet_duration[cell], t_end - e.arrival[cell], 1e-9);

  const Raster max_depth = Raster::read((dir / "stoker_max_depth.tif").string(), "test");
  OGRSpatialReference written, read;
  written.importFromWkt(c.crs_wkt.c_str());
  read.importFromWkt(max_depth.grid().crs_wkt.c_str());
  EXPECT_TRUE(read.IsSame(&written));
  EXPECT_EQ(max_depth.grid().transform[0], 0.0);
  EXPECT_EQ(max_depth.grid().transform[3], 0.4);
  EXPECT_EQ(max_depth.grid().columns, 500);
  EXPECT_EQ(max_depth.grid().rows, 10);
  const Vec2 pixel_centre(x_gauge + 0.06, 0.22);  // a pixel near it, inside one cell
  int h2 = -1;
  const int under = engine.field_cell_of(pixel_centre, h2);
  ASSERT_EQ(*max_depth.nearest(pixel_centre), e.max_depth[under]);

  // Hazard: behind the shock the middle state holds, HR = h_m (u_m + 0.5) (no bodies: DF = 0);
  // its class and the Australian one follow from it, and the rasters hold the cell's values.
  const double hr = stoker.h_m * (stoker.u_m + 0.5);
  std::printf("hazard rating at the gauge %.4f (middle state %.4f), Australian class H%g\n",
              e.max_hazard_rating[cell], hr, e.australian_class[cell]);
  EXPECT_NEAR(e.max_hazard_rating[cell] / hr, 1.0, 0.03);
  EXPECT_EQ(e.australian_class[cell], australian_hazard_class(stoker.h_m, stoker.u_m));
  EXPECT_EQ(e.hazard_rating_class()[cell], hazard_rating_class(hr));
  for (auto [name, values] : {std::pair{"hazard_rating", e.max_hazard_rating},
                              std::pair{"hazard_rating_class", e.hazard_rating_class()},
                              std::pair{"australian_hazard_class", e.australian_class},
                              std::pair{"vehicle_class", e.vehicle_class}}) {
    const Raster raster = Raster::read((dir / fmt::format("stoker_{}.tif", name)).string(), "test");
    EXPECT_EQ(*raster.nearest(pixel_centre), values[under]) << name;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace flotsam
