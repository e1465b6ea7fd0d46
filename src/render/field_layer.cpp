#include "render/field_layer.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "render/cairo_draw.hpp"

namespace flotsam {
namespace {

std::uint32_t pack(const Colour& c) {
  return 0xff000000u | (std::uint32_t{c.r} << 16) | (std::uint32_t{c.g} << 8) | c.b;
}

/// Reference coordinates (r, s) of the six nodes, and the four sub-triangles by local node.
const std::array<Vec2, 6> node_rs = {Vec2(0, 0),   Vec2(1, 0),     Vec2(0, 1),
                                     Vec2(0.5, 0), Vec2(0.5, 0.5), Vec2(0, 0.5)};

struct ElementPaint {
  const Scene& scene;
  const FrameLayout& layout;
  double min, max;  // [field unit]
  PixelBuffer image;
  bool p2;  // the field has a value per node (else per vertex)

  double value(const std::array<int, 6>& el, double r, double s) const {
    const auto& f = scene.field.values;
    const double l0 = 1.0 - r - s, l1 = r, l2 = s;
    if (!p2) return l0 * f[el[0]] + l1 * f[el[1]] + l2 * f[el[2]];
    // P2 shape functions (mesh/shape_functions.hpp).
    return l0 * (2 * l0 - 1) * f[el[0]] + l1 * (2 * l1 - 1) * f[el[1]] +
           l2 * (2 * l2 - 1) * f[el[2]] + 4 * l0 * l1 * f[el[3]] + 4 * l1 * l2 * f[el[4]] +
           4 * l2 * l0 * f[el[5]];
  }

  // Pixels whose centre q lies in triangle (a, b, c) [px]: barycentric weights
  // w_a = cross(c - b, q - b) / cross(b - a, c - a), and so on, all >= -eps.
  void fill(const std::array<int, 6>& el, const std::array<Vec2, 6>& px, const int (&t)[3]) {
    const Vec2 &a = px[t[0]], &b = px[t[1]], &c = px[t[2]];
    const double area2 = cross(b - a, c - a);
    if (std::abs(area2) < 1e-12) return;
    const PixelBox& box = layout.plot;
    const int i0 = std::max(int(std::floor(std::min({a.x(), b.x(), c.x()}) - 0.5)), int(box.x0));
    const int i1 = std::min(int(std::ceil(std::max({a.x(), b.x(), c.x()}) - 0.5)), int(box.x1) - 1);
    const int j0 = std::max(int(std::floor(std::min({a.y(), b.y(), c.y()}) - 0.5)), int(box.y0));
    const int j1 = std::min(int(std::ceil(std::max({a.y(), b.y(), c.y()}) - 0.5)), int(box.y1) - 1);
    constexpr double eps = 1e-9;  // [-] pixel centres on a shared edge go to both sides
    const Vec2 &ra = node_rs[t[0]], &rb = node_rs[t[1]], &rc = node_rs[t[2]];
    for (int j = j0; j <= j1; ++j) {
      std::uint32_t* row = image.data + static_cast<std::ptrdiff_t>(j) * image.stride;
      for (int i = i0; i <= i1; ++i) {
        const Vec2 q(i + 0.5, j + 0.5);
        const double wa = cross(c - b, q - b) / area2;
        const double wb = cross(a - c, q - c) / area2;
        const double wc = 1.0 - wa - wb;
        if (wa < -eps || wb < -eps || wc < -eps) continue;
        const Vec2 rs = wa * ra + wb * rb + wc * rc;
        const double f = value(el, rs.x(), rs.y());
        row[i] = pack(colour_at(scene.colour_map, colour_coordinate(f, min, max)));
      }
    }
  }
};

}  // namespace

void draw_field(const Scene& scene, const FrameLayout& layout, double min, double max,
                PixelBuffer image) {
  const PixelBox& box = layout.plot;
  for (int j = int(box.y0); j < int(box.y1); ++j) {
    std::fill_n(image.data + static_cast<std::ptrdiff_t>(j) * image.stride + int(box.x0),
                int(box.width()), pack(land));
  }
  const Mesh& mesh = *scene.mesh;
  ElementPaint paint{
      scene, layout, min,
      max,   image,  scene.field.values.size() == static_cast<std::size_t>(mesh.node_count())};
  const std::vector<std::uint8_t>& wet = scene.wet;  // a sub-triangle dry at all three corners
                                                     // stays land
  std::array<Vec2, 6> px;
  for (int e = 0; e < mesh.element_count(); ++e) {
    const auto& el = mesh.elements[e];
    for (int k = 0; k < 6; ++k) px[k] = layout.to_pixel(mesh.nodes[el[k]]);
    double x_lo = px[0].x(), x_hi = x_lo, y_lo = px[0].y(), y_hi = y_lo;
    for (const Vec2& p : px) {
      x_lo = std::min(x_lo, p.x());
      x_hi = std::max(x_hi, p.x());
      y_lo = std::min(y_lo, p.y());
      y_hi = std::max(y_hi, p.y());
    }
    if (x_hi < box.x0 || x_lo > box.x1 || y_hi < box.y0 || y_lo > box.y1) continue;
    for (const auto& t : Mesh::sub_triangles)
      if (wet.empty() || wet[el[t[0]]] || wet[el[t[1]]] || wet[el[t[2]]]) paint.fill(el, px, t);
  }
}

}  // namespace flotsam
