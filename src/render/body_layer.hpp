#pragma once
// The bodies (docs/rendering.md): rotated rectangles L x l around x_G at angle theta, filled by
// category and outlined in dark ink. A body thinner or shorter than min_body_pixels on the
// picture is drawn that size so that logs stay visible on a whole-reach view.
#include <cairo.h>

#include "render/colour_map.hpp"
#include "render/frame_layout.hpp"
#include "render/scene.hpp"

namespace flotsam {

inline constexpr double min_body_pixels = 3.0;  // [px] smallest drawn side of a body

/// Fill colour of a category: floating burlywood, grounded sienna, jammed crimson, gone grey
/// (drawn half transparent).
Colour body_colour(BodyCategory category);

/// Human name of a category: "floating", "grounded", "jammed", "gone".
const char* body_category_name(BodyCategory category);

/// Draws every body, clipped to the plot box; gone bodies first, then the others.
void draw_bodies(cairo_t* cr, const Scene& scene, const FrameLayout& layout);

}  // namespace flotsam
