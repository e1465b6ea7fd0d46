#pragma once
// Geometries the mesh generator knows (issue 2 item 4), and where a case's mesh comes from.
#include <functional>
#include <optional>
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

/// A ring of points with the name that messages give it ("town.gpkg, layer 'buildings',
/// feature 17", or "mesh.region.outline" for points written in the case).
struct NamedRing {
  std::vector<Vec2> points;  // [m], either orientation, not closed (last != first)
  std::string name;
};

/// A polyline that names the outline's sides along it (an inflow, an outflow).
struct BoundaryLine {
  std::string group;
  std::vector<Vec2> points;  // [m]
  std::string name;          // for messages
};

/// A domain from geodata (mesh.region, docs/case-format.md): an outline with holes for buildings
/// (one wall group "buildings") and piers (circles or outlines, groups pier_1, pier_2, ...),
/// named boundary lines along the outline, sizes refined near buildings and piers and where the
/// terrain is steep. Checked before meshing: every ring simple, holes inside the outline and
/// apart from each other (errors name the features); vertices closer than merge_distance are
/// merged and buildings smaller than min_building_area dropped (slivers are not meshed).
struct RegionGeometry {
  NamedRing outline;
  std::vector<NamedRing> islands;  // holes of the outline itself (walls in default_group)
  std::vector<BoundaryLine> lines;
  std::string default_group = "bank";  // outline sides no line names
  std::vector<NamedRing> buildings;
  std::vector<Pier> piers;
  std::vector<NamedRing> pier_outlines;        // pier_<piers.size() + 1>, ...
  double mesh_size = 10.0;                     // [m] far from buildings and piers
  double building_mesh_size = 2.0;             // [m] on the buildings' walls
  double pier_mesh_size = 1.0;                 // [m] on the piers
  double refine_distance = 20.0;               // [m] over which the size grows back to mesh_size
  std::optional<double> merge_distance;        // [m] consecutive vertices closer are merged
  std::optional<double> min_building_area;     // [m^2] smaller footprints are dropped
  std::function<double(const Vec2&)> size_at;  // an extra bound on the size [m] (steep
                                               // terrain), or empty

  // Unless given, both follow the scale of the buildings' walls: a twentieth of their element
  // size, and the square of half of it (0.1 m and 1 m^2 at the default 2 m; 2.5 mm and
  // 6.25 cm^2 for a laboratory model meshed at 5 cm).
  double merge() const { return merge_distance.value_or(building_mesh_size / 20.0); }
  double smallest_building() const {
    return min_building_area.value_or(0.25 * building_mesh_size * building_mesh_size);
  }
};

struct MeshSource {
  enum class Kind { file, channel, bend, polygon, region } kind = Kind::channel;
  std::string file;  // Gmsh .msh (2.2 or 4.1, ASCII or binary) when kind == file
  ChannelGeometry channel;
  BendGeometry bend;
  PolygonGeometry polygon;
  RegionGeometry region;
  // Generated meshes: Gmsh's six-node triangles (2) or three-node ones (1, with straight mid
  // nodes added: `flow.engine: fv`, whose cells are straight triangles).
  int element_order = 2;
};

}  // namespace flotsam
