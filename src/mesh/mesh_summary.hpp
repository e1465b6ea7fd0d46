#pragma once
// Mesh statistics, as printed by `flotsam info mesh.msh`.
//
// Definitions:
//   element size   the longest straight edge (vertex to vertex) of an element [m];
//   quality        q = 4 sqrt(3) A / (l_0^2 + l_1^2 + l_2^2) of the straight triangle: 1 for an
//                  equilateral triangle, -> 0 as it degenerates [-];
//   area           integral of det J of the isoparametric P2 map (exact for curved elements);
//   group length   sum of the lengths of the group's P2 edges (curves integrated by Gauss
//                  quadrature; exact for straight edges).
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

struct BoundaryGroupSummary {
  std::string name;
  int edge_count = 0;
  double length = 0;  // [m]
};

struct MeshSummary {
  std::string source;
  int node_count = 0;                        // P2 nodes
  int vertex_count = 0;                      // P1 nodes (corners)
  int element_count = 0;                     // 6-node triangles
  int curved_element_count = 0;              // elements with a mid node off its straight edge
  std::vector<BoundaryGroupSummary> groups;  // in Mesh::group_names order
  double min_element_size = 0;               // [m] smallest longest edge
  double max_element_size = 0;               // [m] largest longest edge
  double min_quality = 0;                    // [-]
  double mean_quality = 0;                   // [-]
  double total_area = 0;                     // [m^2]
  Vec2 lower_corner{0.0, 0.0};               // [m] bounding box of the nodes
  Vec2 upper_corner{0.0, 0.0};               // [m]
};

/// Length of the quadratic curve through end nodes a, b and mid node m (at parameter 1/2) [m].
double p2_edge_length(const Vec2& a, const Vec2& b, const Vec2& m);

/// Area of element e under its isoparametric P2 map [m^2].
double p2_element_area(const Mesh& mesh, int element);

/// Shape quality 4 sqrt(3) A / sum l_k^2 of the straight triangle of element e [-].
double element_quality(const Mesh& mesh, int element);

MeshSummary summarize_mesh(const Mesh& mesh);

/// The summary as an aligned table with units, one quantity per line, ending in a newline.
std::string format_mesh_summary(const MeshSummary& summary);

}  // namespace flotsam
