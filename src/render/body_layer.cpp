#include "render/body_layer.hpp"

#include <algorithm>

#include "render/cairo_draw.hpp"

namespace flotsam {

Colour body_colour(BodyCategory category) {
  switch (category) {
    case BodyCategory::floating:
      return {222, 184, 135};
    case BodyCategory::grounded:
      return {160, 82, 45};
    case BodyCategory::jammed:
      return {220, 20, 60};
    case BodyCategory::gone:
      break;
  }
  return {150, 150, 150};
}

const char* body_category_name(BodyCategory category) {
  switch (category) {
    case BodyCategory::floating:
      return "floating";
    case BodyCategory::grounded:
      return "grounded";
    case BodyCategory::jammed:
      return "jammed";
    case BodyCategory::gone:
      break;
  }
  return "gone";
}

void draw_bodies(cairo_t* cr, const Scene& scene, const FrameLayout& layout) {
  const SceneBodies& bodies = scene.bodies;
  cairo_save(cr);
  cairo_rectangle(cr, layout.plot.x0, layout.plot.y0, layout.plot.width(), layout.plot.height());
  cairo_clip(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
  cairo_set_line_width(cr, std::clamp(0.08 * layout.font_size, 1.0, 2.0));
  const double s = layout.pixels_per_metre;  // [px/m]
  for (const bool gone_pass : {true, false}) {
    for (int i = 0; i < bodies.size(); ++i) {
      const bool gone = bodies.category[i] == BodyCategory::gone;
      if (gone != gone_pass) continue;
      // Corners x_G +- (L/2) a +- (l/2) perp(a); on the picture y points down, so the angle
      // turns the other way: a = (cos theta, -sin theta) in pixels.
      const Vec2 G = layout.to_pixel(bodies.position[i]);
      const Vec2 a(std::cos(bodies.angle[i]), -std::sin(bodies.angle[i]));
      const Vec2 n(a.y(), -a.x());
      const double half_L = 0.5 * std::max(bodies.length[i] * s, min_body_pixels);
      const double half_l = 0.5 * std::max(bodies.width[i] * s, min_body_pixels);
      const Vec2 corners[4] = {G + half_L * a + half_l * n, G - half_L * a + half_l * n,
                               G - half_L * a - half_l * n, G + half_L * a - half_l * n};
      cairo_move_to(cr, corners[0].x(), corners[0].y());
      for (int k = 1; k < 4; ++k) cairo_line_to(cr, corners[k].x(), corners[k].y());
      cairo_close_path(cr);
      set_colour(cr, body_colour(bodies.category[i]), gone ? 0.5 : 1.0);
      cairo_fill_preserve(cr);
      set_colour(cr, ink, gone ? 0.4 : 0.9);
      cairo_stroke(cr);
    }
  }
  cairo_restore(cr);
}

}  // namespace flotsam
