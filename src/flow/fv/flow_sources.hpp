#pragma once
// Water let in inside the domain (flow.sources; docs/model.md "Sources", (M-24)): each source's
// discharge Q_s(t) >= 0 enters its cells in proportion to their areas,
//
//   dh_i/dt = Q_s(t) / A_s   for the cells i of source s,  A_s = sum of their areas,
//
// the cell holding a point source, or the cells whose centroids lie in a polygon. Like rain, the
// water brings no momentum, and the solver adds a sub-step's depth int Q_s dt / A_s inside its
// Runge-Kutta stages, so the volume let in is int Q_s dt exactly (fv_solver.cpp).
#include <vector>

#include "core/time_series.hpp"
#include "flow/fv/cell_mesh.hpp"
#include "io/case.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

class FlowSources {
 public:
  /// The case's sources on the cells. InputError naming the source when a point lies in no cell
  /// or a polygon holds no cell's centroid.
  FlowSources(const std::vector<FlowSource>& sources, const Mesh& mesh, const CellMesh& cells);

  bool any() const { return !sources_.empty(); }
  int count() const { return static_cast<int>(sources_.size()); }

  /// Sets depth[i] [m] to the depth the sources let into cell i over [t0, t1] [s] (the cells of
  /// no source untouched, 0 when `depth` is new) and returns the volume they let in [m^3].
  double depths(double t0, double t1, std::vector<double>& depth) const;

  /// The cells of source k, and their area A_s [m^2].
  const std::vector<int>& cells(int k) const { return sources_[k].cells; }
  double area(int k) const { return sources_[k].area; }

 private:
  struct Placed {
    TimeSeries discharge;  // Q(t) [m^3/s]
    std::vector<int> cells;
    double area = 0.0;  // A_s [m^2]
  };
  std::vector<Placed> sources_;
};

}  // namespace flotsam
