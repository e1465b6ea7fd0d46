#include "render/frame.hpp"

#include <dlfcn.h>

#include <cstring>

#include "core/error.hpp"
#include "render/annotations.hpp"
#include "render/arrow_layer.hpp"
#include "render/body_layer.hpp"
#include "render/boundary_layer.hpp"
#include "render/cairo_draw.hpp"
#include "render/colour_bar.hpp"
#include "render/field_layer.hpp"
#include "render/frame_layout.hpp"

namespace flotsam {
namespace {

CairoSurface draw_scene(const Scene& scene) {
  validate_scene(scene);
  const FrameLayout layout = frame_layout(scene);
  const auto [min, max] = resolve_colour_range(scene, layout.window);

  CairoSurface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, scene.width, scene.height));
  CairoContext context(cairo_create(surface.get()));
  cairo_t* cr = context.get();
  if (cairo_status(cr) != CAIRO_STATUS_SUCCESS) {
    throw_input_error("picture '{}': cannot make a {} x {} px image: {}", scene.title, scene.width,
                      scene.height, cairo_status_to_string(cairo_status(cr)));
  }
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);

  cairo_surface_flush(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get()) / 4;  // [pixels]
  auto* data = reinterpret_cast<std::uint32_t*>(cairo_image_surface_get_data(surface.get()));
  draw_field(scene, layout, min, max, {data, scene.width, scene.height, stride});
  cairo_surface_mark_dirty(surface.get());

  draw_boundaries(cr, scene, layout);
  const double u_ref = draw_arrows(cr, scene, layout);
  draw_bodies(cr, scene, layout);
  draw_colour_bar(cr, scene, layout, min, max);
  draw_header(cr, scene, layout);
  draw_footer(cr, scene, layout, u_ref);
  cairo_surface_flush(surface.get());
  return surface;
}

}  // namespace

Image render_image(const Scene& scene) {
  const CairoSurface surface = draw_scene(scene);
  Image image;
  image.width = scene.width;
  image.height = scene.height;
  image.argb.resize(static_cast<std::size_t>(scene.width) * scene.height);
  const int stride = cairo_image_surface_get_stride(surface.get());  // [bytes]
  const unsigned char* data = cairo_image_surface_get_data(surface.get());
  for (int y = 0; y < scene.height; ++y) {
    std::memcpy(&image.argb[static_cast<std::size_t>(y) * scene.width],
                data + static_cast<std::ptrdiff_t>(y) * stride, 4 * scene.width);
  }
  return image;
}

void render_png(const Scene& scene, const std::string& path) {
  const CairoSurface surface = draw_scene(scene);
  const cairo_status_t status = write_png_whole(surface.get(), path);
  if (status != CAIRO_STATUS_SUCCESS) {
    throw_input_error("cannot write the picture '{}': {} (does its folder exist, is it writable?)",
                      path, cairo_status_to_string(status));
  }
}

void release_font_caches() {
  cairo_debug_reset_static_data();
  // fontconfig comes with Cairo but is not linked directly: look FcFini up where it is loaded.
  if (void* fc_fini = dlsym(RTLD_DEFAULT, "FcFini")) reinterpret_cast<void (*)()>(fc_fini)();
}

}  // namespace flotsam
