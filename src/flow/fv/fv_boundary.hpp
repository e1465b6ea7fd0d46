#pragma once
// Boundary conditions of the finite-volume engine (spec 1.4, issue 15 item 2): each boundary
// edge gets a ghost state outside it, and the edge's flux is the Riemann flux between the inside
// edge value and the ghost, as inside the domain.
//
//   wall, noslip: the inside state mirrored, u_n -> -u_n (no mass crosses: the flux's mass part
//                 is set to exactly 0); a frictionless wall, as the engine has no viscosity
//   elevation:    h_g = max(0, eta_b(t) - z_e), the normal velocity from the outgoing Riemann
//                 invariant u_n + 2 c of the inside, the tangential one the inside's (a
//                 subcritical inflow or outflow at a given level); a supercritical outflow
//                 leaves as it is
//   discharge:    the group's Q(t) [m^3/s] shared along it as q_e = Q h_e^{3/2} / sum(l h^{3/2})
//                 (spec 1.4; by length when the group is dry), entering along the inward normal
//                 with h_g = max(h_e, (q_e^2 / g)^{1/3}) (at least critical: onto a dry bed the
//                 water enters at critical depth), u_g = -q_e / h_g n
//   velocity:     h_g = h_e, u_g = u_b(t)
//   free:         the inside state (transmissive: what reaches the boundary leaves, at any
//                 Froude number)
// Groups of the mesh that the case does not name are walls.
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "io/case.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

/// The flow at one side of an edge.
struct FaceState {
  double h;  // [m]
  double z;  // [m] bed
  double u;  // [m/s]
  double v;  // [m/s]
};

struct FvBoundaries {
  std::vector<int> group_condition;  // per mesh group: index into FlowConfig::boundaries, or -1

  /// Resolves the case's conditions on the mesh's groups.
  static FvBoundaries resolve(const Mesh& mesh, const FlowConfig& flow);
};

/// The ghost state outside an edge of outward unit normal n, for condition `bc` at time t [s];
/// `q` [m^2/s] is the edge's share of a discharge condition (else unused).
FaceState ghost_state(const BoundaryCondition& bc, const FaceState& inside, const Vec2& n, double t,
                      double q, double g);

}  // namespace flotsam
