#pragma once
// What the finite-volume engine's unit tests share: a closed rectangular basin (walls on the four
// sides of make_rectangle_mesh's groups) over a flat bed, to which each test adds its surface,
// velocity, bed and conditions, and a helper that finds the cell holding a point by brute force
// (independent of the point locator the engine uses).
#include <stdexcept>
#include <string>

#include "flow/fv/cell_mesh.hpp"
#include "io/case.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam::test {

/// A case for the finite-volume engine on a rectangle mesh: still water at `eta` [m] over a flat
/// bed at 0, every side a wall.
inline Case closed_basin_case(double eta) {
  Case c;
  c.name = "closed basin";
  c.mesh.kind = MeshSource::Kind::file;  // the mesh is given in memory, not generated
  c.flow.engine = FlowEngineKind::fv;
  c.flow.initial_eta_start = c.flow.initial_eta_end = eta;
  for (const char* side : {"left", "right", "bottom", "top"})
    c.flow.boundaries.push_back(
        {BoundaryCondition::Kind::wall, side, TimeSeries(0.0), TimeSeries(0.0)});
  return c;
}

/// The condition on `group` of the case (which must name it).
inline BoundaryCondition& condition_of(Case& c, const std::string& group) {
  for (BoundaryCondition& b : c.flow.boundaries)
    if (b.group == group) return b;
  throw std::logic_error("no condition on " + group);
}

/// Barycentric coordinates of p in cell i (all >= 0 inside).
inline Eigen::Vector3d barycentric(const Mesh& mesh, const CellMesh& cells, int i, const Vec2& p) {
  const Vec2& a = mesh.nodes[cells.corners[i][0]];
  const Vec2& b = mesh.nodes[cells.corners[i][1]];
  const Vec2& d = mesh.nodes[cells.corners[i][2]];
  const double A2 = cross(b - a, d - a);
  const double l1 = cross(p - a, d - a) / A2, l2 = cross(b - a, p - a) / A2;
  return {1.0 - l1 - l2, l1, l2};
}

/// The cell holding p, found by trying them all; -1 when none does.
inline int cell_holding(const Mesh& mesh, const CellMesh& cells, const Vec2& p) {
  for (int i = 0; i < cells.cell_count; ++i)
    if (barycentric(mesh, cells, i, p).minCoeff() >= -1e-12) return i;
  return -1;
}

/// True when the cell has a neighbour across each of its three edges.
inline bool is_inner_cell(const CellMesh& cells, int i) {
  return cells.neighbour[i][0] >= 0 && cells.neighbour[i][1] >= 0 && cells.neighbour[i][2] >= 0;
}

}  // namespace flotsam::test
