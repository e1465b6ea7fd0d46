#include "flow/characteristics.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/interpolation.hpp"

namespace flotsam {

namespace {

constexpr double courant_per_substep = 0.5;  // [-] path length of one sub-step / h_e
constexpr int substep_limit = 10000;         // [-] bounds a path in a stagnant eddy
constexpr int max_halvings = 4;              // [-] of a sub-step that leaves the domain

}  // namespace

Characteristics::Characteristics(const Mesh& mesh)
    : mesh_(mesh), locator_(mesh), node_element_(mesh.node_count(), -1) {
  size_.resize(mesh.element_count());
  for (int e = 0; e < mesh.element_count(); ++e) {
    size_[e] = std::sqrt(2.0 * mesh.area[e]);
    for (int node : mesh.elements[e]) node_element_[node] = e;
  }
}

void Characteristics::advect(const std::vector<double>& u, const std::vector<double>& v, double dt,
                             const std::vector<double>& q_x, const std::vector<double>& q_y,
                             std::vector<double>& q_x_d, std::vector<double>& q_y_d) const {
  const int n = mesh_.node_count();
  q_x_d.resize(n);
  q_y_d.resize(n);
  int most = 0;
#pragma omp parallel for schedule(dynamic, 256) reduction(max : most)
  for (int i = 0; i < n; ++i) {
    // The velocity at p, or false when p is outside the domain; `element` follows the walk.
    int element = node_element_[i];
    Location at, foot_at;
    const auto velocity = [&](const Vec2& p, Vec2& w) {
      at = locator_.locate(p, element);
      if (!at.inside) return false;
      element = at.element;
      w = interpolate_p2(mesh_, at, u, v);
      return true;
    };
    Vec2 x = mesh_.nodes[i];
    Vec2 w(u[i], v[i]);
    bool moved = false;
    double left = dt;  // [s] of the path still to trace
    int steps = 0, halvings = 0;
    while (left > 0.0 && steps < substep_limit) {
      const double speed = w.norm();
      if (speed == 0.0) break;
      const double h = std::min(left, courant_per_substep * size_[element] / speed) /
                       static_cast<double>(1 << halvings);  // [s]
      Vec2 w_mid, w_end;
      const int start = element;
      if (!velocity(x - 0.5 * h * w, w_mid) || !velocity(x - h * w_mid, w_end)) {  // midpoint
        element = start;
        if (++halvings > max_halvings) break;  // left the domain: stop at x
        continue;
      }
      x -= h * w_mid;
      w = w_end;
      foot_at = at;
      moved = true;
      left -= h;
      ++steps;
    }
    const Vec2 q = moved ? interpolate_p2(mesh_, foot_at, q_x, q_y) : Vec2(q_x[i], q_y[i]);
    q_x_d[i] = q.x();
    q_y_d[i] = q.y();
    most = std::max(most, steps);
  }
  max_substeps_ = most;
}

}  // namespace flotsam
