#pragma once
// The field as colours, pixel by pixel (docs/rendering.md).
//
// Each six-node element is cut into its four sub-triangles (corner, corner, corner and the
// middle one through the mid nodes), so a curved element follows its curved edges. A pixel
// whose centre falls in a sub-triangle gets its reference coordinates (r, s) by linear
// interpolation of the sub-triangle's corners' (r, s) -- exact on straight elements -- and the
// field's value there from the element's P2 (or P1) shape functions, mapped through the colour
// map. The picture therefore shows the finite-element field itself, not a linear blend of
// colours, and a pixel over a point x has exactly colour_at(map, t(f(x))).
#include <cstdint>

#include "render/frame_layout.hpp"
#include "render/scene.hpp"

namespace flotsam {

/// An ARGB32 image in memory (Cairo's layout: 0xAARRGGBB per pixel, rows `stride` pixels apart).
struct PixelBuffer {
  std::uint32_t* data = nullptr;
  int width = 0, height = 0;
  int stride = 0;  // [pixels] between rows
};

/// Paints the plot box: land colour, then every element's pixels coloured by the field between
/// `min` and `max` [field unit].
void draw_field(const Scene& scene, const FrameLayout& layout, double min, double max,
                PixelBuffer image);

}  // namespace flotsam
