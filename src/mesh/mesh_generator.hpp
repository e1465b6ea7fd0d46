#pragma once
// Mesh generation with Gmsh's built-in geometry kernel: the channel with piers (spec 8.2), the
// 180-degree bend (spec 8.1) and closed polygons (geometry.hpp). Meshes are second order
// (Gmsh setOrder(2)): 6-node triangles whose boundary mid nodes lie on the true curves (pier
// circles, bend arcs). Gmsh runs single-threaded with fixed options, so the same input gives
// the same mesh, node for node.
#include <string>

#include "mesh/geometry.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

/// How generate_mesh writes its .msh file (Gmsh options Mesh.MshFileVersion, Mesh.Binary).
struct MshFormat {
  double version = 4.1;  // 2.2 or 4.1
  bool binary = false;
};

/// The mesh of `source`: read from source.file for Kind::file, else generated. When `msh_path`
/// is not empty the mesh is also written there by Gmsh (format by extension; .msh in `format`).
/// Throws InputError for a geometry that cannot be meshed (naming the pier, point or side) or a
/// file that cannot be read or written (naming the file).
Mesh generate_mesh(const MeshSource& source, const std::string& msh_path = "",
                   const MshFormat& format = {});

/// The generators behind generate_mesh, returning the lists build_mesh takes: Gmsh's six-node
/// triangles (`order` 2, mid nodes on curved boundaries), or its three-node ones (`order` 1,
/// build_mesh adds straight mid nodes: the finite-volume engine's cells, meshed faster).
RawMesh generate_channel_mesh(const ChannelGeometry& channel, const std::string& msh_path = "",
                              const MshFormat& format = {}, int order = 2);
RawMesh generate_bend_mesh(const BendGeometry& bend, const std::string& msh_path = "",
                           const MshFormat& format = {}, int order = 2);
RawMesh generate_polygon_mesh(const PolygonGeometry& polygon, const std::string& msh_path = "",
                              const MshFormat& format = {}, int order = 2);
RawMesh generate_region_mesh(const RegionGeometry& region, const std::string& msh_path = "",
                             const MshFormat& format = {}, int order = 2);

}  // namespace flotsam
