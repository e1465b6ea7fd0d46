#pragma once
// Contact geometry (spec 4.1): where two rectangles, or a rectangle and a wall segment, touch.
//
// A contact is a manifold of one or two points M with one unit normal n pointing from B towards
// A and, per point, a separation s (s < 0: the bodies overlap by the depth -s). A vertex pushed
// into an edge gives one point (the paper's Fig. 4); two edges flat against each other give two,
// so that logs lying side by side or flat against a pier rest without spinning.
//
// Method (as Box2D's b2CollidePolygons): separating-axis test over the face normals of both
// shapes, the face of least penetration is the reference face, the most anti-parallel edge of
// the other shape is the incident edge, clipped to the reference face's side planes; clipped
// points within `margin` of the reference face are the contact points. The manifold also keeps
// the reference face and the incident points in the bodies' own frames so that the position
// correction can re-measure the separation after it moves the bodies.
#include <array>

#include "core/vec.hpp"

namespace flotsam {

/// A rigid frame: origin and the unit vector of its local x axis. Walls use the identity.
struct Frame {
  Vec2 origin = Vec2::Zero();  // [m]
  Vec2 axis = Vec2::UnitX();   // unit, local x axis in world coordinates
  Vec2 to_world(const Vec2& local) const { return origin + rotate(local); }
  Vec2 rotate(const Vec2& local) const { return local.x() * axis + local.y() * perp(axis); }
  Vec2 to_local(const Vec2& world) const { return unrotate(world - origin); }
  Vec2 unrotate(const Vec2& v) const { return {v.dot(axis), v.dot(perp(axis))}; }
};

/// A body's footprint: the rectangle L x l centred on G, long side along `frame.axis`.
struct Rectangle {
  Frame frame;               // origin = G [m], axis = long axis
  Vec2 half = Vec2::Zero();  // (L/2, l/2) [m]
};

/// Corners counter-clockwise, starting at local (-L/2, -l/2); face k joins corner k and k+1.
std::array<Vec2, 4> corners(const Rectangle& rectangle);

struct ManifoldPoint {
  Vec2 point = Vec2::Zero();           // M [m], midway between the two surfaces
  double separation = 0.0;             // s [m]; < 0 when overlapping
  Vec2 local_incident = Vec2::Zero();  // incident point in the incident body's frame [m]
  int feature = 0;                     // identifies the point from step to step (warm start)
};

struct Manifold {
  Vec2 normal = Vec2::UnitX();  // n, unit, from B towards A
  int point_count = 0;          // 0: no contact
  std::array<ManifoldPoint, 2> points;
  // Reference face, in the frame of the body that carries it (position correction).
  bool reference_on_a = true;
  Vec2 local_normal = Vec2::UnitX();      // outward normal of the reference face
  Vec2 local_plane_point = Vec2::Zero();  // a point of the reference face [m]

  /// Largest overlap of the manifold's points (>= 0) [m].
  double depth() const;
};

/// Rectangle A against rectangle B. Points farther apart than `margin` [m] are dropped; a face
/// of B is taken as reference only when it separates better than A's by `flip_tolerance` [m]
/// (stable choice for nearly parallel faces).
Manifold collide_rectangles(const Rectangle& a, const Rectangle& b, double margin,
                            double flip_tolerance);

/// Rectangle A against the wall segment from `start` to `end` whose unit normal `wall_normal`
/// points into the water. The wall is one-sided: a rectangle whose centre is behind the wall's
/// line gets no contact.
Manifold collide_rectangle_segment(const Rectangle& a, const Vec2& start, const Vec2& end,
                                   const Vec2& wall_normal, double margin, double flip_tolerance);

}  // namespace flotsam
