#include "flow/fem/boundary_conditions.hpp"

#include <cmath>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "flow/fem/element_values.hpp"

namespace flotsam {

const char* boundary_kind_name(BoundaryCondition::Kind kind) {
  switch (kind) {
    case BoundaryCondition::Kind::elevation:
      return "elevation";
    case BoundaryCondition::Kind::discharge:
      return "discharge";
    case BoundaryCondition::Kind::velocity:
      return "velocity";
    case BoundaryCondition::Kind::wall:
      return "wall";
    case BoundaryCondition::Kind::noslip:
      return "noslip";
    case BoundaryCondition::Kind::free:
      return "free";
  }
  return "?";
}

namespace {

using Kind = BoundaryCondition::Kind;

std::string group_list(const Mesh& mesh) {
  std::string list;
  for (const auto& name : mesh.group_names) list += (list.empty() ? "" : ", ") + name;
  return list;
}

// Rank of a velocity condition at a node: the strongest wins.
int rank(Kind kind) {
  switch (kind) {
    case Kind::noslip:
      return 4;
    case Kind::velocity:
      return 3;
    case Kind::discharge:
      return 2;
    case Kind::wall:
      return 1;
    case Kind::elevation:
    case Kind::free:  // rejected by resolve_boundary_conditions
      return 0;
  }
  return 0;
}

}  // namespace

BoundaryConditions resolve_boundary_conditions(const Mesh& mesh, const FlowConfig& flow,
                                               const std::string& case_file) {
  BoundaryConditions bc;
  const std::string where = case_file.empty() ? "case" : case_file;
  bc.group_condition.assign(mesh.group_names.size(), -1);
  std::vector<int> group_elevation(mesh.group_names.size(), -1);
  for (int i = 0; i < static_cast<int>(flow.boundaries.size()); ++i) {
    const auto& c = flow.boundaries[i];
    if (c.kind == Kind::free) {
      const std::string at = c.line > 0 ? fmt::format("{}:{}", where, c.line) : where;
      throw_input_error(
          "{}: flow.boundaries.{}: type 'free' is supported by 'engine: fv' only; the FEM engine "
          "takes elevation, discharge, velocity, wall or noslip",
          at, c.group);
    }
    const int g = mesh.find_group(c.group);
    if (g < 0)
      throw_input_error(
          "{}: flow boundary {} ('{}', {}): group '{}' is not a boundary group of "
          "the mesh {} (its groups: {})",
          where, i + 1, c.group, boundary_kind_name(c.kind), c.group, mesh.source,
          group_list(mesh));
    const bool elevation = c.kind == Kind::elevation;
    const bool velocity_like = c.kind == Kind::velocity || c.kind == Kind::discharge;
    const int current = bc.group_condition[g];
    const bool current_is_elevation = current >= 0 && current == group_elevation[g];
    const bool current_is_velocity_like =
        current >= 0 && (flow.boundaries[current].kind == Kind::velocity ||
                         flow.boundaries[current].kind == Kind::discharge);
    // Allowed pairs on one group: elevation with velocity or discharge (both imposed).
    const bool pair = (elevation && group_elevation[g] < 0 && current_is_velocity_like) ||
                      (velocity_like && current_is_elevation);
    if (current >= 0 && !pair) {
      const auto& first = flow.boundaries[current];
      throw_input_error(
          "{}: flow boundaries: group '{}' is given two conditions, {} and {}; "
          "expected one per group (or an elevation with a velocity or discharge)",
          where, c.group, boundary_kind_name(first.kind), boundary_kind_name(c.kind));
    }
    if (elevation) group_elevation[g] = i;
    if (!(elevation && pair)) bc.group_condition[g] = i;
  }
  auto kind_of_group = [&](int g) {
    const int c = bc.group_condition[g];
    return c < 0 ? Kind::wall : flow.boundaries[c].kind;
  };

  // Per node: the strongest velocity condition, its normals (wall and discharge kept apart).
  const int n_nodes = mesh.node_count();
  std::vector<int> best_rank(n_nodes, 0), best_condition(n_nodes, -1);
  std::vector<std::vector<Vec2>> wall_normals(n_nodes);
  std::vector<Vec2> discharge_normal(n_nodes, Vec2::Zero());
  std::vector<Vec2> elevation_normal(n_nodes, Vec2::Zero());
  std::vector<int> elevation_condition(mesh.vertex_count, -1);
  for (int b = 0; b < static_cast<int>(mesh.boundary.size()); ++b) {
    const auto& edge = mesh.boundary[b];
    const Kind kind = kind_of_group(edge.group);
    const int condition = bc.group_condition[edge.group];
    const auto nodes = mesh.edge_nodes(edge.element, edge.local_edge);
    const double xi[3] = {0.0, 1.0, 0.5};
    if (group_elevation[edge.group] >= 0)
      for (int k = 0; k < 2; ++k) elevation_condition[nodes[k]] = group_elevation[edge.group];
    if (kind == Kind::elevation) {
      for (int k = 0; k < 2; ++k) elevation_condition[nodes[k]] = condition;
      for (int k = 0; k < 3; ++k) elevation_normal[nodes[k]] += edge_normal(mesh, edge, xi[k]);
      continue;
    }
    if (kind == Kind::discharge || kind == Kind::velocity) bc.open_edges.push_back({b, condition});
    for (int k = 0; k < 3; ++k) {
      const int node = nodes[k];
      const Vec2 n = edge_normal(mesh, edge, xi[k]);
      if (kind == Kind::wall) wall_normals[node].push_back(n);
      if (kind == Kind::discharge) discharge_normal[node] += n;
      if (rank(kind) > best_rank[node]) {
        best_rank[node] = rank(kind);
        best_condition[node] = condition;
      }
    }
  }
  for (int v = 0; v < mesh.vertex_count; ++v)
    if (elevation_condition[v] >= 0)
      bc.elevation_nodes.push_back({v, elevation_condition[v], elevation_normal[v].normalized()});

  const double corner_cos = std::cos(corner_angle_deg * pi / 180.0);
  for (int node = 0; node < n_nodes; ++node) {
    switch (best_rank[node]) {
      case 4:
        bc.velocity_nodes.push_back(
            {VelocityNode::Kind::zero, node, best_condition[node], Vec2::Zero()});
        break;
      case 3:
        bc.velocity_nodes.push_back(
            {VelocityNode::Kind::velocity, node, best_condition[node], Vec2::Zero()});
        break;
      case 2:
        bc.velocity_nodes.push_back({VelocityNode::Kind::discharge, node, best_condition[node],
                                     discharge_normal[node].normalized()});
        break;
      case 1: {
        const auto& normals = wall_normals[node];
        Vec2 sum = Vec2::Zero();
        bool corner = false;
        for (const Vec2& n : normals) {
          sum += n;
          corner = corner || n.dot(normals.front()) < corner_cos;
        }
        if (corner)
          bc.velocity_nodes.push_back({VelocityNode::Kind::zero, node, -1, Vec2::Zero()});
        else
          bc.slip_nodes.push_back({node, sum.normalized()});
        break;
      }
      default:
        // Elevation boundary only: no tangential velocity where water enters, u . t = 0 (the
        // direction held at zero is the tangent t = k x n; the normal velocity stays free;
        // ShallowWaterSolver::apply_boundary_conditions frees u . t where water leaves).
        if (elevation_normal[node] != Vec2::Zero()) {
          const Vec2 n = elevation_normal[node].normalized();
          bc.slip_nodes.push_back({node, Vec2(-n.y(), n.x()), n});
        }
        break;
    }
  }
  return bc;
}

}  // namespace flotsam
