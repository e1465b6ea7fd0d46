#include "flow/fv/flow_sources.hpp"

#include <fmt/format.h>

#include <optional>

#include "core/error.hpp"
#include "mesh/point_locator.hpp"
#include "mesh/simple_polygon.hpp"

namespace flotsam {

FlowSources::FlowSources(const std::vector<FlowSource>& sources, const Mesh& mesh,
                         const CellMesh& cells) {
  std::optional<PointLocator> locator;  // built once, for point sources only
  for (const FlowSource& s : sources) {
    Placed placed;
    placed.discharge = s.discharge;
    if (s.polygon.empty()) {
      // The cell holding the point, found as the flow field finds a gauge's (FvFlowField).
      if (!locator) locator.emplace(mesh);
      const Location where = locator->locate(s.point);
      if (!where.inside)
        throw_input_error("{}: the point ({:.3f}, {:.3f}) m lies outside the mesh '{}'", s.origin,
                          s.point.x(), s.point.y(), mesh.source);
      placed.cells.push_back(cells.cell_of(where.element, where.r, where.s));
    } else {
      for (int i = 0; i < cells.cell_count; ++i)
        if (polygon_contains(s.polygon, cells.centroid[i])) placed.cells.push_back(i);
      if (placed.cells.empty())
        throw_input_error(
            "{}: no cell's centroid lies inside the polygon ({:.3g} m^2; the cells of the mesh "
            "'{}' are larger there, or it lies outside the mesh): give a larger polygon or a "
            "point",
            s.origin, std::abs(signed_area(s.polygon)), mesh.source);
    }
    for (int i : placed.cells) placed.area += cells.area[i];
    sources_.push_back(std::move(placed));
  }
}

// (M-24): the depth int_t0^t1 Q_s dt / A_s in each cell of source s; a cell in two polygons
// takes both.
double FlowSources::depths(double t0, double t1, std::vector<double>& depth) const {
  for (const Placed& s : sources_)
    for (int i : s.cells) depth[i] = 0.0;
  double volume = 0.0;
  for (const Placed& s : sources_) {
    const double V = s.discharge.integral(t0, t1);  // [m^3]
    for (int i : s.cells) depth[i] += V / s.area;
    volume += V;
  }
  return volume;
}

}  // namespace flotsam
