#include "render/derived_fields.hpp"

#include <array>
#include <cmath>

#include "mesh/interpolation.hpp"

namespace flotsam {

std::vector<double> speed_field(std::span<const double> u_x, std::span<const double> u_y) {
  std::vector<double> speed(u_x.size());
  for (std::size_t k = 0; k < speed.size(); ++k) speed[k] = std::hypot(u_x[k], u_y[k]);
  return speed;
}

std::vector<double> vorticity_at_vertices(const Mesh& mesh, std::span<const double> u_x,
                                          std::span<const double> u_y) {
  std::vector<double> sum(mesh.vertex_count, 0.0);     // [m^2 / s]
  std::vector<double> weight(mesh.vertex_count, 0.0);  // [m^2]
  const std::array<Vec2, 3> corner_rs = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)};
  for (int e = 0; e < mesh.element_count(); ++e) {
    Location at;
    at.element = e;
    at.inside = true;
    at.curved = mesh.is_curved(e);
    for (int k = 0; k < 3; ++k) {
      at.r = corner_rs[k].x();
      at.s = corner_rs[k].y();
      const Mat2 grad = gradient_p2(mesh, at, u_x, u_y);  // grad(i, j) = d u_i / d x_j
      const int v = mesh.elements[e][k];
      sum[v] += mesh.area[e] * (grad(1, 0) - grad(0, 1));
      weight[v] += mesh.area[e];
    }
  }
  for (int v = 0; v < mesh.vertex_count; ++v) sum[v] /= weight[v];
  return sum;
}

}  // namespace flotsam
