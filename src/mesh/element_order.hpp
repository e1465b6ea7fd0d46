#pragma once
// The elements' order (docs/mesh.md "Numbering"): Cuthill-McKee (core/cuthill_mckee.hpp) over
// the elements' neighbours across edges, from the numbering along the curve (curve_order.hpp),
// which decides every tie. Its levels are fronts across the mesh, each numbered along the one
// before: a sweep over the elements reads their neighbours' values in a few forward streams that
// the processor's prefetcher follows, where along the curve the neighbours across a quadrant's
// border are misses (docs/performance.md "On a Gmsh mesh"). The nodes keep the curve's order.
#include "mesh/mesh.hpp"

namespace flotsam {

/// `mesh` with its elements in that order: the same nodes, elements, boundary edges and groups.
Mesh ordered_by_cuthill_mckee(const Mesh& mesh);

}  // namespace flotsam
