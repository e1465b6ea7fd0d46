// Unit tests of the piers' form drag (flow/fv/pier_drag.hpp, docs/model.md (M-25)): each pier's
// width (a meshed circle's diameter, an outline's smallest width) and ring, the ring's drag summing
// to C_d b / 2 exactly, none with C_d = 0, and a lake at rest around piers staying at rest to
// round-off with the drag on.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../../support/two_pier_channel.hpp"
#include "flow/fv/fv_solver.hpp"
#include "mesh/mesh_generator.hpp"

namespace flotsam {
namespace {

Mesh channel_mesh() {
  MeshSource source = test::two_pier_channel();  // piers r = 10 m at (60, 30), 8 m at (140, 25)
  source.element_order = 1;
  return generate_mesh(source);
}

// A region 20 m wide from x = 0 to `length` with the given circular piers and pier outlines,
// meshed at 2 m refined to `pier_mesh_size` on the piers, in three-node triangles.
Mesh region_with_piers(double length, std::vector<Pier> piers, std::vector<NamedRing> outlines,
                       double pier_mesh_size, double refine_distance) {
  MeshSource source;
  source.kind = MeshSource::Kind::region;
  source.element_order = 1;
  RegionGeometry& r = source.region;
  r.outline = {{{0, 0}, {length, 0}, {length, 20}, {0, 20}}, "outline"};
  r.piers = std::move(piers);
  r.pier_outlines = std::move(outlines);
  r.mesh_size = 2.0;
  r.pier_mesh_size = pier_mesh_size;
  r.refine_distance = refine_distance;
  return generate_mesh(source);
}

Case still_water_around_piers(const Mesh& mesh) {
  Case c;
  c.name = "piers";
  c.mesh.kind = MeshSource::Kind::file;
  c.flow.engine = FlowEngineKind::fv;
  c.flow.initial_eta_start = c.flow.initial_eta_end = 2.0;
  for (const std::string& group : mesh.group_names)
    c.flow.boundaries.push_back(
        {BoundaryCondition::Kind::wall, group, TimeSeries(0.0), TimeSeries(0.0)});
  return c;
}

TEST(PierDrag, EachPiersRingTakesCdTimesItsWidthOverTwo) {
  const Mesh mesh = channel_mesh();
  const CellMesh cells = build_cell_mesh(mesh, FvCells::elements);
  const double Cd = 1.2;
  const PierDrag drag = find_pier_drag(mesh, cells, {}, Cd);
  ASSERT_EQ(drag.piers.size(), 2u);
  const Vec2 centre[2] = {{60, 30}, {140, 25}};
  const double radius[2] = {10, 8};
  double expected = 0.0, sum = 0.0;
  for (int p = 0; p < 2; ++p) {
    // A meshed circle (2 m sides on a 10 m circle) is the circle: its diameter.
    EXPECT_NEAR(drag.piers[p].width, 2 * radius[p], 1e-9 * radius[p]) << drag.piers[p].name;
    expected += 0.5 * Cd * drag.piers[p].width;
  }
  for (const int i : drag.cells) {
    sum += cells.area[i] * drag.density[i];
    // Each ring cell's centroid lies within one width of its pier's circle (and outside it).
    const int p = (cells.centroid[i] - centre[0]).norm() < 40.0 ? 0 : 1;
    const double d = (cells.centroid[i] - centre[p]).norm() - radius[p];
    EXPECT_GT(d, 0.0);
    EXPECT_LE(d, drag.piers[p].width + 1e-9);
  }
  EXPECT_NEAR(sum, expected, 1e-12 * expected);
  EXPECT_EQ(drag.piers[0].ring.size() + drag.piers[1].ring.size(), drag.cells.size());
  EXPECT_TRUE(find_pier_drag(mesh, cells, {}, 0.0).empty());
}

TEST(PierDrag, AnOutlinesWidthIsItsSmallestAndACirclesItsDiameter) {
  const Mesh mesh =
      region_with_piers(60.0, {{{15, 10}, 0.75}},  // pier_1; pier_2 a wall:
                        {{{{28, 9.5}, {32, 9.5}, {32, 10.5}, {28, 10.5}}, "wall"}}, 0.5, 5.0);
  const CellMesh cells = build_cell_mesh(mesh, FvCells::elements);
  const PierDrag drag = find_pier_drag(mesh, cells, {}, 2.0);
  ASSERT_EQ(drag.piers.size(), 2u);
  EXPECT_EQ(drag.piers[0].name, "pier_1");
  EXPECT_NEAR(drag.piers[0].width, 1.5, 1e-9);  // not its polygon's narrower width
  EXPECT_NEAR(drag.piers[1].width, 1.0, 1e-9);  // a 4 m x 1 m wall along the flow
}

TEST(PierDrag, OverlappingRingsShareEachCellsImpulseInTheRatioOfTheirDrag) {
  // Two piers of 1.5 m, 2.5 m apart centre to centre: their rings (out to 2.25 m from each
  // centre) overlap between them. With a unit impulse in every ring cell, the piers' shares add
  // up to the cells' count.
  const Mesh mesh = region_with_piers(40.0, {{{15, 10}, 0.75}, {{17.5, 10}, 0.75}}, {}, 0.3, 4.0);
  const CellMesh cells = build_cell_mesh(mesh, FvCells::elements);
  PierDrag drag = find_pier_drag(mesh, cells, {}, 1.2);
  ASSERT_EQ(drag.piers.size(), 2u);
  ASSERT_LT(drag.cells.size(), drag.piers[0].ring.size() + drag.piers[1].ring.size());  // shared
  for (const int i : drag.cells) drag.impulse[i] = Vec2(1.0, 0.0);
  const Vec2 sum = drag.impulse_of(0) + drag.impulse_of(1);
  EXPECT_NEAR(sum.x(), static_cast<double>(drag.cells.size()), 1e-12 * drag.cells.size());
  EXPECT_EQ(drag.total_impulse().x(), static_cast<double>(drag.cells.size()));
}

TEST(PierDrag, ALakeAtRestAroundPiersStaysAtRest) {
  const Mesh mesh = channel_mesh();
  const Case c = still_water_around_piers(mesh);
  FiniteVolumeSolver s(mesh, c);
  s.initialize();
  ASSERT_FALSE(s.pier_drag().empty());
  for (int n = 0; n < 4; ++n) s.advance(5.0);
  double largest = 0.0;
  for (int i = 0; i < s.cells().cell_count; ++i)
    largest = std::max({largest, std::abs(s.state().hu[i]), std::abs(s.state().hv[i]),
                        std::abs(s.state().h[i] - 2.0)});
  EXPECT_LE(largest, 1e-13);
  EXPECT_EQ(s.pier_drag().total_impulse().norm(), 0.0);
}

}  // namespace
}  // namespace flotsam
