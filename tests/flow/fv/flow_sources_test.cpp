// Unit tests of sources in the finite-volume engine (flow/fv/flow_sources.hpp, docs/model.md
// (M-24)): a point source lands in the cell holding it, a polygon on the cells whose centroids
// it holds; a sub-step's depths are the hydrograph's exact integral over the source's area; a
// source that lands on no cell is an error naming it; in the solver a source over the whole of a
// closed basin raises it exactly and leaves it at rest, and a point source's water is in the
// balance to round-off (1e-12 relative over some thousand sub-steps).
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "flow/fv/flow_sources.hpp"
#include "flow/fv/fv_solver.hpp"
#include "fv_test_cases.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

Mesh basin_mesh() {
  return make_rectangle_mesh({0.0, 0.0, 10.0, 4.0, 10, 4, true});
}

FlowSource point_source(Vec2 p, TimeSeries Q) {
  FlowSource s;
  s.name = "culvert";
  s.point = p;
  s.discharge = std::move(Q);
  s.origin = "case.yaml:9: flow.sources[0] (culvert)";
  return s;
}

FlowSource polygon_source(std::vector<Vec2> polygon, TimeSeries Q) {
  FlowSource s = point_source(Vec2::Zero(), std::move(Q));
  s.polygon = std::move(polygon);
  return s;
}

TEST(FlowSources, APointLandsInTheCellHoldingIt) {
  const Mesh mesh = basin_mesh();
  const CellMesh cells = build_cell_mesh(mesh, FvCells::split);
  for (const Vec2& p : {Vec2(3.3, 1.7), Vec2(9.9, 0.1), Vec2(0.0, 0.0), Vec2(5.0, 2.0)}) {
    const FlowSources sources({point_source(p, TimeSeries(1.0))}, mesh, cells);
    ASSERT_EQ(sources.cells(0).size(), 1u);
    const int cell = sources.cells(0)[0];
    EXPECT_GE(test::barycentric(mesh, cells, cell, p).minCoeff(), -1e-12) << p.transpose();
    EXPECT_DOUBLE_EQ(sources.area(0), cells.area[cell]);
  }
}

TEST(FlowSources, APolygonTakesTheCellsWhoseCentroidsItHolds) {
  const Mesh mesh = basin_mesh();
  const CellMesh cells = build_cell_mesh(mesh, FvCells::elements);
  // The left half of the basin: its 40 triangles' centroids, none on the line x = 5.
  const FlowSources sources(
      {polygon_source({{-1.0, -1.0}, {5.0, -1.0}, {5.0, 5.0}, {-1.0, 5.0}}, TimeSeries(1.0))}, mesh,
      cells);
  EXPECT_EQ(sources.cells(0).size(), 40u);
  for (int i : sources.cells(0)) EXPECT_LT(cells.centroid[i].x(), 5.0);
  EXPECT_NEAR(sources.area(0), 20.0, 1e-12);
}

// A hydrograph rising to 2 m^3/s at 10 s and falling to 0 at 30 s lets in 30 m^3; between 5 s and
// 15 s, 5 (0.5 + 1) + ... = the trapezoids' sum. Each cell's depth is the volume over the area.
TEST(FlowSources, DepthsAreTheHydrographsIntegralOverTheArea) {
  const Mesh mesh = basin_mesh();
  const CellMesh cells = build_cell_mesh(mesh, FvCells::elements);
  const TimeSeries Q({{0.0, 0.0}, {10.0, 2.0}, {30.0, 0.0}});
  const FlowSources sources({polygon_source({{0, 0}, {10, 0}, {10, 4}, {0, 4}}, Q),
                             point_source({7.2, 3.1}, TimeSeries(0.5))},
                            mesh, cells);
  std::vector<double> depth(cells.cell_count, 0.0);
  EXPECT_NEAR(sources.depths(0.0, 30.0, depth), 30.0 + 15.0, 1e-13);
  const int point_cell = sources.cells(1)[0];
  double volume = 0.0;
  for (int i = 0; i < cells.cell_count; ++i) {
    const double expected = 30.0 / 40.0 + (i == point_cell ? 15.0 / cells.area[i] : 0.0);
    EXPECT_NEAR(depth[i], expected, 1e-14) << "cell " << i;
    volume += cells.area[i] * depth[i];
  }
  EXPECT_NEAR(volume, 45.0, 1e-12);
  // A later interval replaces the depths: 5 s at 1 -> 2 -> 1.5 m^3/s (the trapezoids 7.5 + 8.75)
  // and the point's 5 m^3.
  const double V = sources.depths(5.0, 15.0, depth);
  EXPECT_NEAR(V, 0.5 * 5.0 * (1.0 + 2.0) + 0.5 * 5.0 * (2.0 + 1.5) + 5.0, 1e-13);
  EXPECT_NEAR(depth[point_cell], 16.25 / 40.0 + 5.0 / cells.area[point_cell], 1e-14);
}

