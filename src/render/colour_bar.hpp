#pragma once
// The colour bar (docs/rendering.md): the map from bottom (min) to top (max), one pixel row per
// colour, ticks at round values (1, 2 or 5 times a power of ten) with labels to the right, and
// the field's "name [unit]" written upwards beside them.
#include <cairo.h>

#include <string>
#include <vector>

#include "render/frame_layout.hpp"
#include "render/scene.hpp"

namespace flotsam {

/// A round step (1, 2 or 5 times a power of ten) near span / target_count.
double nice_step(double span, int target_count);

/// The multiples of nice_step(max - min, target_count) within [min, max].
std::vector<double> nice_ticks(double min, double max, int target_count = 5);

/// A tick label with as many decimals as the step needs ("0.25", "-3", "1.5e+06"); zero is "0".
std::string format_tick(double value, double step);

/// Draws the bar for the colour range [min, max] [field unit].
void draw_colour_bar(cairo_t* cr, const Scene& scene, const FrameLayout& layout, double min,
                     double max);

}  // namespace flotsam
