#pragma once
// Velocity arrows (docs/rendering.md) on a regular grid of the plot box, `arrow_spacing` pixels
// apart, the first half a spacing in from the corner (rounded to a pixel centre). At each sample
// point inside the mesh the P2 velocity is interpolated (mesh/interpolation.hpp) and an arrow
// centred on the point is drawn |u| / u_ref * 0.9 spacing long, u_ref the scene's reference speed
// or else the largest sampled speed; arrows shorter than 1.5 px are left out.
#include <cairo.h>

#include "render/frame_layout.hpp"
#include "render/scene.hpp"

namespace flotsam {

/// Draws the arrows when the scene has a velocity; returns u_ref [m/s] (0: no arrows drawn),
/// for the arrow key in the footer.
double draw_arrows(cairo_t* cr, const Scene& scene, const FrameLayout& layout);

/// Draws one arrow from tail to tip [px], head sized for a font size f [px].
void draw_arrow(cairo_t* cr, const Vec2& tail, const Vec2& tip, double f);

}  // namespace flotsam
