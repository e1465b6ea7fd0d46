#pragma once
// The text around the plot (docs/rendering.md): title and time stamp above; below, a scale bar
// in metres, a legend of the body categories present with their counts, and the arrow key.
#include <cairo.h>

#include <string>

#include "render/frame_layout.hpp"
#include "render/scene.hpp"

namespace flotsam {

/// The scale bar's length: the largest 1, 2 or 5 times a power of ten not above `target` [m].
double scale_bar_length(double target);

/// "50 m", "200 m", "1 km", "0.5 m".
std::string format_distance(double metres);

/// Title (left) and "t = h:mm:ss" (right) above the plot; a thin frame around the plot.
void draw_header(cairo_t* cr, const Scene& scene, const FrameLayout& layout);

/// Scale bar, body legend and, when u_ref > 0 [m/s], the arrow key below the plot.
void draw_footer(cairo_t* cr, const Scene& scene, const FrameLayout& layout, double u_ref);

}  // namespace flotsam
