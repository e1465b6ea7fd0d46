#pragma once
// Small Cairo helpers shared by the layers: ownership, colours, text placement.
#include <cairo.h>

#include <filesystem>
#include <memory>
#include <string>

#include "render/colour_map.hpp"

namespace flotsam {

struct CairoSurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct CairoContextDeleter {
  void operator()(cairo_t* c) const { cairo_destroy(c); }
};
using CairoSurface = std::unique_ptr<cairo_surface_t, CairoSurfaceDeleter>;
using CairoContext = std::unique_ptr<cairo_t, CairoContextDeleter>;

/// Writes the surface as a PNG under `path`.part and renames it when whole, so that a kill
/// leaves the previous picture or none, never a truncated one. Cairo's status, and
/// CAIRO_STATUS_WRITE_ERROR when the rename fails (the .part then removed).
inline cairo_status_t write_png_whole(cairo_surface_t* surface, const std::string& path) {
  const std::string part = path + ".part";
  cairo_status_t status = cairo_surface_write_to_png(surface, part.c_str());
  std::error_code error;
  if (status == CAIRO_STATUS_SUCCESS) std::filesystem::rename(part, path, error);
  if (status == CAIRO_STATUS_SUCCESS && error) status = CAIRO_STATUS_WRITE_ERROR;
  if (status != CAIRO_STATUS_SUCCESS && std::filesystem::is_regular_file(part, error))
    std::filesystem::remove(part, error);
  return status;
}

/// Colours of the machinery around the field.
inline constexpr Colour ink{30, 30, 30};             // text, outlines, arrows
inline constexpr Colour land{233, 229, 220};         // the plot outside the mesh
inline constexpr Colour wall_colour{64, 64, 64};     // banks and walls
inline constexpr Colour open_colour{30, 100, 230};   // inflow and outflow
inline constexpr Colour pier_colour{150, 150, 150};  // holes of the mesh: piers, islands

inline void set_colour(cairo_t* cr, const Colour& c, double alpha = 1.0) {
  cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, alpha);
}

enum class Align { left, centre, right };

/// Draws `text` with its baseline at y and its left end, centre or right end at x; returns its
/// advance width [px].
inline double draw_text(cairo_t* cr, double x, double y, const std::string& text,
                        Align align = Align::left) {
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  double start = x;
  if (align == Align::centre) start = x - 0.5 * extents.x_advance;
  if (align == Align::right) start = x - extents.x_advance;
  cairo_move_to(cr, start, y);
  cairo_show_text(cr, text.c_str());
  return extents.x_advance;
}

inline double text_width(cairo_t* cr, const std::string& text) {
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  return extents.x_advance;
}

inline void set_font(cairo_t* cr, double size, bool bold = false) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

}  // namespace flotsam
