#include "mesh/mesh_summary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "mesh/shape_functions.hpp"

namespace flotsam {

double p2_edge_length(const Vec2& a, const Vec2& b, const Vec2& m) {
  // x(t) = a t(t-1)/2 + b t(t+1)/2 + m (1-t^2), t in [-1, 1];
  // x'(t) = a (t - 1/2) + b (t + 1/2) - 2 t m; length = integral |x'(t)| dt, 5-point Gauss
  // (|x'| is constant for a straight edge with its mid node at the midpoint).
  static constexpr std::array<double, 5> t = {0.0, -0.5384693101056831, 0.5384693101056831,
                                              -0.9061798459386640, 0.9061798459386640};
  static constexpr std::array<double, 5> w = {0.5688888888888889, 0.4786286704993665,
                                              0.4786286704993665, 0.2369268850561891,
                                              0.2369268850561891};
  double length = 0;  // [m]
  for (std::size_t q = 0; q < t.size(); ++q)
    length += w[q] * (a * (t[q] - 0.5) + b * (t[q] + 0.5) - 2.0 * t[q] * m).norm();
  return length;
}

double p2_element_area(const Mesh& mesh, int element) {
  // det J of the P2 map is a quadratic polynomial in (r, s): the 3-point rule of degree 2 with
  // points (1/6, 1/6), (2/3, 1/6), (1/6, 2/3) and weights 1/6 integrates it exactly.
  static constexpr std::array<std::array<double, 2>, 3> points = {
      {{1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6}, {1.0 / 6, 2.0 / 3}}};
  const auto& el = mesh.elements[element];
  double area = 0;  // [m^2]
  for (const auto& [r, s] : points) {
    const P2Gradients dN = p2_reference_gradients(r, s);
    Mat2 J = Mat2::Zero();
    for (int k = 0; k < 6; ++k) J += mesh.nodes[el[k]] * dN[k].transpose();
    area += J.determinant() / 6.0;
  }
  return area;
}

double element_quality(const Mesh& mesh, int element) {
  const auto& el = mesh.elements[element];
  double sum_squares = 0;  // [m^2]
  for (int k = 0; k < 3; ++k)
    sum_squares += (mesh.nodes[el[(k + 1) % 3]] - mesh.nodes[el[k]]).squaredNorm();
  return 4.0 * std::sqrt(3.0) * mesh.area[element] / sum_squares;
}

MeshSummary summarize_mesh(const Mesh& mesh) {
  MeshSummary summary;
  summary.source = mesh.source;
  summary.node_count = mesh.node_count();
  summary.vertex_count = mesh.vertex_count;
  summary.element_count = mesh.element_count();
  for (const auto& name : mesh.group_names) summary.groups.push_back({name, 0, 0.0});
  for (const BoundaryEdge& edge : mesh.boundary) {
    const auto nodes = mesh.edge_nodes(edge.element, edge.local_edge);
    auto& group = summary.groups[edge.group];
    ++group.edge_count;
    group.length +=
        p2_edge_length(mesh.nodes[nodes[0]], mesh.nodes[nodes[1]], mesh.nodes[nodes[2]]);
  }
  if (mesh.element_count() == 0) return summary;
  summary.min_element_size = summary.min_quality = std::numeric_limits<double>::infinity();
  double quality_sum = 0;
  for (int e = 0; e < mesh.element_count(); ++e) {
    const auto& el = mesh.elements[e];
    double longest = 0;  // [m]
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, (mesh.nodes[el[(k + 1) % 3]] - mesh.nodes[el[k]]).norm());
    summary.min_element_size = std::min(summary.min_element_size, longest);
    summary.max_element_size = std::max(summary.max_element_size, longest);
    const double q = element_quality(mesh, e);
    summary.min_quality = std::min(summary.min_quality, q);
    quality_sum += q;
    summary.total_area += p2_element_area(mesh, e);
    if (mesh.is_curved(e)) ++summary.curved_element_count;
  }
  summary.mean_quality = quality_sum / mesh.element_count();
  summary.lower_corner = summary.upper_corner = mesh.nodes.front();
  for (const Vec2& p : mesh.nodes) {
    summary.lower_corner = summary.lower_corner.cwiseMin(p);
    summary.upper_corner = summary.upper_corner.cwiseMax(p);
  }
  return summary;
}

std::string format_mesh_summary(const MeshSummary& s) {
  std::string text;
  auto line = [&](const char* label, const std::string& value) {
    text += fmt::format("{:<14} {}\n", label, value);
  };
  line("mesh", s.source);
  line("nodes", fmt::format("{} ({} vertices, {} mid nodes)", s.node_count, s.vertex_count,
                            s.node_count - s.vertex_count));
  line("elements",
       fmt::format("{} six-node triangles ({} curved)", s.element_count, s.curved_element_count));
  line("area", fmt::format("{:.6g} m^2", s.total_area));
  line("extent", fmt::format("x {:.6g} .. {:.6g} m, y {:.6g} .. {:.6g} m", s.lower_corner.x(),
                             s.upper_corner.x(), s.lower_corner.y(), s.upper_corner.y()));
  line("element size",
       fmt::format("{:.4g} .. {:.4g} m (longest edge)", s.min_element_size, s.max_element_size));
  line("quality",
       fmt::format("min {:.3f}, mean {:.3f} (1 = equilateral)", s.min_quality, s.mean_quality));
  std::size_t width = 5;  // "group"
  for (const auto& g : s.groups) width = std::max(width, g.name.size());
  text += fmt::format("boundary groups\n  {:<{}}  {:>7}  {:>12}\n", "group", width, "edges",
                      "length [m]");
  for (const auto& g : s.groups)
    text += fmt::format("  {:<{}}  {:>7}  {:>12.6g}\n", g.name, width, g.edge_count, g.length);
  return text;
}

}  // namespace flotsam
