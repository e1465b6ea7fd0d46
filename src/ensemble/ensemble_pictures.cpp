#include "ensemble/ensemble_pictures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "render/cairo_draw.hpp"
#include "render/colour_bar.hpp"

namespace flotsam {

namespace {

constexpr int picture_width = 1000;                                                         // [px]
constexpr int picture_height = 600;                                                         // [px]
constexpr double margin_left = 90, margin_right = 40, margin_top = 60, margin_bottom = 70;  // [px]

/// The plot area of a chart and its data ranges: data (x, y) -> pixels.
struct Axes {
  double x0, x1, y0, y1;  // data ranges
  double px(double x) const {
    const double span = x1 > x0 ? x1 - x0 : 1.0;
    return margin_left + (x - x0) / span * (picture_width - margin_left - margin_right);
  }
  double py(double y) const {
    const double span = y1 > y0 ? y1 - y0 : 1.0;
    return picture_height - margin_bottom -
           (y - y0) / span * (picture_height - margin_top - margin_bottom);
  }
};

struct Canvas {
  CairoSurface surface{
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, picture_width, picture_height)};
  CairoContext context{cairo_create(surface.get())};
  cairo_t* cr() const { return context.get(); }
  Canvas() {
    set_colour(cr(), {255, 255, 255});
    cairo_paint(cr());
  }
  void save(const std::string& path) const {
    cairo_surface_flush(surface.get());
    if (write_png_whole(surface.get(), path) != CAIRO_STATUS_SUCCESS)
      throw_run_error("could not write the picture '{}'", path);
  }
};

/// Frame, ticks at round values (about five per axis, as the colour bars'), labels and title of a
/// chart.
void draw_axes(cairo_t* cr, const Axes& a, const std::string& title, const std::string& x_label,
               const std::string& y_label) {
  set_colour(cr, ink);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, a.px(a.x0), a.py(a.y1), a.px(a.x1) - a.px(a.x0), a.py(a.y0) - a.py(a.y1));
  cairo_stroke(cr);
  set_font(cr, 13);
  const double x_step = nice_step(a.x1 - a.x0, 5), y_step = nice_step(a.y1 - a.y0, 5);
  for (const double x : nice_ticks(a.x0, a.x1)) {
    cairo_move_to(cr, a.px(x), a.py(a.y0));
    cairo_line_to(cr, a.px(x), a.py(a.y0) + 5);
    draw_text(cr, a.px(x), a.py(a.y0) + 20, format_tick(x, x_step), Align::centre);
  }
  for (const double y : nice_ticks(a.y0, a.y1)) {
    cairo_move_to(cr, a.px(a.x0) - 5, a.py(y));
    cairo_line_to(cr, a.px(a.x0), a.py(y));
    draw_text(cr, a.px(a.x0) - 8, a.py(y) + 4, format_tick(y, y_step), Align::right);
  }
  cairo_stroke(cr);
  draw_text(cr, 0.5 * (a.px(a.x0) + a.px(a.x1)), picture_height - 20, x_label, Align::centre);
  cairo_save(cr);
  cairo_translate(cr, 30, 0.5 * (a.py(a.y0) + a.py(a.y1)));
  cairo_rotate(cr, -M_PI / 2);
  draw_text(cr, 0, 0, y_label, Align::centre);
  cairo_restore(cr);
  set_font(cr, 16, true);
  draw_text(cr, picture_width / 2.0, 35, title, Align::centre);
}

const Colour series_colours[] = {{31, 119, 180}, {214, 39, 40}, {44, 160, 44}, {148, 103, 189}};

