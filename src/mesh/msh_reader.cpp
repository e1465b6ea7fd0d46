// Gmsh model -> RawMesh:
//
//   1. triangles: for every surface, its type-2 and type-9 elements; reoriented as a whole when
//      all of them run clockwise; any other surface element type is an error;
//   2. nodes: those the triangles use, in the file's node order;
//   3. lines: for every curve, its type-1 and type-8 elements, named after the curve's physical
//      group; lines whose end nodes are not triangle nodes are dropped.
#include "mesh/msh_reader.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <unordered_map>
#include <vector>

#include "core/error.hpp"
#include "mesh/gmsh_session.hpp"
#include "mesh/msh_check.hpp"

namespace flotsam {
namespace {

constexpr int gmsh_line2 = 1;      // 2-node line
constexpr int gmsh_triangle3 = 2;  // 3-node triangle
constexpr int gmsh_line3 = 8;      // 3-node line: end, end, mid
constexpr int gmsh_triangle6 = 9;  // 6-node triangle: v0 v1 v2 m01 m12 m20

struct GmshTriangles {
  std::vector<std::vector<std::size_t>> nodes;  // positions in the NodeTable
  std::vector<long> tags;
};

// Gmsh's nodes in tag order, found by tag (a binary search: tags need not be contiguous).
struct NodeTable {
  std::vector<std::size_t> tags;  // ascending
  std::vector<Vec2> xy;           // [m]
  std::vector<char> use;          // by position: 0 unused, 1 mid node, 2 vertex

  static constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::size_t find(std::size_t tag) const {
    const auto it = std::lower_bound(tags.begin(), tags.end(), tag);
    return it != tags.end() && *it == tag ? static_cast<std::size_t>(it - tags.begin()) : none;
  }
  std::size_t at(std::size_t tag, const std::string& source) const {
    const std::size_t k = find(tag);
    if (k == none)
      throw_input_error("{}: an element refers to node {}, which the file does not define", source,
                        tag);
    return k;
  }
};

NodeTable read_nodes() {
  std::vector<std::size_t> tags;
  std::vector<double> xyz, parametric;
  gmsh::model::mesh::getNodes(tags, xyz, parametric, -1, -1, false, false);
  std::vector<std::size_t> order(tags.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return tags[a] < tags[b]; });
  NodeTable table;
  table.tags.reserve(tags.size());
  table.xy.reserve(tags.size());
  for (std::size_t n : order) {
    if (!table.tags.empty() && table.tags.back() == tags[n]) continue;  // listed by two entities
    table.tags.push_back(tags[n]);
    table.xy.emplace_back(xyz[3 * n], xyz[3 * n + 1]);
  }
  table.use.assign(table.tags.size(), 0);
  return table;
}

// The triangles of one surface, their nodes found in the table; all reversed when all run
// clockwise.
void append_surface_triangles(int surface, const NodeTable& nodes, const std::string& source,
                              GmshTriangles& out) {
  GmshTriangles mine;
  for (int type : {gmsh_triangle3, gmsh_triangle6}) {
    std::vector<std::size_t> element_tags, node_tags;
    gmsh::model::mesh::getElementsByType(type, element_tags, node_tags, surface);
    const std::size_t per = type == gmsh_triangle3 ? 3 : 6;
    for (std::size_t e = 0; e < element_tags.size(); ++e) {
      std::vector<std::size_t> tri(per);
      for (std::size_t k = 0; k < per; ++k) tri[k] = nodes.at(node_tags[e * per + k], source);
      mine.nodes.push_back(std::move(tri));
      mine.tags.push_back(static_cast<long>(element_tags[e]));
    }
  }
  bool all_clockwise = !mine.nodes.empty();
  for (const auto& tri : mine.nodes) {
    const Vec2 &a = nodes.xy[tri[0]], &b = nodes.xy[tri[1]], &c = nodes.xy[tri[2]];
    if (cross(b - a, c - a) >= 0) {
      all_clockwise = false;
      break;
    }
  }
  for (std::size_t e = 0; e < mine.nodes.size(); ++e) {
    auto tri = mine.nodes[e];
    if (all_clockwise) {  // v0 v2 v1, mid nodes of edges 0-2, 2-1, 1-0
      std::swap(tri[1], tri[2]);
      if (tri.size() == 6) std::swap(tri[3], tri[5]);
    }
    out.nodes.push_back(std::move(tri));
    out.tags.push_back(mine.tags[e]);
  }
}

// Physical group name of each curve that belongs to one (the first group when several).
std::unordered_map<int, std::string> curve_group_names() {
  std::unordered_map<int, std::string> names;
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 1);
  for (const auto& [dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    if (name.empty()) name = std::to_string(tag);
    std::vector<int> curves;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, curves);
    for (int curve : curves) names.emplace(curve, name);
  }
  return names;
}

void check_surface_element_types(const std::string& source) {
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, 2);
  for (int type : types) {
    if (type == gmsh_triangle3 || type == gmsh_triangle6) continue;
    std::string name;
    int dim = 0, order = 0, node_count = 0, primary = 0;
    std::vector<double> local;
    gmsh::model::mesh::getElementProperties(type, name, dim, order, node_count, local, primary);
    throw_input_error(
        "{}: the mesh holds surface elements of Gmsh type {} ({}, {} nodes); flotsam reads only "
        "3-node and 6-node triangles",
        source, type, name, node_count);
  }
}

