#include "render/colour_bar.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "render/cairo_draw.hpp"

namespace flotsam {

double nice_step(double span, int target_count) {
  const double raw = span / std::max(target_count, 1);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double r = raw / magnitude;  // in [1, 10)
  const double unit = r < 1.5 ? 1.0 : r < 3.0 ? 2.0 : r < 7.0 ? 5.0 : 10.0;
  return unit * magnitude;
}

std::vector<double> nice_ticks(double min, double max, int target_count) {
  std::vector<double> ticks;
  if (!(max > min)) return ticks;
  const double step = nice_step(max - min, target_count);
  const double tolerance = 1e-9 * step;
  for (double k = std::ceil((min - tolerance) / step); k * step <= max + tolerance; k += 1.0) {
    ticks.push_back(k == 0.0 ? 0.0 : k * step);  // no "-0"
  }
  return ticks;
}

std::string format_tick(double value, double step) {
  if (value == 0.0) return "0";
  const double largest = std::max(std::abs(value), step);
  if (largest >= 1e5 || step < 1e-4) return fmt::format("{:.3g}", value);
  const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
  return fmt::format("{:.{}f}", value, decimals);
}

void draw_colour_bar(cairo_t* cr, const Scene& scene, const FrameLayout& layout, double min,
                     double max) {
  const PixelBox& bar = layout.colour_bar;
  const double f = layout.font_size;
  cairo_save(cr);
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
  const int rows = static_cast<int>(bar.height());
  for (int row = 0; row < rows; ++row) {
    const double t = 1.0 - (row + 0.5) / rows;  // top row: max
    set_colour(cr, colour_at(scene.colour_map, t));
    cairo_rectangle(cr, bar.x0, bar.y0 + row, bar.width(), 1.0);
    cairo_fill(cr);
  }
  cairo_restore(cr);

  set_colour(cr, ink);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, bar.x0 + 0.5, bar.y0 + 0.5, bar.width() - 1.0, bar.height() - 1.0);
  cairo_stroke(cr);

  set_font(cr, 0.85 * f);
  const int target = std::clamp(static_cast<int>(bar.height() / (2.2 * f)), 2, 6);
  const auto ticks = nice_ticks(min, max, target);
  const double step = nice_step(max - min, target);
  double widest = 0.0;  // [px] of the tick labels
  for (const double v : ticks) {
    const double y = std::round(bar.y1 - (v - min) / (max - min) * bar.height()) + 0.5;
    cairo_move_to(cr, bar.x1, y);
    cairo_line_to(cr, bar.x1 + 0.3 * f, y);
    cairo_stroke(cr);
    widest = std::max(widest, draw_text(cr, bar.x1 + 0.45 * f, y + 0.3 * f, format_tick(v, step)));
  }

  std::string label = scene.field.name;
  if (!scene.field.unit.empty()) label += " [" + scene.field.unit + "]";
  if (label.empty()) return;
  set_font(cr, 0.9 * f);
  cairo_save(cr);
  cairo_translate(cr, bar.x1 + 0.45 * f + widest + 1.2 * f, 0.5 * (bar.y0 + bar.y1));
  cairo_rotate(cr, -M_PI / 2);  // reads upwards
  draw_text(cr, 0.0, 0.0, label, Align::centre);
  cairo_restore(cr);
}

}  // namespace flotsam
