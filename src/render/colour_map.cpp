#include "render/colour_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace flotsam {
namespace {

constexpr std::array<Colour, 9> viridis = {{{0x44, 0x01, 0x54},
                                            {0x47, 0x2d, 0x7b},
                                            {0x3b, 0x52, 0x8b},
                                            {0x2c, 0x72, 0x8e},
                                            {0x21, 0x91, 0x8c},
                                            {0x28, 0xae, 0x80},
                                            {0x5e, 0xc9, 0x62},
                                            {0xad, 0xdc, 0x30},
                                            {0xfd, 0xe7, 0x25}}};

constexpr std::array<Colour, 9> blue_white_red = {{{0x21, 0x66, 0xac},
                                                   {0x43, 0x93, 0xc3},
                                                   {0x92, 0xc5, 0xde},
                                                   {0xd1, 0xe5, 0xf0},
                                                   {0xf7, 0xf7, 0xf7},
                                                   {0xfd, 0xdb, 0xc7},
                                                   {0xf4, 0xa5, 0x82},
                                                   {0xd6, 0x60, 0x4d},
                                                   {0xb2, 0x18, 0x2b}}};

std::uint8_t mix(std::uint8_t a, std::uint8_t b, double f) {
  return static_cast<std::uint8_t>(std::lround(a + f * (b - a)));
}

}  // namespace

std::span<const Colour> colour_map_control_points(ColourMapName map) {
  switch (map) {
    case ColourMapName::blue_white_red:
      return blue_white_red;
    case ColourMapName::viridis:
      break;
  }
  return viridis;
}

Colour colour_at(ColourMapName map, double t) {
  if (std::isnan(t)) return no_data_colour;
  const auto points = colour_map_control_points(map);
  const int last = static_cast<int>(points.size()) - 1;
  const double x = std::clamp(t, 0.0, 1.0) * last;  // position in the table
  const int k = std::min(static_cast<int>(x), last - 1);
  const double f = x - k;
  const Colour& a = points[k];
  const Colour& b = points[k + 1];
  return {mix(a.r, b.r, f), mix(a.g, b.g, f), mix(a.b, b.b, f)};
}

}  // namespace flotsam
