#include "mesh/curve_order.hpp"

#include <algorithm>
#include <array>
#include <numeric>

namespace flotsam {
namespace {

constexpr int grid_bits = 20;  // 2^20 cells a side: 1.4 mm on a 1.5 km mesh
constexpr std::uint32_t grid_last = (std::uint32_t{1} << grid_bits) - 1;

using Cell = std::array<std::uint32_t, 2>;

std::uint64_t curve_index(const Cell& c) {
  return hilbert_index(c[0], c[1], grid_bits);
}

}  // namespace

std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y, int bits) {
  // From the coarsest level down: the quadrant of (x, y) at this level adds its place along the
  // curve (0 lower left, 1 upper left, 2 upper right, 3 lower right) times the cells of a
  // quadrant; then (x, y) is turned into the frame in which that quadrant's curve starts at its
  // lower left corner and leaves it at the lower right.
  const std::uint32_t last = bits >= 32 ? ~std::uint32_t{0} : (std::uint32_t{1} << bits) - 1;
  std::uint64_t d = 0;
  for (int level = bits - 1; level >= 0; --level) {
    const std::uint32_t s = std::uint32_t{1} << level;
    const std::uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
    d += static_cast<std::uint64_t>(s) * s * ((3 * rx) ^ ry);
    if (ry == 0) {
      if (rx == 1) {
        x = last - x;
        y = last - y;
      }
      std::swap(x, y);
    }
  }
  return d;
}

std::vector<int> sorting_permutation(const std::vector<std::uint64_t>& keys) {
  std::vector<int> order(keys.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return keys[a] < keys[b]; });
  return order;
}

Mesh ordered_along_curve(const Mesh& mesh) {
  const int node_count = mesh.node_count(), element_count = mesh.element_count();
  const int vertex_count = mesh.vertex_count;
  if (node_count == 0) return mesh;

  // Cells of a grid over the bounding square (square, so that the curve's steps are as long
  // in x as in y), the box spanning 2^20 - 1/2 cells: a point on a simple fraction of the box
  // (the middle, a quarter, ...), where drawn geometry puts many, then lies inside a cell, not
  // on a border, so that a round-off in its coordinates (a mesh written to a file and read back,
  // a translated copy) keeps its cell.
  Vec2 lo = mesh.nodes.front(), hi = lo;
  for (const Vec2& p : mesh.nodes) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double box = std::max(hi.x() - lo.x(), hi.y() - lo.y());  // [m]
  const double cells_per_metre = box > 0 ? (grid_last + 0.5) / box : 0.0;
  std::vector<Cell> cell(node_count);
  for (int n = 0; n < node_count; ++n)
    for (int a = 0; a < 2; ++a) {
      const double x = (mesh.nodes[n][a] - lo[a]) * cells_per_metre;  // not a number: cell 0
      cell[n][a] = x >= 0.0 ? static_cast<std::uint32_t>(std::min(x, double{grid_last})) : 0;
    }

  // Nodes: vertices first, each group along the curve.
  std::vector<std::uint64_t> key(node_count);
  for (int n = 0; n < node_count; ++n) key[n] = curve_index(cell[n]);
  std::vector<int> node_order =
      sorting_permutation(std::vector<std::uint64_t>(key.begin(), key.begin() + vertex_count));
  const std::vector<int> mid_order =
      sorting_permutation(std::vector<std::uint64_t>(key.begin() + vertex_count, key.end()));
  for (int m : mid_order) node_order.push_back(vertex_count + m);

  // Elements: the cell of the mean of their vertices' cells (integers: the same on any machine).
  std::vector<std::uint64_t> element_key(element_count);
  for (int e = 0; e < element_count; ++e) {
    Cell mean{};
    for (int a = 0; a < 2; ++a) {
      std::uint64_t sum = 0;
      for (int k = 0; k < 3; ++k) sum += cell[mesh.elements[e][k]][a];
      mean[a] = static_cast<std::uint32_t>(sum / 3);
    }
    element_key[e] = curve_index(mean);
  }
  const std::vector<int> element_order = sorting_permutation(element_key);

  return renumbered(mesh, node_order, element_order);
}

Mesh renumbered(const Mesh& mesh, const std::vector<int>& node_order,
                const std::vector<int>& element_order) {
  const int node_count = mesh.node_count(), element_count = mesh.element_count();
  std::vector<int> new_node(node_count), new_element(element_count);
  for (int n = 0; n < node_count; ++n) new_node[node_order[n]] = n;
  for (int e = 0; e < element_count; ++e) new_element[element_order[e]] = e;
  Mesh out;
  out.source = mesh.source;
  out.vertex_count = mesh.vertex_count;
  out.group_names = mesh.group_names;
  out.nodes.resize(node_count);
  out.node_tags.resize(node_count);
  for (int n = 0; n < node_count; ++n) {
    out.nodes[n] = mesh.nodes[node_order[n]];
    out.node_tags[n] = mesh.node_tags[node_order[n]];
  }
  out.elements.resize(element_count);
  out.neighbours.resize(element_count);
  out.area.resize(element_count);
  out.element_tags.resize(element_count);
  out.boundary.reserve(mesh.boundary.size());
  for (int e = 0; e < element_count; ++e) {
    const int old = element_order[e];
    for (int k = 0; k < 6; ++k) out.elements[e][k] = new_node[mesh.elements[old][k]];
    out.area[e] = mesh.area[old];
    out.element_tags[e] = mesh.element_tags[old];
    for (int k = 0; k < 3; ++k) {  // boundary edges in the order of (element, local edge)
      const int across = mesh.neighbours[old][k];
      if (!Mesh::is_boundary(across)) {
        out.neighbours[e][k] = new_element[across];
        continue;
      }
      out.neighbours[e][k] = -(static_cast<int>(out.boundary.size()) + 1);
      out.boundary.push_back({e, k, mesh.boundary[Mesh::boundary_edge_of(across)].group});
    }
  }
  return out;
}

}  // namespace flotsam