std::string blocking_probability_png(const std::string& directory, const EnsembleStatistics& s,
                                     const EnsembleConfig& config) {
  Canvas canvas;
  cairo_t* cr = canvas.cr();
  std::vector<double> xs;
  for (const SweepStatistics& sweep : s.sweep) xs.push_back(sweep.value);
  const auto [lo, hi] = std::minmax_element(xs.begin(), xs.end());
  const double pad = *hi > *lo ? 0.05 * (*hi - *lo) : 1.0;
  const Axes a{*lo - pad, *hi + pad, 0.0, 1.0};
  const std::string x_label =
      config.has_sweep
          ? fmt::format("{} [{}]", input_key(config.sweep_input), input_unit(config.sweep_input))
          : "(no sweep)";
  draw_axes(cr, a, "Blocking probability with 95% Wilson intervals", x_label,
            "probability of blocking [-]");
  const std::size_t targets = s.sweep.front().blocking.size();
  int series = 0;
  for (std::size_t t = 0; t < targets; ++t) {
    if (s.sweep.front().blocking[t].gap >= 0) continue;  // bridges only
    const Colour colour = series_colours[series % 4];
    set_colour(cr, colour);
    cairo_set_line_width(cr, 2.0);
    for (std::size_t k = 0; k < s.sweep.size(); ++k) {
      const Proportion& p = s.sweep[k].blocking[t].blocked;
      if (std::isnan(p.p)) continue;
      const double x = a.px(s.sweep[k].value);
      cairo_move_to(cr, x, a.py(p.lower));  // the interval bar with its caps
      cairo_line_to(cr, x, a.py(p.upper));
      for (double y : {p.lower, p.upper}) {
        cairo_move_to(cr, x - 6, a.py(y));
        cairo_line_to(cr, x + 6, a.py(y));
      }
      cairo_stroke(cr);
      cairo_arc(cr, x, a.py(p.p), 5, 0, 2 * M_PI);
      cairo_fill(cr);
    }
    set_font(cr, 13);
    draw_text(cr, a.px(a.x0) + 15, a.py(a.y1) + 20 + 18 * series,
              s.sweep.front().blocking[t].target);
    ++series;
  }
  const std::string path = directory + "/blocking_probability.png";
  canvas.save(path);
  return path;
}

std::string histogram_png(const std::string& path, const std::vector<double>& values, bool integers,
                          const std::string& title, const std::string& x_label) {
  Canvas canvas;
  cairo_t* cr = canvas.cr();
  double lo = *std::min_element(values.begin(), values.end());
  double hi = *std::max_element(values.begin(), values.end());
  int bins = 20;
  if (integers) {
    lo -= 0.5;
    hi += 0.5;
    bins = static_cast<int>(hi - lo);
  } else if (hi <= lo) {
    hi = lo + 1.0;
  }
  const std::vector<int> counts = histogram(values, lo, hi, bins);
  const int most = *std::max_element(counts.begin(), counts.end());
  const Axes a{lo, hi, 0.0, static_cast<double>(std::max(most, 1))};
  draw_axes(cr, a, title, x_label, "members");
  const double width = (hi - lo) / bins;
  for (int k = 0; k < bins; ++k) {
    const double x = lo + k * width;
    cairo_rectangle(cr, a.px(x) + 1, a.py(counts[k]), a.px(x + width) - a.px(x) - 2,
                    a.py(0) - a.py(counts[k]));
  }
  set_colour(cr, series_colours[0]);
  cairo_fill(cr);
  canvas.save(path);
  return path;
}

