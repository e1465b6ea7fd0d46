#include "render/frame_layout.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace flotsam {

FrameLayout frame_layout(const Scene& scene) {
  FrameLayout layout;
  layout.width = scene.width;
  layout.height = scene.height;
  const double f = std::clamp(std::sqrt(double(scene.width) * scene.height) / 55.0, 9.0, 24.0);
  layout.font_size = f;

  // The window asked for: the given one, or the mesh's bounding box with a 3% margin.
  ViewWindow want;
  if (scene.view) {
    want = *scene.view;
  } else {
    want = bounding_box(*scene.mesh);
    const double margin = 0.03 * std::max(want.x_max - want.x_min, want.y_max - want.y_min);
    want = {want.x_min - margin, want.x_max + margin, want.y_min - margin, want.y_max + margin};
  }
  const double dx = want.x_max - want.x_min;  // [m]
  const double dy = want.y_max - want.y_min;  // [m]

  // Space left for the plot: the image minus margins, header, footer and colour-bar column.
  const double margin = std::round(0.8 * f);
  const double header = std::round(2.0 * f);
  const double footer = std::round(2.4 * f);
  const double column = std::round(8.5 * f);
  const double room_w = scene.width - 2 * margin - column;
  const double room_h = scene.height - 2 * margin - header - footer;
  const double scale = std::min(room_w / dx, room_h / dy);  // [px/m]
  const double plot_w = std::floor(std::min(room_w, dx * scale));
  const double plot_h = std::floor(std::min(room_h, dy * scale));
  if (!(plot_w >= 16 && plot_h >= 16)) {
    throw_input_error(
        "picture '{}': image {} x {} px leaves no room for the plot (needs at least "
        "16 x 16 px besides the title, colour bar and scale bar)",
        scene.title, scene.width, scene.height);
  }
  layout.pixels_per_metre = scale;
  const double cx = 0.5 * (want.x_min + want.x_max), cy = 0.5 * (want.y_min + want.y_max);
  layout.window = {cx - 0.5 * plot_w / scale, cx + 0.5 * plot_w / scale, cy - 0.5 * plot_h / scale,
                   cy + 0.5 * plot_h / scale};

  // Centre the composition (header + plot + footer high, plot + column wide).
  const double x0 = std::round(0.5 * (scene.width - plot_w - column));
  const double y0 = std::round(0.5 * (scene.height - plot_h - header - footer)) + header;
  layout.plot = {x0, y0, x0 + plot_w, y0 + plot_h};
  layout.header = {x0, y0 - header, x0 + plot_w + column, y0};
  layout.footer = {x0, y0 + plot_h, x0 + plot_w + column, y0 + plot_h + footer};

  // The bar spans the plot's height, but at least 8 font sizes when the image allows.
  const double bar_h = std::min(std::max(plot_h, 8.0 * f), room_h);
  const double bar_y0 = std::round(y0 + 0.5 * (plot_h - bar_h));
  const double bar_x0 = x0 + plot_w + std::round(0.8 * f);
  layout.colour_bar = {bar_x0, bar_y0, bar_x0 + std::round(1.0 * f), bar_y0 + bar_h};
  return layout;
}

}  // namespace flotsam
