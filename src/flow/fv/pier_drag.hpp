#pragma once
// The piers' form drag on the water (docs/model.md "Pier drag", (M-25)), finite volumes.
// A pier meshed as a hole takes almost no drag from a depth-averaged flow without viscosity: the
// flow closes behind it as potential flow does and recovers its pressure, so the bridge's own
// backwater would be missing. Its drag is therefore added as a force, as HEC-RAS's momentum
// method counts it:
//   F_p = 1/2 rho C_d b h |u| u                                                        (M-25)
// with b the pier's width across the flow (a meshed circle's diameter, the circle through its
// vertices; any other outline's smallest width: piers stand along the flow) and h, u the water
// around it. F_p is spread over the pier's *ring*, the cells whose centroid lies within b of its
// outline and those along it (area A_r = sum of their areas):
//   d(hu)/dt = -m_i h |u| u,   m_i = C_d b / (2 A_r)  [1/m]   (a sum where rings overlap),
// so that sum_i A_i m_i = C_d b / 2 exactly. Backward Euler in the velocity, as friction (M-14):
//   (hu)^{n+1} = (hu)* 2 / (1 + sqrt(1 + 4 dt m_i |u*|)),
// the flow slows and never turns round; at rest nothing changes (a lake at rest stays at rest),
// and mass is untouched. What each cell gives up is kept, so the force on the piers is exact.
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "flow/fv/cell_mesh.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

struct BridgeConfig;

struct PierDrag {
  struct Pier {
    std::string name;        // its boundary group
    double width = 0.0;      // b [m]
    double ring_area = 0.0;  // A_r [m^2]
    double density = 0.0;    // its m_i [1/m] in each cell of its ring
    std::vector<int> ring;   // its cells, ascending
  };
  std::vector<Pier> piers;
  std::vector<double> density;  // m_i [1/m] per cell (its piers' summed); empty without piers
  std::vector<int> cells;       // the cells with m_i > 0, ascending
  std::vector<Vec2> impulse;    // sum over sub-steps of ((hu)* - (hu)^{n+1}) A_i per cell
                                // [m^4/s] (times rho: N s)
  double duration = 0.0;        // [s] the time over which `impulse` was summed

  bool empty() const { return cells.empty(); }
  /// The impulse the water has given all piers so far [m^4/s] (times rho: N s), summed in the
  /// cells' order.
  Vec2 total_impulse() const;
  /// Pier p's share of it: each cell's impulse in the ratio of p's density to the cell's.
  Vec2 impulse_of(int p) const;
};

/// The piers of `mesh`: its boundary groups named "pier*" and those the case's bridges name as
/// piers, with drag coefficient `drag_coefficient` C_d [-] (0: none, an empty PierDrag).
PierDrag find_pier_drag(const Mesh& mesh, const CellMesh& cells,
                        const std::vector<BridgeConfig>& bridges, double drag_coefficient);

}  // namespace flotsam