struct PendingLine {
  std::vector<std::size_t> nodes;  // Gmsh node tags: end, end, [mid]
  std::string group;
  long tag;
};

// 3. The lines of every curve whose end nodes are triangle vertices (NodeTable::use), with
// their group. A 3-node line keeps its mid node even if no triangle uses it (3-node triangles
// with 3-node boundary lines: the mid node is on the curve), so it is marked used.
std::vector<PendingLine> lines_on_triangles(NodeTable& nodes, const std::string& source) {
  std::vector<PendingLine> lines;
  const auto group_of_curve = curve_group_names();
  gmsh::vectorpair curves;
  gmsh::model::getEntities(curves, 1);
  for (const auto& curve : curves) {
    const auto found = group_of_curve.find(curve.second);
    const std::string group = found == group_of_curve.end() ? std::string() : found->second;
    for (int type : {gmsh_line2, gmsh_line3}) {
      std::vector<std::size_t> element_tags, node_tags;
      gmsh::model::mesh::getElementsByType(type, element_tags, node_tags, curve.second);
      const std::size_t per = type == gmsh_line2 ? 2 : 3;
      for (std::size_t e = 0; e < element_tags.size(); ++e) {
        PendingLine line{{node_tags.begin() + static_cast<std::ptrdiff_t>(e * per),
                          node_tags.begin() + static_cast<std::ptrdiff_t>((e + 1) * per)},
                         group,
                         static_cast<long>(element_tags[e])};
        const std::size_t a = nodes.find(line.nodes[0]), b = nodes.find(line.nodes[1]);
        if (a == NodeTable::none || b == NodeTable::none || nodes.use[a] != 2 || nodes.use[b] != 2)
          continue;
        if (per == 3) {
          char& mid = nodes.use[nodes.at(line.nodes[2], source)];
          mid = std::max(mid, char{1});
        }
        lines.push_back(std::move(line));
      }
    }
  }
  return lines;
}

RawMesh extract_raw_mesh(const std::string& source) {
  check_surface_element_types(source);
  NodeTable nodes = read_nodes();

  // 1. Triangles, surface by surface.
  GmshTriangles triangles;
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  for (const auto& surface : surfaces)
    append_surface_triangles(surface.second, nodes, source, triangles);
  if (triangles.nodes.empty())
    throw_input_error("{}: the mesh has no triangles (Gmsh element type 2 or 9)", source);

  // 2. The nodes the triangles and lines use, in tag order.
  RawMesh raw;
  raw.source = source;
  for (const auto& tri : triangles.nodes)
    for (std::size_t k = 0; k < tri.size(); ++k)
      nodes.use[tri[k]] = std::max(nodes.use[tri[k]], k < 3 ? char{2} : char{1});
  const std::vector<PendingLine> lines = lines_on_triangles(nodes, source);
  std::vector<int> index(nodes.tags.size(), -1);  // by position: index in raw.nodes
  for (std::size_t n = 0; n < nodes.tags.size(); ++n) {
    if (!nodes.use[n]) continue;
    index[n] = static_cast<int>(raw.nodes.size());
    raw.nodes.push_back(nodes.xy[n]);
    raw.node_tags.push_back(static_cast<long>(nodes.tags[n]));
  }
  raw.triangles.reserve(triangles.nodes.size());
  for (std::size_t t = 0; t < triangles.nodes.size(); ++t) {
    std::vector<int> tri;
    tri.reserve(triangles.nodes[t].size());
    for (std::size_t n : triangles.nodes[t]) tri.push_back(index[n]);
    raw.triangles.push_back(std::move(tri));
  }
  raw.triangle_tags = std::move(triangles.tags);
  for (const auto& line : lines) {
    RawMesh::Line raw_line;
    for (std::size_t tag : line.nodes) raw_line.nodes.push_back(index[nodes.at(tag, source)]);
    raw_line.group = line.group;
    raw_line.tag = line.tag;
    raw.lines.push_back(std::move(raw_line));
  }
  return raw;
}

}  // namespace

RawMesh raw_mesh_from_gmsh_model(const std::string& source) {
  try {
    return extract_raw_mesh(source);
  } catch (const InputError&) {
    throw;
  } catch (...) {
    throw_input_error("{}: Gmsh failed handing over the mesh: {}", source, current_gmsh_error());
  }
}

RawMesh read_msh_raw(const std::string& path) {
  check_msh(path);  // Gmsh 4.8 trusts the file's counts: only a checked file goes to it
  GmshSession session;
  try {
    gmsh::open(path);
  } catch (...) {
    throw_input_error("{}: Gmsh cannot read the mesh file: {}", path, current_gmsh_error());
  }
  return raw_mesh_from_gmsh_model(path);
}

Mesh read_msh(const std::string& path) {
  return build_mesh(read_msh_raw(path));
}

}  // namespace flotsam
