#pragma once
// Where things go in a picture, and the map from the world [m] to pixels.
//
//   +--------------------------------------------------+
//   | title                                   t = h:mm:ss |   header
//   | +----------------------------------------+  +-+ 0.3 |
//   | |   field, boundaries, piers, bodies,    |  | | 0.2 |   plot  +  colour bar with ticks,
//   | |   arrows (the world window)            |  | | 0.1 |            name [unit] along it
//   | +----------------------------------------+  +-+ 0.0 |
//   | |---| 100 m      [] floating 3 [] jammed 2   -> 1 m/s |   footer
//   +--------------------------------------------------+
//
// The plot box has the world window's aspect ratio (one scale in x and y) and as many pixels as
// fit; the whole composition is centred in the image. Sizes scale with the font size, which
// grows with the image: clamp(sqrt(width * height) / 55, 9, 24) px.
#include "core/vec.hpp"
#include "render/scene.hpp"

namespace flotsam {

/// A rectangle of the image in pixels, y down; (x0, y0) is the top-left corner.
struct PixelBox {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;  // [px]
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
};

struct FrameLayout {
  int width = 0, height = 0;      // [px] the image
  double font_size = 12.0;        // [px]
  PixelBox header;                // title and time stamp
  PixelBox plot;                  // the world window (integer corners)
  PixelBox colour_bar;            // the bar itself; ticks and labels to its right
  PixelBox footer;                // scale bar, body legend, arrow key
  ViewWindow window;              // [m] the world rectangle shown in `plot`
  double pixels_per_metre = 1.0;  // [px/m]

  /// Image position of a world point [px] (y down), and back.
  Vec2 to_pixel(const Vec2& p) const {
    return {plot.x0 + (p.x() - window.x_min) * pixels_per_metre,
            plot.y0 + (window.y_max - p.y()) * pixels_per_metre};
  }
  Vec2 to_world(const Vec2& pixel) const {
    return {window.x_min + (pixel.x() - plot.x0) / pixels_per_metre,
            window.y_max - (pixel.y() - plot.y0) / pixels_per_metre};
  }
};

/// The layout of a valid scene (validate_scene). Throws InputError when the image is too small
/// for a plot box of at least 16 x 16 px.
FrameLayout frame_layout(const Scene& scene);

}  // namespace flotsam
