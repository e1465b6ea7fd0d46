#pragma once
// Advection by the method of characteristics (spec 1.3, the paper's ref. [11]): the material
// derivative of (M-1a), du/dt + (u . grad) u, is taken along the paths of the water,
//     q*(x_i) = q(X_i(t^{n+1} - lag)),   dX/dt = w(X, t),  X(t^{n+1}) = x_i,
// at every P2 node x_i, by tracing the path back (midpoint rule in sub-steps of at most half an
// element) and interpolating a carried field q at its foot with the P2 shape functions. The
// path velocity w is u^n, or linear in time through u^{n-1} and u^n (extrapolated beyond t^n),
// which makes the feet second-order accurate in time; the carried fields are u^n (foot at
// t^n, lag dt) and u^{n-1} (foot at t^{n-1}) for BDF2, or u^n plus the explicit part of the
// step's acceleration for the theta-scheme (flow_time_stepping.cpp).
// It is unconditionally stable, has no node-to-node wiggles, and uses the point location of
// spec 4.4 (the walk from the element of the previous sub-step). A sub-step that leaves the
// domain is halved (up to 4 times): a path along a straight wall runs on its line, where
// round-off puts half its points outside, and a chord cuts across a curved wall. A path that
// still leaves stops at its last point inside: through an inflow boundary the water brings the
// boundary's value.
#include <span>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/point_locator.hpp"

namespace flotsam {

/// The velocity along the paths [m/s], P2 per node: u^n at t^n and, when `dt_before` > 0,
/// u^{n-1} at t^n - dt_before, w(t) = u^n + (t - t^n) (u^n - u^{n-1}) / dt_before; else u^n.
struct PathVelocity {
  const std::vector<double>& u;
  const std::vector<double>& v;
  const std::vector<double>& u_before;
  const std::vector<double>& v_before;
  double dt_before = 0.0;  // [s]
};

/// A carried P2 field (q_x, q_y) and its departure values, read where the path was at
/// t^{n+1} - lag.
struct Foot {
  double lag;  // [s] > 0
  const std::vector<double>& q_x;
  const std::vector<double>& q_y;
  std::vector<double>& q_x_d;
  std::vector<double>& q_y_d;
};

class Characteristics {
 public:
  /// Keeps a reference to `mesh`, which must outlive this object.
  explicit Characteristics(const Mesh& mesh);

  /// Departure values (q_x, q_y)(X_i) at every P2 node of the carried P2 field (q_x, q_y) along
  /// the paths of the P2 velocity (u, v) [m/s] over dt [s]. Deterministic and thread-count
  /// independent (one path per node, OpenMP over nodes).
  void advect(const std::vector<double>& u, const std::vector<double>& v, double dt,
              const std::vector<double>& q_x, const std::vector<double>& q_y,
              std::vector<double>& q_x_d, std::vector<double>& q_y_d) const;
  /// The departure values of every foot (in increasing lag) along the paths of w, traced back
  /// from t^{n+1} = t^n + dt [s]. Deterministic and thread-count independent.
  void advect(const PathVelocity& w, double dt, std::span<const Foot> feet) const;

  /// Largest number of sub-steps any path took in the last advect() [-] (statistics).
  int max_substeps() const { return max_substeps_; }

 private:
  const Mesh& mesh_;
  PointLocator locator_;
  std::vector<int> node_element_;  // per P2 node: an element holding it (the walk's start)
  std::vector<double> size_;       // per element: h_e = sqrt(2 A_e) [m]
  mutable int max_substeps_ = 0;
};

}  // namespace flotsam
