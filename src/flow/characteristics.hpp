#pragma once
// Advection by the method of characteristics (spec 1.3, the paper's ref. [11]): the advective
// part of (M-1a), du/dt + (u . grad) u = 0, is solved exactly along the paths of the water,
//     u*(x_i) = u^n(X_i(t^n)),   dX/dt = u^n(X),  X(t^{n+1}) = x_i,
// at every P2 node x_i, by tracing the path back over dt (midpoint rule in sub-steps of at most
// half an element) and interpolating u^n at its foot with the P2 shape functions. It is
// unconditionally stable, has no node-to-node wiggles, and uses the point location of spec 4.4
// (the walk from the element of the previous sub-step). A path that leaves the domain stops at
// its last point inside: through an inflow boundary the water brings the boundary's velocity.
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/point_locator.hpp"

namespace flotsam {

class Characteristics {
 public:
  /// Keeps a reference to `mesh`, which must outlive this object.
  explicit Characteristics(const Mesh& mesh);

  /// Departure values (u_d, v_d) at every P2 node of the P2 field (u, v) [m/s] after dt [s].
  /// Deterministic and thread-count independent (one path per node, OpenMP over nodes).
  void advect(const std::vector<double>& u, const std::vector<double>& v, double dt,
              std::vector<double>& u_d, std::vector<double>& v_d) const;

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
