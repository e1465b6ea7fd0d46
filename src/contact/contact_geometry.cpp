#include "contact/contact_geometry.hpp"

#include <algorithm>
#include <limits>

namespace flotsam {
namespace {

// A convex polygon of 2 (a segment) or 4 vertices, counter-clockwise, with outward face
// normals; face k joins vertex k and vertex (k+1) % count.
struct Polygon {
  std::array<Vec2, 4> vertex;
  std::array<Vec2, 4> normal;
  int count = 0;
  int faces_to_test = 0;  // faces used as separating axes (a one-sided wall: only face 0)
  Frame frame;            // the body's frame (identity for a wall)
};

Polygon polygon_of(const Rectangle& r) {
  Polygon p;
  p.vertex = corners(r);
  const Vec2 u = r.frame.axis, v = perp(u);
  p.normal = {-v, u, v, -u};
  p.count = 4;
  p.faces_to_test = 4;
  p.frame = r.frame;
  return p;
}

Polygon polygon_of_segment(const Vec2& start, const Vec2& end, const Vec2& wall_normal) {
  Polygon p;
  p.vertex = {start, end, end, start};
  p.normal = {wall_normal, -wall_normal, wall_normal, -wall_normal};
  p.count = 2;
  p.faces_to_test = 1;
  return p;
}

struct Separation {
  double value = -std::numeric_limits<double>::infinity();  // [m]
  int face = 0;
};

// Largest over the tested faces k of `first` of min_j (second.vertex_j - first.vertex_k) . n_k:
// the separating axis test (positive: a gap along that face's normal).
Separation max_separation(const Polygon& first, const Polygon& second) {
  Separation best;
  for (int k = 0; k < first.faces_to_test; ++k) {
    double s = std::numeric_limits<double>::infinity();
    for (int j = 0; j < second.count; ++j) {
      s = std::min(s, (second.vertex[j] - first.vertex[k]).dot(first.normal[k]));
    }
    if (s > best.value) best = {s, k};
  }
  return best;
}

struct ClipVertex {
  Vec2 point;
  int feature;
};

// Keeps the part of segment (in[0], in[1]) where (x . tangent) <= offset (Box2D's
// b2ClipSegmentToLine); returns the number of points kept (0 or 2).
int clip_to_side(const std::array<ClipVertex, 2>& in, std::array<ClipVertex, 2>& out,
                 const Vec2& tangent, double offset, int plane) {
  const double d0 = in[0].point.dot(tangent) - offset;
  const double d1 = in[1].point.dot(tangent) - offset;
  int n = 0;
  if (d0 <= 0.0) out[n++] = in[0];
  if (d1 <= 0.0) out[n++] = in[1];
  if (d0 * d1 < 0.0) {  // the ends are on either side: add the crossing point
    const double t = d0 / (d0 - d1);
    out[n++] = {in[0].point + t * (in[1].point - in[0].point), 8 + plane};
  }
  return n;
}

// Clips the incident edge of `incident` against reference face `face` of `reference`.
Manifold clip(const Polygon& reference, int face, const Polygon& incident, bool reference_on_a,
              double margin) {
  Manifold m;
  const Vec2 v1 = reference.vertex[face];
  const Vec2 v2 = reference.vertex[(face + 1) % reference.count];
  const Vec2 n = reference.normal[face];
  const Vec2 tangent = (v2 - v1).normalized();

  int edge = 0;  // incident edge: the most anti-parallel to n
  double lowest = std::numeric_limits<double>::infinity();
  for (int k = 0; k < incident.count; ++k) {
    const double d = incident.normal[k].dot(n);
    if (d < lowest) lowest = d, edge = k;
  }
  const std::array<ClipVertex, 2> edge_points = {
      ClipVertex{incident.vertex[edge], 2 * edge},
      ClipVertex{incident.vertex[(edge + 1) % incident.count], 2 * edge + 1}};

  // Side planes of the reference face: v1 . t <= x . t <= v2 . t.
  std::array<ClipVertex, 2> once{}, twice{};
  if (clip_to_side(edge_points, once, -tangent, -tangent.dot(v1), 0) < 2) return m;
  if (clip_to_side(once, twice, tangent, tangent.dot(v2), 1) < 2) return m;

  m.normal = reference_on_a ? Vec2(-n) : n;
  m.reference_on_a = reference_on_a;
  m.local_normal = reference.frame.unrotate(n);
  m.local_plane_point = reference.frame.to_local(v1);
  for (const ClipVertex& c : twice) {
    const double s = (c.point - v1).dot(n);  // separation from the reference face
    if (s > margin) continue;
    ManifoldPoint& p = m.points[static_cast<std::size_t>(m.point_count++)];
    p.point = c.point - 0.5 * s * n;
    p.separation = s;
    p.local_incident = incident.frame.to_local(c.point);
    p.feature = (reference_on_a ? 0 : 1024) + 64 * face + c.feature;
  }
  return m;
}

}  // namespace

std::array<Vec2, 4> corners(const Rectangle& r) {
  const Vec2 hx = r.half.x() * r.frame.axis, hy = r.half.y() * perp(r.frame.axis);
  const Vec2 c = r.frame.origin;
  return {c - hx - hy, c + hx - hy, c + hx + hy, c - hx + hy};
}

double Manifold::depth() const {
  double d = 0.0;
  for (int k = 0; k < point_count; ++k)
    d = std::max(d, -points[static_cast<std::size_t>(k)].separation);
  return d;
}

Manifold collide_rectangles(const Rectangle& a, const Rectangle& b, double margin,
                            double flip_tolerance) {
  const Polygon pa = polygon_of(a), pb = polygon_of(b);
  const Separation sa = max_separation(pa, pb);
  if (sa.value > margin) return {};
  const Separation sb = max_separation(pb, pa);
  if (sb.value > margin) return {};
  if (sb.value > sa.value + flip_tolerance) return clip(pb, sb.face, pa, false, margin);
  return clip(pa, sa.face, pb, true, margin);
}

Manifold collide_rectangle_segment(const Rectangle& a, const Vec2& start, const Vec2& end,
                                   const Vec2& wall_normal, double margin, double flip_tolerance) {
  if ((a.frame.origin - start).dot(wall_normal) < 0.0) return {};  // behind a one-sided wall
  const Polygon pa = polygon_of(a), wall = polygon_of_segment(start, end, wall_normal);
  const Separation sw = max_separation(wall, pa);
  if (sw.value > margin) return {};
  const Separation sa = max_separation(pa, wall);
  if (sa.value > margin) return {};
  if (sa.value > sw.value + flip_tolerance) return clip(pa, sa.face, wall, true, margin);
  return clip(wall, 0, pa, false, margin);
}

}  // namespace flotsam
