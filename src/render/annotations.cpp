#include "render/annotations.hpp"

#include <array>
#include <cmath>

#include <fmt/format.h>

#include "render/arrow_layer.hpp"
#include "render/body_layer.hpp"
#include "render/cairo_draw.hpp"

namespace flotsam {

double scale_bar_length(double target) {
  const double magnitude = std::pow(10.0, std::floor(std::log10(target)));
  const double r = target / magnitude;  // in [1, 10)
  return (r >= 5.0 ? 5.0 : r >= 2.0 ? 2.0 : 1.0) * magnitude;
}

std::string format_distance(double metres) {
  if (metres >= 1000.0) return fmt::format("{:g} km", metres / 1000.0);
  return fmt::format("{:g} m", metres);
}

void draw_header(cairo_t* cr, const Scene& scene, const FrameLayout& layout) {
  const double f = layout.font_size;
  const PixelBox& plot = layout.plot;
  set_colour(cr, ink);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, plot.x0 - 0.5, plot.y0 - 0.5, plot.width() + 1.0, plot.height() + 1.0);
  cairo_stroke(cr);
  const double baseline = layout.header.y1 - 0.55 * f;
  if (!scene.title.empty()) {
    set_font(cr, 1.1 * f, true);
    draw_text(cr, plot.x0, baseline, scene.title);
  }
  if (scene.time) {
    set_font(cr, f);
    draw_text(cr, plot.x1, baseline, "t = " + format_clock(*scene.time), Align::right);
  }
}

void draw_footer(cairo_t* cr, const Scene& scene, const FrameLayout& layout, double u_ref) {
  const double f = layout.font_size;
  const PixelBox& plot = layout.plot;
  const double middle = layout.footer.y0 + 1.2 * f;  // [px] the footer's centre line
  set_font(cr, 0.9 * f);

  // Scale bar: two halves, dark and light, and its length.
  const double metres = scale_bar_length(0.2 * plot.width() / layout.pixels_per_metre);
  const double length = metres * layout.pixels_per_metre;  // [px]
  const double bar_h = std::round(0.35 * f);
  const double x0 = plot.x0, y0 = std::round(middle - 0.5 * bar_h);
  cairo_set_line_width(cr, 1.0);
  set_colour(cr, ink);
  cairo_rectangle(cr, x0, y0, 0.5 * length, bar_h);
  cairo_fill(cr);
  cairo_rectangle(cr, x0 + 0.5, y0 + 0.5, length - 1.0, bar_h - 1.0);
  cairo_stroke(cr);
  double x = x0 + length + 0.5 * f;
  x += draw_text(cr, x, middle + 0.33 * f, format_distance(metres)) + 1.5 * f;

  // Legend: a swatch and a count for each category present.
  std::array<int, 4> count{};
  for (const BodyCategory c : scene.bodies.category) ++count[static_cast<int>(c)];
  for (int c = 0; c < 4; ++c) {
    if (count[c] == 0) continue;
    const auto category = static_cast<BodyCategory>(c);
    cairo_rectangle(cr, std::round(x) + 0.5, std::round(middle - 0.3 * f) + 0.5,
                    std::round(1.2 * f), std::round(0.6 * f));
    set_colour(cr, body_colour(category), category == BodyCategory::gone ? 0.5 : 1.0);
    cairo_fill_preserve(cr);
    set_colour(cr, ink);
    cairo_stroke(cr);
    x += 1.6 * f;
    x += draw_text(cr, x, middle + 0.33 * f,
                   fmt::format("{} {}", body_category_name(category), count[c])) +
         1.2 * f;
  }

  // Arrow key at the right: an arrow of the reference speed and its value.
  if (u_ref > 0.0) {
    const std::string label = fmt::format("{:.3g} m/s", u_ref);
    const double label_w = text_width(cr, label);
    const double arrow = 0.9 * scene.arrow_spacing;  // [px]
    const double tail = plot.x1 - label_w - 0.5 * f - arrow;
    draw_arrow(cr, {tail, middle}, {tail + arrow, middle}, f);
    set_colour(cr, ink);
    draw_text(cr, plot.x1, middle + 0.33 * f, label, Align::right);
  }
}

}  // namespace flotsam