/// Stopping points (trapped or stranded bodies' G) of every member, counted in square cells of
/// 1/150 of the mesh's longer side, over the mesh (light grey triangles) and its boundary.
std::string stopping_points_png(const std::string& directory,
                                const std::vector<MemberResult>& results, const Mesh& mesh) {
  Canvas canvas;
  cairo_t* cr = canvas.cr();
  Vec2 lo = mesh.nodes.front(), hi = lo;
  for (const Vec2& p : mesh.nodes) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double top = 60, bottom = 60, side = 40;  // [px]
  const double scale = std::min((picture_width - 2 * side) / (hi.x() - lo.x()),
                                (picture_height - top - bottom) / (hi.y() - lo.y()));     // [px/m]
  const double rise = 0.5 * (picture_height - top - bottom - (hi.y() - lo.y()) * scale);  // [px]
  auto px = [&](const Vec2& p) {  // the mesh centred in the picture
    return Vec2{side + (p.x() - lo.x()) * scale,
                picture_height - bottom - rise - (p.y() - lo.y()) * scale};
  };
  set_colour(cr, {215, 230, 245});
  for (const auto& e : mesh.elements) {
    for (int k = 0; k < 3; ++k) {
      const Vec2 q = px(mesh.nodes[e[k]]);
      k == 0 ? cairo_move_to(cr, q.x(), q.y()) : cairo_line_to(cr, q.x(), q.y());
    }
    cairo_close_path(cr);
  }
  cairo_fill(cr);
  set_colour(cr, wall_colour);
  cairo_set_line_width(cr, 1.5);
  for (const BoundaryEdge& b : mesh.boundary) {
    const auto& e = mesh.elements[b.element];
    const Vec2 p = px(mesh.nodes[e[b.local_edge]]), q = px(mesh.nodes[e[(b.local_edge + 1) % 3]]);
    cairo_move_to(cr, p.x(), p.y());
    cairo_line_to(cr, q.x(), q.y());
  }
  cairo_stroke(cr);
  const double cell = std::max(hi.x() - lo.x(), hi.y() - lo.y()) / 150.0;  // [m]
  const int nx = static_cast<int>(std::ceil((hi.x() - lo.x()) / cell)) + 1;
  const int ny = static_cast<int>(std::ceil((hi.y() - lo.y()) / cell)) + 1;
  std::vector<int> count(static_cast<std::size_t>(nx * ny), 0);
  int stops = 0;
  for (const MemberResult& r : results)
    for (const BodyOutcome& b : r.bodies) {
      if (b.fate != BodyFate::trapped && b.fate != BodyFate::stranded) continue;
      const int i = std::clamp(static_cast<int>((b.end.x() - lo.x()) / cell), 0, nx - 1);
      const int j = std::clamp(static_cast<int>((b.end.y() - lo.y()) / cell), 0, ny - 1);
      ++count[static_cast<std::size_t>(j * nx + i)];
      ++stops;
    }
  const int most = std::max(1, *std::max_element(count.begin(), count.end()));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int c = count[static_cast<std::size_t>(j * nx + i)];
      if (c == 0) continue;
      set_colour(cr, colour_at(ColourMapName::viridis, static_cast<double>(c) / most));
      const Vec2 p = px({lo.x() + i * cell, lo.y() + (j + 1) * cell});
      cairo_rectangle(cr, p.x(), p.y(), std::max(2.0, cell * scale), std::max(2.0, cell * scale));
      cairo_fill(cr);
    }
  set_colour(cr, ink);
  set_font(cr, 16, true);
  draw_text(cr, picture_width / 2.0, 35,
            fmt::format("Where bodies stopped (trapped or stranded): {} stops in {} members", stops,
                        results.size()),
            Align::centre);
  set_font(cr, 13);
  draw_text(cr, picture_width / 2.0, picture_height - 20,
            fmt::format("stops per {:.3g} m cell: dark 1 to yellow {}", cell, most), Align::centre);
  const std::string path = directory + "/stopping_points.png";
  canvas.save(path);
  return path;
}

}  // namespace

std::vector<std::string> draw_ensemble_pictures(const std::string& directory,
                                                const std::vector<MemberResult>& results,
                                                const EnsembleStatistics& statistics,
                                                const EnsembleConfig& config, const Mesh& mesh) {
  std::vector<std::string> written;
  if (!statistics.sweep.empty() && !statistics.sweep.front().blocking.empty())
    written.push_back(blocking_probability_png(directory, statistics, config));
  std::vector<double> jam_size, rise;
  for (const MemberResult& r : results) {
    if (r.failed) continue;
    int largest = 0;
    double largest_rise = std::nan("");
    for (const BridgeOutcome& b : r.bridges) {
      largest = std::max(largest, b.largest_jam);
      if (!std::isnan(b.max_rise))
        largest_rise = std::isnan(largest_rise) ? b.max_rise : std::max(largest_rise, b.max_rise);
    }
    jam_size.push_back(largest);
    if (!std::isnan(largest_rise)) rise.push_back(largest_rise);
  }
  if (!jam_size.empty())
    written.push_back(histogram_png(directory + "/jam_size.png", jam_size, true,
                                    "Largest jam at a bridge, per member", "bodies in the jam"));
  if (!rise.empty())
    written.push_back(histogram_png(directory + "/backwater_rise.png", rise, false,
                                    "Largest backwater rise upstream of a bridge, per member",
                                    "backwater rise [m]"));
  written.push_back(stopping_points_png(directory, results, mesh));
  return written;
}

}  // namespace flotsam
