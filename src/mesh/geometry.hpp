#pragma once
// Geometries the mesh generator knows (issue 2 item 4), and where a case's mesh comes from.
#include <string>
#include <vector>

#include "core/vec.hpp"

namespace flotsam {

struct Pier {
  Vec2 centre;    // [m]
  double radius;  // [m]
};

/// Rectangular channel [0, length] x [0, width] with circular piers (spec 8.2). Boundary groups:
/// "inflow" (x = 0), "outflow" (x = length), "bank_right" (y = 0), "bank_left" (y = width),
/// "pier_1", "pier_2", ... in the order given.
struct ChannelGeometry {
  double length = 1500.0;  // [m]
  double width = 170.0;    // [m]
  std::vector<Pier> piers;
  // Defaults give the paper's mesh for spec 8.2: 4,468 six-node triangles, 9,385 nodes (paper:
  // 4,468 and 9,357). Gmsh size field: Threshold of the Distance to the piers, linear from
  // pier_mesh_size on the circles to mesh_size at refine_distance from them.
  double mesh_size = 14.5;        // [m] element size far from the piers
  double pier_mesh_size = 4.0;    // [m] element size on the piers' circles
  double refine_distance = 60.0;  // [m] distance from a pier over which the size grows back
};

/// 180-degree bend (spec 8.1): straight inlet reach along -x ending at the bend, a half annulus
/// centred at `centre`, and a straight outlet reach back along +x. Groups: "inflow", "outflow",
/// "bank_inner", "bank_outer". Relative to `centre`: the inlet reach is x in [0, inlet_length],
/// y in [R_i, R_o] (R_i = inner_radius, R_o = inner_radius + width) with the inflow at
/// x = inlet_length; the bend is the half annulus x <= 0; the outlet reach is x in
/// [0, outlet_length], y in [-R_o, -R_i] with the outflow at x = outlet_length.
struct BendGeometry {
  Vec2 centre{0.0, 0.0};       // [m] centre of the bend's arcs
  double width = 0.8;          // B [m]
  double inner_radius = 0.4;   // [m]
  double inlet_length = 3.0;   // [m]
  double outlet_length = 3.0;  // [m]
  double mesh_size = 0.04;     // [m]
};

/// A closed polygon; side i joins point i and point i+1 and belongs to group names[i].
struct PolygonGeometry {
  std::vector<Vec2> points;         // [m], counter-clockwise or clockwise
  std::vector<std::string> groups;  // one per side
  double mesh_size = 1.0;           // [m]
};

struct MeshSource {
  enum class Kind { file, channel, bend, polygon } kind = Kind::channel;
  std::string file;  // Gmsh .msh (2.2 or 4.1, ASCII or binary) when kind == file
  ChannelGeometry channel;
  BendGeometry bend;
  PolygonGeometry polygon;
};

}  // namespace flotsam
