#pragma once
// The mesh: unstructured six-node (P2) triangles whose three corner nodes are the P1 vertices.
//
// Numbering. The P1 vertices are nodes 0 .. vertex_count-1, so a P1 field (elevation eta) is an
// array of vertex_count values and a P2 field (velocity) an array of node_count() values whose
// first vertex_count entries are the vertex values. Mid-edge nodes follow. Each group, and the
// elements, run along a space-filling curve (mesh/curve_order.hpp), not in the file's order.
//
// Local numbering of an element (Gmsh's order for the 6-node triangle, counter-clockwise):
//
//        2
//        | \          local edge k joins vertex k and vertex (k+1)%3; its mid node is 3+k;
//        5   4        neighbours[e][k] is the element across edge k, or a boundary code
//        |     \      (see is_boundary / boundary_edge_of) when edge k lies on the boundary.
//        0 - 3 - 1
//
// Curved boundaries keep their mid node on the true curve (the element is then isoparametric).
#include <array>
#include <string>
#include <vector>

#include "core/vec.hpp"

namespace flotsam {

/// One boundary edge: local edge `local_edge` of `element`, in boundary group `group`.
struct BoundaryEdge {
  int element;     // owning triangle
  int local_edge;  // 0, 1, 2: from vertex k to vertex (k+1)%3, mid node 3+k
  int group;       // index into Mesh::group_names
};

struct Mesh {
  std::string source;  // file or generator, named in error messages

  int vertex_count = 0;                        // P1 nodes: 0 .. vertex_count-1
  std::vector<Vec2> nodes;                     // [m] all P2 nodes, vertices first
  std::vector<std::array<int, 6>> elements;    // v0 v1 v2 m01 m12 m20, counter-clockwise
  std::vector<std::array<int, 3>> neighbours;  // across local edge k; boundary code when < 0
  std::vector<double> area;                    // [m^2] of the straight triangle v0 v1 v2
  std::vector<BoundaryEdge> boundary;          // every boundary edge, each in one named group
  std::vector<std::string> group_names;        // physical group names of the boundary
  std::vector<long> node_tags;                 // tag of each node in its source file (messages)
  std::vector<long> element_tags;              // tag of each element in its source file

  int node_count() const { return static_cast<int>(nodes.size()); }
  int element_count() const { return static_cast<int>(elements.size()); }

  /// The four straight sub-triangles of an element (the paper's Fig. 3), counter-clockwise, as
  /// local node indices: three at the corners, then the middle one.
  static constexpr int sub_triangles[4][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}};

  /// A neighbour entry < 0 encodes boundary edge index b as -(b + 1).
  static bool is_boundary(int neighbour) { return neighbour < 0; }
  static int boundary_edge_of(int neighbour) { return -neighbour - 1; }

  /// Index of the boundary group called `name`, or -1.
  int find_group(const std::string& name) const;

  /// Affine map of the straight triangle from the reference triangle (0,0),(1,0),(0,1):
  /// J = [x1-x0, x2-x0; y1-y0, y2-y0] [m]; det J = 2 * area.
  Mat2 jacobian(int element) const;

  /// The two end nodes and the mid node of local edge k of an element.
  std::array<int, 3> edge_nodes(int element, int local_edge) const;

  /// True when the element's mid nodes are off the straight edges' midpoints (curved boundary).
  bool is_curved(int element) const;
};

/// What a reader or generator hands to build_mesh: plain lists, in the file's numbering.
struct RawMesh {
  std::string source;
  std::vector<Vec2> nodes;                  // [m]
  std::vector<long> node_tags;              // tag of each node in the file
  std::vector<std::vector<int>> triangles;  // 3 or 6 indices into nodes each (Gmsh order)
  std::vector<long> triangle_tags;
  struct Line {
    std::vector<int> nodes;  // 2 or 3 indices into nodes (end, end, [mid])
    std::string group;       // physical group name, "" when it has none
    long tag = 0;
  };
  std::vector<Line> lines;  // boundary line elements
};

/// Builds and validates the mesh: P2 mid nodes for 3-node triangles (edge midpoints), mid nodes
/// shared between neighbours, adjacency, boundary groups, areas; numbered vertices first, nodes
/// along a space-filling curve (mesh/curve_order.hpp), elements in Cuthill-McKee order from it
/// (mesh/element_order.hpp), whatever the input's order.
/// Throws InputError naming the file and the element or node for: degenerate or inverted
/// elements, nodes no element uses, non-manifold edges, 6-node neighbours disagreeing on a mid
/// node, and boundary edges without a named group.
Mesh build_mesh(const RawMesh& raw);

}  // namespace flotsam
