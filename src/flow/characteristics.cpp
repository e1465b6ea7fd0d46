#include "flow/characteristics.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/interpolation.hpp"

namespace flotsam {

namespace {

constexpr double courant_per_substep = 0.5;  // [-] path length of one sub-step / h_e
constexpr int substep_limit = 10000;         // [-] bounds a path in a stagnant eddy

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
                             std::vector<double>& u_d, std::vector<double>& v_d) const {
  const int n = mesh_.node_count();
  u_d.resize(n);
  v_d.resize(n);
  int most = 0;
#pragma omp parallel for schedule(dynamic, 256) reduction(max : most)
  for (int i = 0; i < n; ++i) {
    // The velocity at p, or false when p is outside the domain; `element` follows the walk.
    int element = node_element_[i];
    const auto velocity = [&](const Vec2& p, Vec2& w) {
      const Location at = locator_.locate(p, element);
      if (!at.inside) return false;
      element = at.element;
      w = interpolate_p2(mesh_, at, u, v);
      return true;
    };
    Vec2 x = mesh_.nodes[i];
    Vec2 w(u[i], v[i]);
    double left = dt;  // [s] of the path still to trace
    int steps = 0;
    while (left > 0.0 && steps < substep_limit) {
      const double speed = w.norm();
      if (speed == 0.0) break;
      const double h = std::min(left, courant_per_substep * size_[element] / speed);  // [s]
      Vec2 w_mid, w_end;
      if (!velocity(x - 0.5 * h * w, w_mid)) break;  // midpoint rule
      const Vec2 foot = x - h * w_mid;
      if (!velocity(foot, w_end)) break;  // left the domain: stop at x
      x = foot;
      w = w_end;
      left -= h;
      ++steps;
    }
    u_d[i] = w.x();
    v_d[i] = w.y();
    most = std::max(most, steps);
  }
  max_substeps_ = most;
}

}  // namespace flotsam
