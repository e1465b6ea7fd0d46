#pragma once
// The steps every mesh generator shares (mesh_generator.cpp, region_mesh.cpp), on Gmsh's
// built-in (geo) kernel inside a GmshSession: points, circles, named boundary groups, options,
// the size field near curves, then mesh -> order 2 (or 1: three-node triangles) -> (write) ->
// RawMesh.
#include <string>
#include <utility>
#include <vector>

#include "core/vec.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_generator.hpp"

namespace flotsam {

int add_point(const Vec2& p);

/// A circle arc of at most a quarter turn between two points on a circle around `centre`.
int add_arc(int from, int centre, int to);

/// A full circle as four quarter arcs, counter-clockwise from angle 0.
std::vector<int> add_circle(const Vec2& centre, double radius);

/// Boundary curves by group name, in the order the names first appear.
class BoundaryGroups {
 public:
  void add(const std::string& name, int curve);
  /// Physical groups for the curves and the surface; after geo::synchronize.
  void create(int surface) const;

 private:
  std::vector<std::pair<std::string, std::vector<int>>> groups_;
};

/// Frontal-Delaunay, `mesh_size` as the largest size, sizes only from fields, mid nodes on the
/// curves.
void set_common_options(double mesh_size);

/// A Threshold field of the Distance to `curves`: `size_near` on them growing linearly to
/// `size_far` at `distance` [m]; returns its tag (not yet the background field).
int add_distance_size_field(const std::vector<int>& curves, double size_near, double size_far,
                            double distance);

/// Writes the current model's mesh to `msh_path` (InputError naming it when it cannot).
void write_current_model(const std::string& msh_path, const MshFormat& format);

/// A local origin for geometry given in map coordinates: the corner of the points' bounding box
/// truncated towards zero to a multiple of 10 km, (0, 0) within 10 km of the origin. Gmsh
/// integrates element sizes along curves with finite differences of the coordinates; around
/// UTM coordinates (5e5, 5e6 m) their round-off keeps that integration from converging (minutes
/// for one curve), so the generators build the model at `p - origin` and move the nodes back.
Vec2 local_origin(const std::vector<Vec2>& points);
/// Surface from the curve loops (outer first), groups, mesh, order 2, nodes moved by `origin`
/// (the model was built around it: local_origin), write, extract.
RawMesh mesh_current_model(const std::string& source, const std::vector<int>& loops,
                           const BoundaryGroups& groups, const std::string& msh_path,
                           const MshFormat& format, int order, const Vec2& origin = Vec2::Zero());

void require_positive(const std::string& source, const char* key, double value);

}  // namespace flotsam
