#include "flow/fv/fv_boundary.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace flotsam {

FvBoundaries FvBoundaries::resolve(const Mesh& mesh, const FlowConfig& flow) {
  FvBoundaries b;
  b.group_condition.assign(mesh.group_names.size(), -1);
  for (int k = 0; k < static_cast<int>(flow.boundaries.size()); ++k) {
    const BoundaryCondition& bc = flow.boundaries[k];
    const int g = mesh.find_group(bc.group);
    if (g < 0)
      throw_input_error("flow.boundaries.{}{}: the mesh '{}' has no boundary group '{}'", bc.group,
                        bc.line > 0 ? fmt::format(" (line {})", bc.line) : "", mesh.source,
                        bc.group);
    b.group_condition[g] = k;
  }
  return b;
}

FaceState ghost_state(const BoundaryCondition& bc, const FaceState& inside, const Vec2& n, double t,
                      double q, double g) {
  using Kind = BoundaryCondition::Kind;
  FaceState ghost = inside;
  switch (bc.kind) {
    case Kind::wall:
    case Kind::noslip: {
      const double u_n = inside.u * n.x() + inside.v * n.y();
      ghost.u -= 2.0 * u_n * n.x();
      ghost.v -= 2.0 * u_n * n.y();
      break;
    }
    case Kind::elevation: {
      // The level is imposed; the normal velocity follows from the characteristic that leaves
      // the domain, u_n + 2 c constant along it (subcritical): u_n,g = u_n + 2 (c - c_g).
      // A supercritical outflow takes no condition: the inside state leaves as it is.
      const double c = std::sqrt(g * inside.h);
      const double u_n = inside.u * n.x() + inside.v * n.y();
      if (u_n >= c && inside.h > 0.0) break;
      ghost.h = std::max(0.0, bc.value(t) - inside.z);
      const double u_n_ghost = u_n + 2.0 * (c - std::sqrt(g * ghost.h));
      ghost.u += (u_n_ghost - u_n) * n.x();
      ghost.v += (u_n_ghost - u_n) * n.y();
      break;
    }
    case Kind::discharge: {
      const double h_critical = std::cbrt(q * q / g);  // [m]
      ghost.h = std::max(inside.h, h_critical);
      const double speed = ghost.h > 0.0 ? q / ghost.h : 0.0;
      ghost.u = -speed * n.x();
      ghost.v = -speed * n.y();
      break;
    }
    case Kind::velocity:
      ghost.u = bc.value(t);
      ghost.v = bc.value_y(t);
      break;
    case Kind::free:
      break;
  }
  return ghost;
}

}  // namespace flotsam
