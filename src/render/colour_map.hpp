#pragma once
// Colour maps for fields (docs/rendering.md): a small table of control points, equally spaced
// on t in [0, 1], with linear interpolation in sRGB between neighbours.
//
//  * viridis (magnitudes: |u|, depth): matplotlib's viridis sampled at t = 0, 1/8, ..., 1:
//    #440154 #472d7b #3b528b #2c728e #21918c #28ae80 #5ec962 #addc30 #fde725.
//    Perceptually uniform, readable in grey and by colour-blind readers.
//  * blue_white_red (signed fields: vorticity, eta about a reference): ColorBrewer's RdBu with
//    nine classes, reversed so that negative is blue:
//    #2166ac #4393c3 #92c5de #d1e5f0 #f7f7f7 #fddbc7 #f4a582 #d6604d #b2182b; t = 1/2 is #f7f7f7.
#include <cstdint>
#include <span>

namespace flotsam {

struct Colour {
  std::uint8_t r = 0, g = 0, b = 0;  // sRGB [0, 255]
  bool operator==(const Colour&) const = default;
};

enum class ColourMapName : std::uint8_t { viridis, blue_white_red };

/// Drawn where the field has no value (NaN, e.g. a dry node).
inline constexpr Colour no_data_colour{200, 200, 200};

/// The control points of a map, at t = k / (n - 1).
std::span<const Colour> colour_map_control_points(ColourMapName map);

/// The map's colour at t; t is clamped to [0, 1]; NaN gives no_data_colour.
Colour colour_at(ColourMapName map, double t);

/// Where `value` sits in [min, max] as t = (value - min) / (max - min), unclamped.
inline double colour_coordinate(double value, double min, double max) {
  return (value - min) / (max - min);
}

}  // namespace flotsam
