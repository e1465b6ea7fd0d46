#include "render/arrow_layer.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "mesh/interpolation.hpp"
#include "mesh/point_locator.hpp"
#include "render/cairo_draw.hpp"

namespace flotsam {

void draw_arrow(cairo_t* cr, const Vec2& tail, const Vec2& tip, double f) {
  const Vec2 d = tip - tail;
  const double length = d.norm();  // [px]
  if (length <= 0.0) return;
  const Vec2 a = d / length;
  const Vec2 n = perp(a);
  const double head = std::min(0.4 * length, 0.45 * f);  // [px]
  const Vec2 base = tip - head * a;
  // A white halo under the dark arrow keeps it readable on dark and light colours alike.
  for (const bool halo : {true, false}) {
    cairo_set_line_width(cr, halo ? std::max(2.5, 0.2 * f) : std::max(1.0, 0.08 * f));
    if (halo) {
      cairo_set_source_rgba(cr, 1, 1, 1, 0.6);
    } else {
      set_colour(cr, ink);
    }
    cairo_move_to(cr, tail.x(), tail.y());
    cairo_line_to(cr, base.x(), base.y());
    cairo_stroke(cr);
    cairo_move_to(cr, tip.x(), tip.y());
    cairo_line_to(cr, base.x() + 0.45 * head * n.x(), base.y() + 0.45 * head * n.y());
    cairo_line_to(cr, base.x() - 0.45 * head * n.x(), base.y() - 0.45 * head * n.y());
    cairo_close_path(cr);
    if (halo) {
      cairo_stroke(cr);
    } else {
      cairo_fill(cr);
    }
  }
}

double draw_arrows(cairo_t* cr, const Scene& scene, const FrameLayout& layout) {
  if (scene.u_x.empty()) return 0.0;
  const Mesh& mesh = *scene.mesh;
  const PointLocator locator(mesh);
  struct Sample {
    Vec2 pixel;  // [px]
    Vec2 u;      // [m/s]
  };
  std::vector<Sample> samples;
  const double h = scene.arrow_spacing;  // [px]
  const PixelBox& box = layout.plot;
  int hint = -1;
  // Sample points at pixel centres, so that a horizontal or vertical arrow is crisp.
  for (double y_row = box.y0 + 0.5 * h; y_row < box.y1; y_row += h) {
    const double y = std::floor(y_row) + 0.5;
    for (double x_column = box.x0 + 0.5 * h; x_column < box.x1; x_column += h) {
      const double x = std::floor(x_column) + 0.5;
      const Location where = locator.locate(layout.to_world({x, y}), hint);
      hint = where.element;
      if (!where.inside) continue;
      samples.push_back({{x, y}, interpolate_p2(mesh, where, scene.u_x, scene.u_y)});
    }
  }
  double u_ref = scene.arrow_reference_speed;  // [m/s]
  if (u_ref <= 0.0) {
    for (const Sample& s : samples) u_ref = std::max(u_ref, s.u.norm());
  }
  if (!(u_ref > 0.0)) return 0.0;
  cairo_save(cr);
  cairo_rectangle(cr, box.x0, box.y0, box.width(), box.height());
  cairo_clip(cr);
  for (const Sample& s : samples) {
    const double length = 0.9 * h * s.u.norm() / u_ref;  // [px]
    if (!(length >= 1.5)) continue;
    const Vec2 d = 0.5 * length * Vec2(s.u.x(), -s.u.y()).normalized();  // y down on the picture
    draw_arrow(cr, s.pixel - d, s.pixel + d, layout.font_size);
  }
  cairo_restore(cr);
  return u_ref;
}

}  // namespace flotsam
