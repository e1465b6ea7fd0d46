#pragma once
// The momentum balance of a straight, flat, frictionless reach (Chow 1959, ch. 3) that the
// jam-at-a-bridge verification cases check over a time window T:
//   mean of (M(x1) - M(x2)) - (P(end) - P(start)) / T = mean force on the obstacle,
// M the momentum flux through a cross-section of the finite-volume engine's cells (the scheme's
// own, whatever the cells' numbering), P the momentum of the water between them (a channel
// without friction keeps the seiches of its start: P changes by a few per cent of F T over a
// window); and the 1D depth upstream of an obstacle that takes a given force.
#include <cmath>
#include <vector>

#include "core/constants.hpp"
#include "flow/fv/fv_engine.hpp"

namespace flotsam::test {

/// The finite-volume engine's interior edges between the cells whose centroids lie on either
/// side of the line x = x0: the line's own edges where it is a line of cell edges (a structured
/// mesh), else a staircase of edges around it (an unstructured one).
inline std::vector<int> edges_across_x(const CellMesh& c, double x0) {
  std::vector<int> edges;
  for (int e = 0; e < c.edge_count; ++e) {
    const int i = c.left[e], j = c.right[e];
    if (j >= 0 && (c.centroid[i].x() < x0) != (c.centroid[j].x() < x0)) edges.push_back(e);
  }
  return edges;
}

/// The length [m] of the section `edges`.
inline double section_width(const CellMesh& c, const std::vector<int>& edges) {
  double sum = 0.0;
  for (const int e : edges) sum += c.length[e];
  return sum;
}

/// rho * the scheme's momentum flux along +x through the section `edges` [N]: the discrete
/// integral of (h u^2 + g h^2 / 2) dy the engine itself exchanges there (FiniteVolumeSolver::
/// section_flux). `depth` gets the section's mean depth [m]: the length-weighted mean of the
/// two cells' depths at each edge (whatever the cells' numbering).
inline double section_momentum(const FlowEngine& flow, const std::vector<int>& edges,
                               double& depth) {
  const FiniteVolumeSolver& solver = dynamic_cast<const FvEngine&>(flow).solver();
  const CellMesh& c = solver.cells();
  const std::vector<double>& h = solver.state().h;
  double h_sum = 0.0;
  for (const int e : edges) h_sum += c.length[e] * 0.5 * (h[c.left[e]] + h[c.right[e]]);
  depth = h_sum / section_width(c, edges);
  return water_density_default * solver.section_flux(edges, Vec2(1.0, 0.0)).momentum.x();
}

/// rho * the x-momentum of the water in the cells whose centroids lie between x1 and x2 [N s]:
/// the reach's, when x1 and x2 are lines of cell edges.
inline double reach_momentum(const FlowEngine& flow, double x1, double x2) {
  const FiniteVolumeSolver& solver = dynamic_cast<const FvEngine&>(flow).solver();
  const CellMesh& c = solver.cells();
  double sum = 0.0;
  for (int i = 0; i < c.cell_count; ++i)
    if (c.centroid[i].x() > x1 && c.centroid[i].x() < x2) sum += c.area[i] * solver.state().hu[i];
  return water_density_default * sum;
}

/// The reach between the lines x1 < x2 (lines of cell edges, or the staircases of edges around
/// them) and its momentum balance over a window:
/// start() when the window opens, sample() at each instant inside it, balance() at its end.
class ReachBalance {
 public:
  ReachBalance(const FlowEngine& flow, double x1, double x2)
      : x1_(x1),
        x2_(x2),
        cells_(dynamic_cast<const FvEngine&>(flow).solver().cells()),
        upstream_(edges_across_x(cells_, x1)),
        downstream_(edges_across_x(cells_, x2)) {}
  double upstream_width() const { return section_width(cells_, upstream_); }      // [m]
  double downstream_width() const { return section_width(cells_, downstream_); }  // [m]
  void start(const FlowEngine& flow) { momentum_start_ = reach_momentum(flow, x1_, x2_); }
  void sample(const FlowEngine& flow) {
    double d1 = 0.0, d2 = 0.0;
    flux_sum_ += section_momentum(flow, upstream_, d1) - section_momentum(flow, downstream_, d2);
    depth_sum_ += d2;
    ++samples_;
  }
  /// mean of M(x1) - M(x2) - (P(now) - P(start)) / window [N]: the mean force the reach's
  /// water exchanged with what stands in it.
  double balance(const FlowEngine& flow, double window) const {
    return flux_sum_ / samples_ - (reach_momentum(flow, x1_, x2_) - momentum_start_) / window;
  }
  double downstream_depth() const { return depth_sum_ / samples_; }  // [m] mean at x2

 private:
  double x1_, x2_;  // [m]
  const CellMesh& cells_;
  std::vector<int> upstream_, downstream_;
  double momentum_start_ = 0.0;              // [N s]
  double flux_sum_ = 0.0, depth_sum_ = 0.0;  // [N], [m]
  int samples_ = 0;
};

/// The depth [m] upstream whose momentum function per width, q^2 / h + g h^2 / 2, exceeds that
/// of depth h2 by `excess` [m^3/s^2] (the subcritical root, by Newton from h2).
inline double depth_upstream(double q, double h2, double excess) {
  const double target = q * q / h2 + 0.5 * gravity * h2 * h2 + excess;
  double h = h2;
  for (int k = 0; k < 50; ++k)
    h -= (q * q / h + 0.5 * gravity * h * h - target) / (gravity * h - q * q / (h * h));
  return h;
}

}  // namespace flotsam::test
