#include "mesh/structured_mesh.hpp"

#include <fmt/format.h>

namespace flotsam {

RawMesh make_rectangle_raw(const RectangleSpec& s) {
  RawMesh raw;
  raw.source = fmt::format("rectangle {}x{} m, {}x{} cells", s.length, s.width, s.nx, s.ny);
  auto id = [&](int i, int j) { return j * (s.nx + 1) + i; };
  for (int j = 0; j <= s.ny; ++j)
    for (int i = 0; i <= s.nx; ++i)
      raw.nodes.emplace_back(s.x0 + s.length * i / s.nx, s.y0 + s.width * j / s.ny);
  for (int j = 0; j < s.ny; ++j)
    for (int i = 0; i < s.nx; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (!s.alternate_diagonals || (i + j) % 2 == 0) {
        raw.triangles.push_back({a, b, c});
        raw.triangles.push_back({a, c, d});
      } else {
        raw.triangles.push_back({a, b, d});
        raw.triangles.push_back({b, c, d});
      }
    }
  for (int i = 0; i < s.nx; ++i) {
    raw.lines.push_back({{id(i, 0), id(i + 1, 0)}, "bottom", 0});
    raw.lines.push_back({{id(i, s.ny), id(i + 1, s.ny)}, "top", 0});
  }
  for (int j = 0; j < s.ny; ++j) {
    raw.lines.push_back({{id(0, j), id(0, j + 1)}, "left", 0});
    raw.lines.push_back({{id(s.nx, j), id(s.nx, j + 1)}, "right", 0});
  }
  return raw;
}

Mesh make_rectangle_mesh(const RectangleSpec& spec) {
  return build_mesh(make_rectangle_raw(spec));
}

}  // namespace flotsam
