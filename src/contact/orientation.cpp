#include "contact/orientation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace flotsam {
namespace {

// Error-free transformations (Shewchuk 1997): a op b = hi + lo exactly.
struct Pair {
  double hi, lo;
};

Pair two_sum(double a, double b) {
  const double s = a + b;
  const double bv = s - a;
  const double av = s - bv;
  return {s, (a - av) + (b - bv)};
}

Pair two_diff(double a, double b) {
  return two_sum(a, -b);
}

Pair two_product(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

// Sign of the exact sum of `terms`. Grow-Expansion adds each term to a nonoverlapping expansion
// kept in increasing magnitude; the sign of the sum is the sign of its largest nonzero component.
int exact_sign_of_sum(std::span<const double> terms) {
  std::array<double, 32> expansion{};
  std::size_t size = 0;
  for (const double t : terms) {
    double q = t;
    for (std::size_t i = 0; i < size; ++i) {
      const Pair s = two_sum(q, expansion[i]);
      expansion[i] = s.lo;
      q = s.hi;
    }
    expansion[size++] = q;
  }
  for (std::size_t i = size; i-- > 0;) {
    if (expansion[i] != 0.0) return expansion[i] > 0.0 ? 1 : -1;
  }
  return 0;
}

// det = (ax - cx)(by - cy) - (ay - cy)(bx - cx) with every difference and product split exactly.
int orient2d_exact(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Pair acx = two_diff(a.x(), c.x()), bcy = two_diff(b.y(), c.y());
  const Pair acy = two_diff(a.y(), c.y()), bcx = two_diff(b.x(), c.x());
  std::array<double, 16> terms{};
  std::size_t k = 0;
  for (const double x : {acx.hi, acx.lo}) {
    for (const double y : {bcy.hi, bcy.lo}) {
      const Pair p = two_product(x, y);
      terms[k++] = p.hi;
      terms[k++] = p.lo;
    }
  }
  for (const double x : {acy.hi, acy.lo}) {
    for (const double y : {bcx.hi, bcx.lo}) {
      const Pair p = two_product(x, y);
      terms[k++] = -p.hi;
      terms[k++] = -p.lo;
    }
  }
  return exact_sign_of_sum(terms);
}

int sign(double x) {
  return (x > 0.0) - (x < 0.0);
}

}  // namespace

int orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  // Shewchuk's orient2d filter: |det - det_computed| <= ccw_bound * (|detleft| + |detright|).
  constexpr double epsilon = std::numeric_limits<double>::epsilon() / 2;  // 2^-53 [-]
  constexpr double ccw_bound = (3.0 + 16.0 * epsilon) * epsilon;          // [-]
  const double detleft = (a.x() - c.x()) * (b.y() - c.y());
  const double detright = (a.y() - c.y()) * (b.x() - c.x());
  const double det = detleft - detright;
  double detsum;
  if (detleft > 0.0) {
    if (detright <= 0.0) return sign(det);
    detsum = detleft + detright;
  } else if (detleft < 0.0) {
    if (detright >= 0.0) return sign(det);
    detsum = -detleft - detright;
  } else {
    return sign(det);
  }
  if (std::abs(det) >= ccw_bound * detsum) return sign(det);
  return orient2d_exact(a, b, c);
}

bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  // A and B on opposite sides of line CD, and C and D on opposite sides of line AB (P-5.4);
  // a zero means an end point lies on the other line: then they touch if the boxes overlap.
  const int o1 = orient2d(c, d, a), o2 = orient2d(c, d, b);
  const int o3 = orient2d(a, b, c), o4 = orient2d(a, b, d);
  if (o1 * o2 > 0 || o3 * o4 > 0) return false;
  if (o1 != 0 || o2 != 0) return true;  // proper crossing or an end point on the other segment
  // All four collinear: overlap of the projections on both axes.
  return std::max(std::min(a.x(), b.x()), std::min(c.x(), d.x())) <=
             std::min(std::max(a.x(), b.x()), std::max(c.x(), d.x())) &&
         std::max(std::min(a.y(), b.y()), std::min(c.y(), d.y())) <=
             std::min(std::max(a.y(), b.y()), std::max(c.y(), d.y()));
}

bool point_in_convex_polygon(const Vec2& p, std::span<const Vec2> polygon) {
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (orient2d(polygon[i], polygon[(i + 1) % n], p) < 0) return false;
  }
  return true;
}

bool convex_polygons_touch(std::span<const Vec2> first, std::span<const Vec2> second) {
  const std::size_t n = first.size(), m = second.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < m; ++j) {
      if (segments_cross(first[i], first[(i + 1) % n], second[j], second[(j + 1) % m])) {
        return true;
      }
    }
  }
  return point_in_convex_polygon(first[0], second) || point_in_convex_polygon(second[0], first);
}

}  // namespace flotsam