TEST(FlowSources, ASourceOnNoCellIsAnErrorNamingIt) {
  const Mesh mesh = basin_mesh();
  const CellMesh cells = build_cell_mesh(mesh, FvCells::split);
  try {
    FlowSources({point_source({12.0, 1.0}, TimeSeries(1.0))}, mesh, cells);
    FAIL() << "a point outside the mesh was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "case.yaml:9: flow.sources[0] (culvert): the point (12.000, 1.000) m lies outside "
              "the mesh 'rectangle 10x4 m, 10x4 cells'");
  }
  // A 4 cm square between the centroids of the 0.5 m split cells.
  const std::vector<Vec2> small = {{0.48, 0.48}, {0.52, 0.48}, {0.52, 0.52}, {0.48, 0.52}};
  try {
    FlowSources({polygon_source(small, TimeSeries(1.0))}, mesh, cells);
    FAIL() << "a polygon holding no centroid was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "case.yaml:9: flow.sources[0] (culvert): no cell's centroid lies inside the polygon "
              "(0.0016 m^2; the cells of the mesh 'rectangle 10x4 m, 10x4 cells' are larger "
              "there, or it lies outside the mesh): give a larger polygon or a point");
  }
}

// A uniform source over the whole of a closed basin: every cell rises by Q t / A, exactly (the
// fluxes of a lake at rest cancel), and the water stays still.
TEST(FvFlowSources, AUniformSourceRaisesAClosedBasinExactly) {
  const Mesh mesh = basin_mesh();
  Case c = test::closed_basin_case(1.0);
  c.flow.sources = {polygon_source({{-1, -1}, {11, -1}, {11, 5}, {-1, 5}}, TimeSeries(0.8))};
  FiniteVolumeSolver s(mesh, c);
  s.initialize();
  for (int n = 0; n < 10; ++n) s.advance(5.0);  // 50 s: 40 m^3 over 40 m^2
  for (int i = 0; i < s.cells().cell_count; ++i) {
    EXPECT_NEAR(s.state().h[i], 2.0, 1e-13) << "cell " << i;
    EXPECT_LE(std::abs(s.state().hu[i]) + std::abs(s.state().hv[i]), 1e-12) << "cell " << i;
  }
  EXPECT_NEAR(s.water_balance().sources, 40.0, 1e-12);
  EXPECT_LT(std::abs(s.water_balance().relative_error()), 1e-14);
}

// A hydrograph through a point into a half-dry basin with a sloping bed: the water spreads from
// the cell, and the balance counts exactly the hydrograph's volume.
TEST(FvFlowSources, APointSourcesWaterIsInTheBalance) {
  const Mesh mesh = basin_mesh();
  Case c = test::closed_basin_case(0.0);
  c.bed.kind = BedConfig::Kind::slope;
  c.bed.slope = Vec2(0.01, 0.0);
  c.flow.initial_eta = Expression("x < 5 ? 0.1 : -1", "test: flow.initial.eta");  // half dry
  c.flow.sources = {point_source({8.3, 2.2}, TimeSeries({{0.0, 0.0}, {20.0, 0.4}, {40.0, 0.0}}))};
  FiniteVolumeSolver s(mesh, c);
  s.initialize();
  const double V0 = s.volume();
  for (int n = 0; n < 12; ++n) s.advance(5.0);
  const WaterBalance& b = s.water_balance();
  EXPECT_NEAR(b.sources, 8.0, 1e-14);  // the triangle: 0.4 m^3/s x 40 s / 2
  EXPECT_NEAR(s.volume(), V0 + 8.0, 1e-12 * (V0 + 8.0));
  EXPECT_LT(std::abs(b.relative_error()), 1e-12);
  int wet_right = 0;  // cells on the dry half that the source's water reached
  for (int i = 0; i < s.cells().cell_count; ++i)
    wet_right += s.cells().centroid[i].x() > 5.0 && s.state().h[i] > 1e-3;
  EXPECT_GT(wet_right, 10);
}

}  // namespace
}  // namespace flotsam
