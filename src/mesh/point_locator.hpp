#pragma once
// Point location by neighbour walk (spec 4.4 = paper 5.3, (P-31) to (P-33)): the element that
// holds a point, and the point's reference coordinates in it, so that P1/P2 fields can be sampled
// there (mesh/interpolation.hpp).
//
// A query walks from a hint (the element found for the same body last time) towards the point;
// a cold start takes its first element from a bucket grid over the mesh's bounding box (about one
// element per bucket), so no query ever scans the mesh. A walk that leaves the mesh through a
// boundary edge is confirmed against the elements listed in the point's bucket before the point
// is reported outside, so holes and non-convex domains are classified exactly.
#include <vector>

#include "core/vec.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

/// Where a point lies in the mesh.
struct Location {
  int element = -1;         // inside: an element containing the point (any one, on shared edges)
                            // outside: the element the walk left from (a good hint), or -1
  double r = 0.0;           // [-] reference coordinates of the point in `element` (inside only):
  double s = 0.0;           // [-] x = sum_k X_k N_k(r, s), shape functions of shape_functions.hpp
  bool inside = false;      // false: the point is outside the domain (a hole, beyond a bank)
  bool curved = false;      // `element` is curved: isoparametric map, (r, s) found by Newton
  int boundary_edge = -1;   // outside: index into Mesh::boundary of the edge the walk left through
  int boundary_group = -1;  // outside: that edge's group (Mesh::group_names), -1 when unknown
  int steps = 0;  // elements stepped across, plus elements tested in a bucket (statistics)
};

class PointLocator {
 public:
  /// Keeps a pointer to `mesh`, which must outlive the locator. Builds the bucket grid: O(N).
  explicit PointLocator(const Mesh& mesh);

  /// The element containing p, found by walking from `hint` (an element index; -1 or an element
  /// far from p: cold start from the bucket grid). Thread-safe (const, no shared state).
  Location locate(const Vec2& p, int hint = -1) const;

  /// locate(p_k, hints[k]) for the points p_k = (x[k], y[k]) with active[k], k < n, into out[k]
  /// (the same elements and bits). A point still in its hint's straight element, as a body's
  /// point mostly is from one Runge-Kutta stage to the next, is found there from a flat copy of
  /// the element's corners without the bucket and stale-hint checks, which cannot change the
  /// answer there; the others walk as locate does.
  void locate_batch(int n, const double* x, const double* y, const bool* active, const int* hints,
                    Location* out) const;

  /// The first element containing p by a scan of all elements: O(N), for tests and benchmarks.
  /// When outside, no boundary edge is named (boundary_edge = boundary_group = -1).
  Location locate_brute_force(const Vec2& p) const;

  /// True when p lies in `element`: all barycentric coordinates >= -eps (P-32); for a curved
  /// element, in one of its four straight sub-triangles (P-33).
  bool contains(int element, const Vec2& p) const;

  const Mesh& mesh() const { return *mesh_; }
  int bucket_count() const { return nx_ * ny_; }

  /// [-] tolerance on barycentric coordinates: a point on an edge or a vertex belongs to every
  /// element that touches it.
  static constexpr double eps = 1e-12;

 private:
  struct WalkResult {
    int element;        // last element visited
    int boundary_edge;  // >= 0: the walk left the mesh through this boundary edge
    bool found;         // p is in `element`
    int steps;
  };

  /// Per-edge coordinates c[k] of p in element e (negative: p lies beyond local edge k) and
  /// whether p is in e. Straight: c[k] is the barycentric coordinate of the vertex opposite edge k.
  bool edge_coordinates(int e, const Vec2& p, double c[3]) const;
  WalkResult walk(int start, const Vec2& p, bool stochastic, int max_steps) const;
  int bucket_of(const Vec2& p) const;  // -1 when p lies outside the grid's box
  Location inside_at(int element, const Vec2& p, int steps) const;
  Vec2 reference_coordinates(int element, const Vec2& p) const;

  const Mesh* mesh_;
  std::vector<char> curved_;       // per element: Mesh::is_curved
  Vec2 origin_;                    // [m] lower-left corner of the bucket grid
  Vec2 cell_;                      // [m] bucket size along x and y
  int nx_ = 1, ny_ = 1;            // buckets along x and y
  std::vector<int> seed_;          // per bucket: the element whose centroid is nearest its centre
  std::vector<int> bucket_begin_;  // CSR: elements overlapping bucket b are
  std::vector<int> bucket_elements_;  // bucket_elements_[bucket_begin_[b] .. bucket_begin_[b+1])
  int max_steps_ = 0;                 // step cap of one walk before the fallback
  // Per element, 8 numbers in one cache line (aligned to it): the corners x0 y0 x1 y1 x2 y2 [m],
  // 1 / (2 A) [m^-2] as edge_coordinates computes it, and 1 when a point in the element is never
  // a stale hint's (straight, and every point of it within 4 bucket diagonals of corner 0), else 0.
  struct alignas(64) HintCorners {
    double g[8];
  };
  std::vector<HintCorners> hint_corners_;
};

}  // namespace flotsam
