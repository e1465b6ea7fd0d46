// Neighbour walk (spec 4.4, paper 5.3 and Fig. 5) with a bucket grid for cold starts.
//
//   locate(p, hint):
//     e <- hint, unless it is unknown or far from p: then the seed element of p's bucket
//     walk: repeat  compute the coordinates of p in e                           (P-32), (P-33)
//                   if all >= -eps: found
//                   k <- the edge beyond which p lies most (most negative coordinate)
//                   if edge k is on the boundary: left the mesh through it
//                   e <- neighbour across edge k
//     a walk that runs over its step cap (a cycle, possible in a non-Delaunay mesh) is redone as
//     a stochastic walk (a random edge among those with a negative coordinate), which ends with
//     probability one in any triangulation (Devillers, Pion and Teillaud 2002)
//     left the mesh: p may still lie inside, past a hole or round a bend; test the elements
//     listed in p's bucket; none holds p -> outside, reported with the edge the walk left by.
#include "mesh/point_locator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "mesh/shape_functions.hpp"

namespace flotsam {
namespace {

// Sub-triangles of a curved six-node element (P-33): Mesh::sub_triangles.

// True when p lies in the straight triangle a b c (counter-clockwise): coordinates >= -eps.
bool in_triangle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& p, double eps) {
  const double twice_area = cross(b - a, c - a);
  if (!(twice_area > 0)) return false;  // a folded sub-triangle holds nothing
  const double tolerance = -eps * twice_area;
  return cross(b - p, c - p) >= tolerance && cross(c - p, a - p) >= tolerance &&
         cross(a - p, b - p) >= tolerance;
}

// A small generator for the stochastic walk: deterministic, no shared state.
std::uint32_t next_random(std::uint32_t& state) {
  state ^= state << 13;
  state ^= state >> 17;
  state ^= state << 5;
  return state;
}

}  // namespace

