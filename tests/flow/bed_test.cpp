// The bed from a terrain raster (flow/bed.hpp): sampled exactly where the terrain is bilinear,
// edited by a formula in x, y and z, and a clear error where the raster has no value.
#include "flow/bed.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

using ::testing::HasSubstr;

/// A raster of 1 m pixels over [-2, 22] x [-2, 12] m holding f at the pixel centres.
BedConfig raster_bed(double (*f)(double, double), int nodata_column = -1, int nodata_row = -1) {
  RasterGrid g = RasterGrid::covering({-2.0, -2.0}, {22.0, 12.0}, 1.0, "");
  std::vector<double> v(static_cast<std::size_t>(g.columns) * g.rows);
  for (int r = 0; r < g.rows; ++r)
    for (int c = 0; c < g.columns; ++c) {
      const Vec2 p = g.centre(c, r);
      v[static_cast<std::size_t>(r) * g.columns + c] =
          c == nodata_column && r == nodata_row ? -9999.0 : f(p.x(), p.y());
    }
  BedConfig bed;
  bed.kind = BedConfig::Kind::raster;
  bed.raster = std::make_shared<const Raster>(g, v, -9999.0);
  bed.origin = "case.yaml:3: bed.raster";
  return bed;
}

double bilinear_terrain(double x, double y) {
  return 2.0 - 0.01 * x + 0.03 * y + 0.002 * x * y;
}

Mesh channel() {
  RectangleSpec spec;
  spec.length = 20.0;
  spec.width = 10.0;
  spec.nx = 13;
  spec.ny = 7;
  return make_rectangle_mesh(spec);
}

TEST(Bed, RasterIsSampledExactlyWhereTheTerrainIsBilinear) {
  const Mesh mesh = channel();
  const std::vector<double> z = bed_at_nodes(mesh, raster_bed(bilinear_terrain));
  double worst = 0.0;
  for (int k = 0; k < mesh.node_count(); ++k)
    worst =
        std::max(worst, std::abs(z[k] - bilinear_terrain(mesh.nodes[k].x(), mesh.nodes[k].y())));
  EXPECT_LE(worst, 1e-12);
}

TEST(Bed, AFormulaEditsTheRaster) {  // a levee 1 m above the terrain along y = 5 m
  BedConfig bed = raster_bed(bilinear_terrain);
  bed.expression = Expression("abs(y - 5) < 1 ? z + 1 : z", "case.yaml:4: bed.expression", true);
  EXPECT_NEAR(bed_elevation(bed, {10.0, 5.0}), bilinear_terrain(10.0, 5.0) + 1.0, 1e-12);
  EXPECT_NEAR(bed_elevation(bed, {10.0, 8.0}), bilinear_terrain(10.0, 8.0), 1e-12);
}

TEST(Bed, NodataInsideTheDomainNamesTheNodeElementAndPosition) {
  const Mesh mesh = channel();
  std::string message = "no error";
  try {
    bed_at_nodes(mesh, raster_bed(bilinear_terrain, 9, 6));  // the pixel around (9.5, 5.5) m
  } catch (const InputError& e) {
    message = e.what();
  }
  EXPECT_THAT(message, HasSubstr("case.yaml:3: bed.raster: the terrain raster"));
  EXPECT_THAT(message, HasSubstr("has no value at node "));
  EXPECT_THAT(message, HasSubstr(" of element "));
  EXPECT_THAT(message, HasSubstr("holds nodata"));
}

TEST(Bed, ARasterSmallerThanTheDomainIsAnError) {
  BedConfig bed = raster_bed(bilinear_terrain);
  try {
    bed_elevation(bed, {30.0, 5.0});
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_THAT(
        std::string(e.what()),
        HasSubstr("(x, y) = (30.000, 5.000) m: the point lies outside the raster's extent"));
  }
}

}  // namespace
}  // namespace flotsam
