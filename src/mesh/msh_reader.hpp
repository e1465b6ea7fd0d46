#pragma once
// Reading Gmsh meshes (MSH 2.2 and 4.1, ASCII and binary) through the Gmsh C++ API.
//
// What is read: the 3-node (Gmsh type 2) and 6-node (type 9) triangles of every surface, and
// the 2-node (type 1) and 3-node (type 8) lines of every curve, each line named after the
// physical group of its curve (getPhysicalGroups / getEntitiesForPhysicalGroup /
// getPhysicalName). A physical group without a name is named by its number ("7"); a line in no
// physical group gets the group "" (build_mesh then rejects it if it lies on the boundary).
// Triangles of a surface whose triangles all run clockwise (a surface with normal -z) are
// reoriented; nodes that no triangle uses are dropped, and so are lines off the triangles.
#include <string>

#include "mesh/mesh.hpp"

namespace flotsam {

/// The mesh of `path` as plain lists, in the file's numbering. Throws InputError naming the
/// file when it is missing or unreadable, when its structure is damaged (check_msh, before Gmsh
/// sees it; with the line or byte), when Gmsh cannot parse it, when it holds surface
/// elements other than 3- or 6-node triangles, or when it has no triangles.
RawMesh read_msh_raw(const std::string& path);

/// read_msh_raw followed by build_mesh (validation, P2 numbering, adjacency, groups).
Mesh read_msh(const std::string& path);

/// The mesh of Gmsh's current model as plain lists, `source` naming it in messages. Requires a
/// live GmshSession; shared by the reader and the generator.
RawMesh raw_mesh_from_gmsh_model(const std::string& source);

}  // namespace flotsam
