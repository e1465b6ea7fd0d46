#pragma once
// The domain's edges (docs/rendering.md): boundary edges chained into closed loops; a loop that
// runs clockwise is a hole of the mesh (a pier, an island) and is filled grey; walls are thick
// dark grey lines, open boundaries dashed blue ones. Curved edges are drawn through their mid
// node (the parabola of the P2 edge, as a Bezier curve). Bridge decks are translucent slabs.
#include <cairo.h>

#include <vector>

#include "render/frame_layout.hpp"
#include "render/scene.hpp"

namespace flotsam {

/// One closed chain of boundary edges (indices into Mesh::boundary), in the mesh's orientation:
/// counter-clockwise around the domain, so clockwise around a hole.
struct BoundaryLoop {
  std::vector<int> edges;
  double signed_area = 0.0;  // [m^2] of the polygon through ends and mid nodes; < 0: a hole
  bool is_hole() const { return signed_area < 0.0; }
};

/// The mesh's boundary as closed loops.
std::vector<BoundaryLoop> boundary_loops(const Mesh& mesh);

/// Fills the holes and strokes every boundary edge, clipped to the plot box.
void draw_boundaries(cairo_t* cr, const Scene& scene, const FrameLayout& layout);

}  // namespace flotsam