PointLocator::PointLocator(const Mesh& mesh) : mesh_(&mesh) {
  const int element_count = mesh.element_count();
  curved_.resize(element_count);
  for (int e = 0; e < element_count; ++e) curved_[e] = mesh.is_curved(e) ? 1 : 0;

  // Bucket grid over the box of all nodes (mid nodes too: a curved edge may bulge out), widened
  // so that any point within eps of an element lies in the box, with about one element a bucket.
  Vec2 low = mesh.nodes.front(), high = mesh.nodes.front();
  for (const Vec2& x : mesh.nodes) {
    low = low.cwiseMin(x);
    high = high.cwiseMax(x);
  }
  const double margin = 1e-8 * (high - low).norm();  // [m]
  low.array() -= margin;
  high.array() += margin;
  const Vec2 size = high - low;
  const double h = std::sqrt(size.x() * size.y() / std::max(element_count, 1));  // [m]
  nx_ = std::clamp(static_cast<int>(std::ceil(size.x() / h)), 1, 4 * element_count);
  ny_ = std::clamp(static_cast<int>(std::ceil(size.y() / h)), 1, 4 * element_count);
  origin_ = low;
  cell_ = Vec2(size.x() / nx_, size.y() / ny_);
  max_steps_ = 64 + 2 * (nx_ + ny_);

  // Buckets overlapped by each element's box (all six nodes, widened by a tiny margin), in CSR.
  auto bucket_range = [&](int e, int range[4]) {
    const auto& el = mesh.elements[e];
    Vec2 a = mesh.nodes[el[0]], b = a;
    for (int n : el) {
      a = a.cwiseMin(mesh.nodes[n]);
      b = b.cwiseMax(mesh.nodes[n]);
    }
    const double pad = 1e-8 * (b - a).norm();
    range[0] = std::clamp(static_cast<int>((a.x() - pad - origin_.x()) / cell_.x()), 0, nx_ - 1);
    range[1] = std::clamp(static_cast<int>((b.x() + pad - origin_.x()) / cell_.x()), 0, nx_ - 1);
    range[2] = std::clamp(static_cast<int>((a.y() - pad - origin_.y()) / cell_.y()), 0, ny_ - 1);
    range[3] = std::clamp(static_cast<int>((b.y() + pad - origin_.y()) / cell_.y()), 0, ny_ - 1);
  };
  const int buckets = nx_ * ny_;
  bucket_begin_.assign(buckets + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<int> fill;
    if (pass == 1) {
      for (int b = 0; b < buckets; ++b) bucket_begin_[b + 1] += bucket_begin_[b];
      bucket_elements_.resize(bucket_begin_[buckets]);
      fill.assign(bucket_begin_.begin(), bucket_begin_.end() - 1);
    }
    for (int e = 0; e < element_count; ++e) {
      int range[4];
      bucket_range(e, range);
      for (int j = range[2]; j <= range[3]; ++j)
        for (int i = range[0]; i <= range[1]; ++i) {
          const int b = j * nx_ + i;
          if (pass == 0)
            ++bucket_begin_[b + 1];
          else
            bucket_elements_[fill[b]++] = e;
        }
    }
  }

  // The corners of each element for locate_batch's check of a hint.
  const double stale = 4.0 * cell_.norm();  // [m] locate's bound on a hint's distance
  hint_corners_.resize(element_count);
  for (int e = 0; e < element_count; ++e) {
    const auto& el = mesh.elements[e];
    const Vec2 &a = mesh.nodes[el[0]], &b = mesh.nodes[el[1]], &d = mesh.nodes[el[2]];
    double* g = hint_corners_[e].g;
    g[0] = a.x(), g[1] = a.y(), g[2] = b.x(), g[3] = b.y(), g[4] = d.x(), g[5] = d.y();
    g[6] = 1.0 / (2.0 * mesh.area[e]);
    // A point within eps of a straight triangle is within (1 + 3 eps) of its farthest corner
    // from corner 0; the factor 1 + 1e-6 covers that and the round-off of the distances.
    const double reach = std::max((b - a).norm(), (d - a).norm()) * (1.0 + 1e-6);  // [m]
    g[7] = !curved_[e] && reach < stale ? 1.0 : 0.0;
  }

  // Seed of a bucket: of the elements it lists, the one whose centroid is nearest its centre;
  // an empty bucket (in a hole, beyond a bank) takes the seed of the nearest listed bucket
  // (breadth-first over the grid).
  seed_.assign(buckets, -1);
  std::vector<int> queue;
  queue.reserve(buckets);
  for (int b = 0; b < buckets; ++b) {
    const Vec2 centre = origin_ + Vec2((b % nx_ + 0.5) * cell_.x(), (b / nx_ + 0.5) * cell_.y());
    double best = std::numeric_limits<double>::infinity();
    for (int k = bucket_begin_[b]; k < bucket_begin_[b + 1]; ++k) {
      const auto& el = mesh.elements[bucket_elements_[k]];
      const Vec2 centroid = (mesh.nodes[el[0]] + mesh.nodes[el[1]] + mesh.nodes[el[2]]) / 3.0;
      const double d = (centroid - centre).squaredNorm();
      if (d < best) {
        best = d;
        seed_[b] = bucket_elements_[k];
      }
    }
    if (seed_[b] >= 0) queue.push_back(b);
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int b = queue[head], i = b % nx_, j = b / nx_;
    const int next[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
    for (const auto& [ni, nj] : next) {
      if (ni < 0 || ni >= nx_ || nj < 0 || nj >= ny_ || seed_[nj * nx_ + ni] >= 0) continue;
      seed_[nj * nx_ + ni] = seed_[b];
      queue.push_back(nj * nx_ + ni);
    }
  }
}

int PointLocator::bucket_of(const Vec2& p) const {
  const double x = (p.x() - origin_.x()) / cell_.x(), y = (p.y() - origin_.y()) / cell_.y();
  if (!(x >= 0 && x <= nx_ && y >= 0 && y <= ny_)) return -1;
  return std::min(static_cast<int>(y), ny_ - 1) * nx_ + std::min(static_cast<int>(x), nx_ - 1);
}

// Barycentric coordinates (P-32) of p in the straight triangle, by the edge they measure the
// distance from: c[k] = lambda of the vertex opposite local edge k, i.e. lambda_{(k+2)%3}.
// A curved element (P-33) holds p when one of its four sub-triangles does; c[k] is then the
// most negative of the two half-edges' coordinates, on the same scale.
bool PointLocator::edge_coordinates(int e, const Vec2& p, double c[3]) const {
  const auto& el = mesh_->elements[e];
  const auto& x = mesh_->nodes;
  const double inverse = 1.0 / (2.0 * mesh_->area[e]);  // [m^-2]
  if (!curved_[e]) {
    const Vec2 &a = x[el[0]], &b = x[el[1]], &d = x[el[2]];
    c[0] = cross(a - p, b - p) * inverse;  // lambda_2
    c[1] = cross(b - p, d - p) * inverse;  // lambda_0
    c[2] = cross(d - p, a - p) * inverse;  // lambda_1
    return c[0] >= -eps && c[1] >= -eps && c[2] >= -eps;
  }
  for (int k = 0; k < 3; ++k) {
    const Vec2 &a = x[el[k]], &m = x[el[3 + k]], &b = x[el[(k + 1) % 3]];
    c[k] = 2.0 * inverse * std::min(cross(a - p, m - p), cross(m - p, b - p));
  }
  for (const auto& t : Mesh::sub_triangles)
    if (in_triangle(x[el[t[0]]], x[el[t[1]]], x[el[t[2]]], p, eps)) return true;
  return false;
}

bool PointLocator::contains(int element, const Vec2& p) const {
  double c[3];
  return edge_coordinates(element, p, c);
}

PointLocator::WalkResult PointLocator::walk(int start, const Vec2& p, bool stochastic,
                                            int max_steps) const {
  std::uint32_t state = 0x9E3779B9u ^ static_cast<std::uint32_t>(start);
  int e = start;
  for (int steps = 0; steps <= max_steps; ++steps) {
    double c[3];
    if (edge_coordinates(e, p, c)) return {e, -1, true, steps};
    int k = 0;
    if (c[1] < c[k]) k = 1;
    if (c[2] < c[k]) k = 2;
    if (!(c[k] < -eps)) return {e, -1, false, steps};  // nothing to cross (a folded element)
    if (stochastic) {
      int negative[3], count = 0;
      for (int j = 0; j < 3; ++j)
        if (c[j] < -eps) negative[count++] = j;
      k = negative[next_random(state) % static_cast<std::uint32_t>(count)];
    }
    const int next = mesh_->neighbours[e][k];
    if (Mesh::is_boundary(next)) return {e, Mesh::boundary_edge_of(next), false, steps + 1};
    e = next;
  }
  return {e, -1, false, max_steps};
}

Location PointLocator::locate(const Vec2& p, int hint) const {
  if (!p.allFinite()) return {};
  const int bucket = bucket_of(p);
  int start = hint >= 0 && hint < mesh_->element_count() ? hint : -1;
  if (start >= 0 && (mesh_->nodes[mesh_->elements[start][0]] - p).norm() > 4.0 * cell_.norm())
    start = -1;  // a stale hint: the grid is nearer
  if (start < 0) {
    const Vec2 q = p.cwiseMax(origin_).cwiseMin(origin_ + Vec2(nx_ * cell_.x(), ny_ * cell_.y()));
    start = seed_[bucket >= 0 ? bucket : bucket_of(q)];
  }
  WalkResult w = walk(start, p, false, max_steps_);
  int steps = w.steps;
  if (!w.found && w.boundary_edge < 0) {  // cycled: walk again, choosing edges at random
    w = walk(w.element, p, true, 8 * max_steps_);
    steps += w.steps;
  }
  if (w.found) return inside_at(w.element, p, steps);
  if (bucket >= 0)
    for (int k = bucket_begin_[bucket]; k < bucket_begin_[bucket + 1]; ++k) {
      ++steps;
      if (contains(bucket_elements_[k], p)) return inside_at(bucket_elements_[k], p, steps);
    }
  Location outside;
  outside.element = w.element;
  outside.steps = steps;
  outside.boundary_edge = w.boundary_edge;
  if (w.boundary_edge >= 0) outside.boundary_group = mesh_->boundary[w.boundary_edge].group;
  return outside;
}

void PointLocator::locate_batch(int n, const double* x, const double* y, const bool* active,
                                const int* hints, Location* out) const {
  const int element_count = mesh_->element_count();
  for (int k = 0; k < n; ++k) {
    if (!active[k]) continue;
    const int e = hints[k];
    const Vec2 p(x[k], y[k]);
    if (e >= 0 && e < element_count) {
      const double* g = hint_corners_[e].g;
      if (g[7] != 0.0) {  // edge_coordinates and reference_coordinates of a straight element
        const Vec2 a = Vec2(g[0], g[1]) - p, b = Vec2(g[2], g[3]) - p, d = Vec2(g[4], g[5]) - p;
        const double c0 = cross(a, b) * g[6], c1 = cross(b, d) * g[6], c2 = cross(d, a) * g[6];
        if (c0 >= -eps && c1 >= -eps && c2 >= -eps) {
          out[k] = Location{.element = e, .r = c2, .s = c0, .inside = true};
          continue;
        }
      }
    }
    out[k] = locate(p, e);
  }
}

Location PointLocator::locate_brute_force(const Vec2& p) const {
  for (int e = 0; e < mesh_->element_count(); ++e)
    if (contains(e, p)) return inside_at(e, p, e + 1);
  Location outside;
  outside.steps = mesh_->element_count();
  return outside;
}

Location PointLocator::inside_at(int element, const Vec2& p, int steps) const {
  Location location;
  location.element = element;
  location.inside = true;
  location.curved = curved_[element] != 0;
  location.steps = steps;
  const Vec2 rs = reference_coordinates(element, p);
  location.r = rs.x();
  location.s = rs.y();
  return location;
}

// Straight element: (r, s) = (lambda_1, lambda_2) (P-32). Curved element: solve
// x(r, s) = sum_k X_k N_k(r, s) = p by Newton from the straight guess,
//   (r, s) <- (r, s) - J^-1 (x(r, s) - p),   J = dx/d(r, s) = sum_k X_k grad N_k^T,
// which converges quadratically to round-off in a few iterations on a valid element.
Vec2 PointLocator::reference_coordinates(int element, const Vec2& p) const {
  const auto& el = mesh_->elements[element];
  const auto& x = mesh_->nodes;
  const Vec2 &a = x[el[0]], &b = x[el[1]], &d = x[el[2]];
  const double inverse = 1.0 / (2.0 * mesh_->area[element]);
  const Vec2 straight(cross(d - p, a - p) * inverse, cross(a - p, b - p) * inverse);
  if (!curved_[element]) return straight;
  Vec2 rs = straight;
  for (int iteration = 0; iteration < 20; ++iteration) {
    const P2Values N = p2_values(rs.x(), rs.y());
    const P2Gradients G = p2_reference_gradients(rs.x(), rs.y());
    Vec2 mapped = Vec2::Zero();
    Mat2 J = Mat2::Zero();
    for (int k = 0; k < 6; ++k) {
      mapped += N[k] * x[el[k]];
      J += x[el[k]] * G[k].transpose();
    }
    const Vec2 delta = J.inverse() * (mapped - p);
    if (!delta.allFinite()) return straight;  // a folded element: keep the straight estimate
    rs -= delta;
    // (r, s) are O(1): 1e-12 is round-off of x ~ 1e3 m over J ~ h. A tighter bound (it was
    // 1e-14) is never met far from the origin, and every call then ran all 20 iterations.
    if (delta.norm() < 1e-12) break;
  }
  return rs;
}

}  // namespace flotsam
