#pragma once
// A rectangle [x0, x0+Lx] x [y0, y0+Ly] cut into nx x ny cells, each split into two triangles,
// with the four sides in groups "left", "right", "bottom", "top". No Gmsh involved: tests,
// verification cases and benchmarks use it where an exactly known mesh is wanted.
#include "mesh/mesh.hpp"

namespace flotsam {

struct RectangleSpec {
  double x0 = 0.0, y0 = 0.0;        // [m] lower-left corner
  double length = 1.0;              // Lx [m]
  double width = 1.0;               // Ly [m]
  int nx = 1, ny = 1;               // cells along x and y
  bool alternate_diagonals = true;  // criss-cross pattern (no preferred direction)
};

RawMesh make_rectangle_raw(const RectangleSpec& spec);
Mesh make_rectangle_mesh(const RectangleSpec& spec);

}  // namespace flotsam
