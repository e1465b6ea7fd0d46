#pragma once
// The solid boundary as straight wall segments (spec 4.1): every mesh boundary edge in a `wall`
// or `noslip` group, banks and pier holes alike, a curved P2 edge split at its mid node into two
// segments. Segments never move, so they are bucketed once in a uniform grid (spec 4.2) and a
// body asks the grid for the segments near its bounding box.
#include <limits>
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "io/case.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

/// An axis-aligned box [m].
struct Aabb {
  Vec2 lower = Vec2::Zero();
  Vec2 upper = Vec2::Zero();
  bool overlaps(const Aabb& o) const {
    return lower.x() <= o.upper.x() && o.lower.x() <= upper.x() && lower.y() <= o.upper.y() &&
           o.lower.y() <= upper.y();
  }
};

struct BoundarySegments {
  // One entry per segment (structure of arrays).
  std::vector<Vec2> start, end;  // [m]; the water is on the left of start -> end
  std::vector<Vec2> normal;      // unit, pointing into the water
  std::vector<int> group;        // boundary group (Mesh::group_names index, or the caller's)
  std::vector<std::string> group_names;
  // The vertical band [m] in which a segment stops bodies (a bridge deck from its soffit to its
  // railing's top; bridges/deck_contact.hpp): empty while every segment stops every body.
  std::vector<double> band_lower, band_upper;

  // Uniform grid, built by build_grid(): cell (i, j) holds the segments whose box meets it,
  // listed in cell_segments[cell_start[c] .. cell_start[c + 1]).
  Vec2 grid_origin = Vec2::Zero();  // [m]
  double cell_size = 1.0;           // [m]
  int columns = 0, rows = 0;
  std::vector<int> cell_start, cell_segments;

  int size() const { return static_cast<int>(start.size()); }

  /// Appends the segment a -> b (water on its left) in `group`.
  void add_segment(const Vec2& a, const Vec2& b, int group_index);

  /// Appends a segment that stops only the bodies whose vertical extent meets [lower, upper] [m]
  /// and whose centre is on its water side (a deck's face).
  void add_banded_segment(const Vec2& a, const Vec2& b, int group_index, double lower,
                          double upper);

  /// Whether segment s stops a body with centre `centre` and vertical extent [bottom, top] [m]:
  /// always for a plain wall; for a banded one when the extents overlap and the centre is on the
  /// water side.
  bool stops(int s, const Vec2& centre, double bottom, double top) const {
    if (band_lower.empty() || (band_lower[s] == -infinity && band_upper[s] == infinity))
      return true;
    return top > band_lower[s] && bottom < band_upper[s] && normal[s].dot(centre - start[s]) > 0.0;
  }
  static constexpr double infinity = std::numeric_limits<double>::infinity();

  /// Appends a circular hole (a pier) as `sides` segments whose normals point away from the
  /// centre; the polygon's vertices lie on the circle.
  void add_circle_hole(const Vec2& centre, double radius, int sides, int group_index);

  /// Buckets the segments in a uniform grid of cells of about `cell_size` [m] (<= 0: the mean
  /// segment length, at least 1/1000 of the extent). Call once after the last add.
  void build_grid(double cell_size = 0.0);

  /// Indices of the segments whose grid cells meet `box`, each once, ascending. `stamp` is
  /// scratch space the caller keeps between calls (one int per segment).
  void query(const Aabb& box, std::vector<int>& found, std::vector<int>& stamp,
             int& stamp_value) const;
};

/// Segments of the groups `solid_groups` (indices into mesh.group_names) of the mesh's boundary,
/// with the grid built. Curved edges are split at their mid node.
BoundarySegments extract_boundary_segments(const Mesh& mesh, const std::vector<int>& solid_groups);

/// Indices of the mesh groups whose boundary condition is `wall` or `noslip`. Throws InputError
/// naming the group when a condition names a group the mesh does not have.
std::vector<int> solid_group_indices(const Mesh& mesh,
                                     const std::vector<BoundaryCondition>& conditions);

}  // namespace flotsam
