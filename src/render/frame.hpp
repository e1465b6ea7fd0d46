#pragma once
// One picture of a scene (docs/rendering.md), drawn in this order: land and field
// (field_layer), piers and boundaries (boundary_layer), velocity arrows (arrow_layer), bodies
// (body_layer), colour bar (colour_bar), title, time stamp, scale bar and legend (annotations).
// The run calls it with its in-memory state at output times; `flotsam render` with what it
// read back from a run folder.
#include <cstdint>
#include <string>
#include <vector>

#include "render/colour_map.hpp"
#include "render/scene.hpp"

namespace flotsam {

/// A drawn picture in memory: opaque ARGB pixels (0xffRRGGBB), row after row, top row first.
struct Image {
  int width = 0, height = 0;        // [px]
  std::vector<std::uint32_t> argb;  // width * height pixels

  Colour at(int x, int y) const {
    const std::uint32_t p = argb[static_cast<std::size_t>(y) * width + x];
    return {static_cast<std::uint8_t>(p >> 16), static_cast<std::uint8_t>(p >> 8),
            static_cast<std::uint8_t>(p)};
  }
};

/// Draws the scene. Throws InputError for an invalid scene (validate_scene, frame_layout).
Image render_image(const Scene& scene);

/// Draws the scene into a PNG file of exactly scene.width x scene.height pixels. Throws
/// InputError naming `path` when it cannot be written.
void render_png(const Scene& scene, const std::string& path);

/// Frees Cairo's and fontconfig's static font caches. Call once at the end of a program that
/// drew pictures (after the last one), so that a sanitizer build's leak check sees only leaks of
/// our own.
void release_font_caches();

}  // namespace flotsam
