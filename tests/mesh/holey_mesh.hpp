#pragma once
// Test fixture shared by tests/mesh and bench/point_location.cpp: the rectangle [0, 12] x [0, 8] m
// of the structured grid (n cells per metre, criss-cross diagonals) with three holes cut out:
//
//   hole_1  the square [2, 4] x [2, 5]                              whole cells removed
//   hole_2  the diamond |x - 7| + |y - 4| < 1.6                      triangles whose centroid is
//           inside: a polygon with staircase and diagonal sides
//   hole_3  a U open upwards, [9, 11] x [2, 6] minus [9.5, 10.5] x [3, 6]   non-convex: its
//           pocket is part of the domain and lies behind the hole for a walk from below
//
// The outer sides keep their groups "left", "right", "bottom", "top"; the edges of hole k form
// the group "hole_k". n must be even (the U's walls are half a metre thick).
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "mesh/shape_functions.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam::fixtures {

/// Which hole (1, 2, 3) a point of the plane lies in, 0 for none (the fixture's geometry).
inline int holey_hole_of(const Vec2& x) {
  auto in_box = [&](double x0, double x1, double y0, double y1) {
    return x.x() > x0 && x.x() < x1 && x.y() > y0 && x.y() < y1;
  };
  if (in_box(2, 4, 2, 5)) return 1;
  if (std::abs(x.x() - 7) + std::abs(x.y() - 4) < 1.6) return 2;
  if (in_box(9, 11, 2, 6) && !in_box(9.5, 10.5, 3, 6.5)) return 3;
  return 0;
}

/// The fixture as plain lists for build_mesh: about 192 n^2 triangles.
inline RawMesh make_holey_raw(int cells_per_metre) {
  const int n = cells_per_metre;
  const RawMesh full =
      make_rectangle_raw({.length = 12.0, .width = 8.0, .nx = 12 * n, .ny = 8 * n});
  auto key = [](int a, int b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
  };

  // Triangles kept, and the hole that each edge of a removed triangle borders.
  std::vector<std::vector<int>> kept;
  std::unordered_map<std::uint64_t, int> hole_of_edge;
  std::unordered_map<std::uint64_t, int> use_count;
  for (const auto& tri : full.triangles) {
    const Vec2 centroid = (full.nodes[tri[0]] + full.nodes[tri[1]] + full.nodes[tri[2]]) / 3.0;
    const int hole = holey_hole_of(centroid);
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t edge = key(tri[k], tri[(k + 1) % 3]);
      if (hole > 0)
        hole_of_edge[edge] = hole;
      else
        ++use_count[edge];
    }
    if (hole == 0) kept.push_back(tri);
  }

  // Nodes renumbered over the kept triangles only.
  RawMesh raw;
  raw.source = "holey rectangle 12x8 m, " + std::to_string(n) + " cells per metre";
  std::vector<int> index(full.nodes.size(), -1);
  for (auto& tri : kept)
    for (int& v : tri) {
      if (index[v] < 0) {
        index[v] = static_cast<int>(raw.nodes.size());
        raw.nodes.push_back(full.nodes[v]);
      }
      v = index[v];
    }
  raw.triangles = kept;

  for (const auto& line : full.lines)  // the outer sides
    raw.lines.push_back({{index[line.nodes[0]], index[line.nodes[1]]}, line.group, 0});
  for (const auto& tri : full.triangles)  // edges once used, bordering a hole
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      const auto hole = hole_of_edge.find(key(a, b));
      const auto use = use_count.find(key(a, b));
      if (hole == hole_of_edge.end() || use == use_count.end() || use->second != 1) continue;
      raw.lines.push_back({{index[a], index[b]}, "hole_" + std::to_string(hole->second), 0});
      use->second = 0;  // once
    }
  return raw;
}

inline Mesh make_holey_mesh(int cells_per_metre) {
  return build_mesh(make_holey_raw(cells_per_metre));
}

}  // namespace flotsam::fixtures

namespace flotsam::fixtures {

/// The unit square of 4 x 4 cells (32 triangles) whose bottom edges are arcs of
/// circles: the mid node of the bottom edge over [i/4, (i+1)/4] is moved by the sagitta
/// 0.15 * 0.25 m off the straight edge, outwards (y < 0) for even i, inwards for odd i. The four
/// bottom elements are then curved (isoparametric P2), the others straight.
inline Mesh make_curved_square_mesh() {
  Mesh mesh = make_rectangle_mesh({.nx = 4, .ny = 4});
  const int bottom = mesh.find_group("bottom");
  for (const BoundaryEdge& edge : mesh.boundary) {
    if (edge.group != bottom) continue;
    const auto [a, b, m] = mesh.edge_nodes(edge.element, edge.local_edge);
    const Vec2 middle = 0.5 * (mesh.nodes[a] + mesh.nodes[b]);
    const int i = static_cast<int>(std::floor(middle.x() * 4));
    const double sagitta = 0.15 * (mesh.nodes[b] - mesh.nodes[a]).norm();  // [m]
    mesh.nodes[m] = middle + Vec2(0, i % 2 == 0 ? -sagitta : sagitta);
  }
  return mesh;
}

/// x(r, s) = sum_k X_k N_k(r, s): the point of reference coordinates (r, s) in an element.
inline Vec2 map_to_element(const Mesh& mesh, int element, double r, double s) {
  const auto& el = mesh.elements[element];
  const P2Values N = p2_values(r, s);
  Vec2 x = Vec2::Zero();
  for (int k = 0; k < 6; ++k) x += N[k] * mesh.nodes[el[k]];
  return x;
}

}  // namespace flotsam::fixtures
