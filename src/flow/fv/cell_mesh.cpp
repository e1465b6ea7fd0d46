#include "flow/fv/cell_mesh.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace flotsam {

namespace {

std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b));
  const auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return hi << 32 | lo;
}

// Cell geometry: centroid, area, the Courant length 2 A / (3 l_max) (for an equilateral
// triangle its inradius; model.md "Time step").
void set_geometry(const Mesh& mesh, CellMesh& c, int i) {
  const Vec2& a = mesh.nodes[c.corners[i][0]];
  const Vec2& b = mesh.nodes[c.corners[i][1]];
  const Vec2& d = mesh.nodes[c.corners[i][2]];
  c.centroid[i] = (a + b + d) / 3.0;
  c.area[i] = 0.5 * cross(b - a, d - a);
  const double l_max = std::max({(b - a).norm(), (d - b).norm(), (a - d).norm()});
  c.length_scale[i] = 2.0 * c.area[i] / (3.0 * l_max);
}

// Least-squares weights: with d_k the offsets to the three neighbour centroids (a mirrored
// centroid across a boundary edge), grad phi minimises sum_k (d_k . g - dphi_k)^2, so
// g = M^-1 sum_k d_k dphi_k with M = sum_k d_k d_k^T, i.e. weight_k = M^-1 d_k.
void set_gradient_weights(CellMesh& c, int i) {
  std::array<Vec2, 3> d;
  Mat2 M = Mat2::Zero();
  for (int k = 0; k < 3; ++k) {
    const int j = c.neighbour[i][k];
    if (j >= 0) {
      d[k] = c.centroid[j] - c.centroid[i];
    } else {
      const Vec2& n = c.normal[c.cell_edges[i][k]];
      d[k] = 2.0 * c.to_edge[i][k].dot(n) * n;  // the centroid mirrored in the edge
    }
    M += d[k] * d[k].transpose();
  }
  const Mat2 M_inv = M.inverse();
  for (int k = 0; k < 3; ++k) c.gradient_weight[i][k] = M_inv * d[k];
}

}  // namespace

int CellMesh::sub_cell(int element, double r, double s) {
  const double l0 = 1.0 - r - s;  // barycentric coordinates (l0, r, s) of v0, v1, v2
  const int first = 4 * element;
  if (l0 >= 0.5) return first;
  if (r >= 0.5) return first + 1;
  if (s >= 0.5) return first + 2;
  return first + 3;
}

CellMesh build_cell_mesh(const Mesh& mesh, FvCells kind) {
  CellMesh c;
  c.kind = kind;
  const int per_element = kind == FvCells::split ? 4 : 1;
  const int n = per_element * mesh.element_count();
  c.cell_count = n;
  c.corners.resize(n);
  c.centroid.resize(n);
  c.area.resize(n);
  c.length_scale.resize(n);
  c.cell_edges.resize(n);
  c.cell_is_left.resize(n);
  c.to_edge.resize(n);
  c.gradient_weight.resize(n);
  c.neighbour.assign(n, {-1, -1, -1});
  for (int e = 0; e < mesh.element_count(); ++e)
    for (int q = 0; q < per_element; ++q) {
      const int i = per_element * e + q;
      for (int k = 0; k < 3; ++k)
        c.corners[i][k] = mesh.elements[e][per_element == 4 ? Mesh::sub_triangles[q][k] : k];
      set_geometry(mesh, c, i);
    }

  // Edges: the first cell to meet an edge is its left cell, the second its right.
  std::unordered_map<std::uint64_t, int> edge_of;
  edge_of.reserve(static_cast<std::size_t>(2 * n));
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      const int a = c.corners[i][k], b = c.corners[i][(k + 1) % 3];
      const auto [it, added] = edge_of.try_emplace(edge_key(a, b), c.edge_count);
      if (added) {
        const Vec2 t = mesh.nodes[b] - mesh.nodes[a];
        c.left.push_back(i);
        c.left_slot.push_back(k);
        c.right.push_back(-1);
        c.right_slot.push_back(-1);
        c.length.push_back(t.norm());
        c.normal.push_back(Vec2(t.y(), -t.x()) / t.norm());  // outward of a counter-clockwise cell
        c.group.push_back(-1);
        ++c.edge_count;
      } else {
        const int edge = it->second;
        c.right[edge] = i;
        c.right_slot[edge] = k;
        c.neighbour[i][k] = c.left[edge];
        c.neighbour[c.left[edge]][c.left_slot[edge]] = i;
      }
      c.cell_edges[i][k] = it->second;
      c.cell_is_left[i][k] = added;
      c.to_edge[i][k] = 0.5 * (mesh.nodes[a] + mesh.nodes[b]) - c.centroid[i];
    }

  // Boundary groups: a mesh boundary edge (local edge k of its element: vertex k, mid node 3+k,
  // vertex k+1) is one cell edge, or two when the elements are split.
  for (const BoundaryEdge& b : mesh.boundary) {
    const auto& el = mesh.elements[b.element];
    const int k = b.local_edge, v0 = el[k], mid = el[3 + k], v1 = el[(k + 1) % 3];
    const std::vector<std::array<int, 2>> ends =
        kind == FvCells::split ? std::vector<std::array<int, 2>>{{v0, mid}, {mid, v1}}
                               : std::vector<std::array<int, 2>>{{v0, v1}};
    for (const auto& end : ends) {
      const auto it = edge_of.find(edge_key(end[0], end[1]));
      if (it == edge_of.end() || c.right[it->second] >= 0)
        throw std::logic_error("build_cell_mesh: boundary edge of element " +
                               std::to_string(b.element) + " is not a cell boundary edge");
      c.group[it->second] = b.group;
    }
  }
  for (int edge = 0; edge < c.edge_count; ++edge)
    if (c.right[edge] < 0) {
      if (c.group[edge] < 0)
        throw std::logic_error("build_cell_mesh: a boundary cell edge has no boundary group");
      c.boundary_edges.push_back(edge);
    }
  for (int i = 0; i < n; ++i) set_gradient_weights(c, i);
  return c;
}

}  // namespace flotsam
