#include "flow/fem/characteristics.hpp"

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
  const Foot foot{dt, q_x, q_y, q_x_d, q_y_d};
  advect(PathVelocity{u, v, u, v, 0.0}, dt, std::span(&foot, 1));
}

void Characteristics::advect(const PathVelocity& w, double dt, std::span<const Foot> feet) const {
  const int n = mesh_.node_count();
  for (const Foot& foot : feet) {
    foot.q_x_d.resize(n);
    foot.q_y_d.resize(n);
  }
  // w(t) = u^n + s (u^n - u^{n-1}) at t = t^{n+1} - lag: s = (dt - lag) / dt_before.
  const auto slope = [&](double lag) { return w.dt_before > 0.0 ? (dt - lag) / w.dt_before : 0.0; };
  int most = 0;
#pragma omp parallel for schedule(dynamic, 256) reduction(max : most)
  for (int i = 0; i < n; ++i) {
    // The path velocity at p, `lag` before t^{n+1}, or false when p is outside the domain;
    // `element` follows the walk.
    int element = node_element_[i];
    Location at, foot_at;
    const auto velocity = [&](const Vec2& p, double lag, Vec2& velocity_at) {
      at = locator_.locate(p, element);
      if (!at.inside) return false;
      element = at.element;
      velocity_at = interpolate_p2(mesh_, at, w.u, w.v);
      if (w.dt_before > 0.0)
        velocity_at +=
            slope(lag) * (velocity_at - interpolate_p2(mesh_, at, w.u_before, w.v_before));
      return true;
    };
    Vec2 x = mesh_.nodes[i];
    Vec2 w_x(w.u[i], w.v[i]);  // [m/s]
    if (w.dt_before > 0.0) w_x += slope(0.0) * (w_x - Vec2(w.u_before[i], w.v_before[i]));
    bool moved = false, stopped = false;
    double lag = 0.0;  // [s] traced so far
    int steps = 0, halvings = 0;
    for (const Foot& foot : feet) {
      while (!stopped && lag < foot.lag && steps < substep_limit) {
        const double speed = w_x.norm();
        if (speed == 0.0 && w.dt_before == 0.0) break;  // a frozen field: the path stays here
        const double left = foot.lag - lag;
        const double h =
            (speed > 0.0 ? std::min(left, courant_per_substep * size_[element] / speed) : left) /
            static_cast<double>(1 << halvings);  // [s]
        Vec2 w_mid, w_end;
        const int start = element;
        if (!velocity(x - 0.5 * h * w_x, lag + 0.5 * h, w_mid) ||
            !velocity(x - h * w_mid, lag + h, w_end)) {  // midpoint
          element = start;
          stopped = ++halvings > max_halvings;  // left the domain: stop at x
          continue;
        }
        x -= h * w_mid;
        w_x = w_end;
        foot_at = at;
        moved = true;
        lag += h;
        ++steps;
      }
      const Vec2 q = moved ? interpolate_p2(mesh_, foot_at, foot.q_x, foot.q_y)
                           : Vec2(foot.q_x[i], foot.q_y[i]);
      foot.q_x_d[i] = q.x();
      foot.q_y_d[i] = q.y();
    }
    most = std::max(most, steps);
  }
  max_substeps_ = most;
}

}  // namespace flotsam
