#pragma once
// Boundary conditions (spec 1.4) resolved on the mesh once at setup: which node carries which
// constraint. Per P2 node, the strongest condition wins: noslip > velocity > discharge > wall.
//   elevation: eta = eta_b(t) at the group's vertices (P1 Dirichlet); tangential velocity
//              u . t = 0 at the group's P2 nodes where water enters (u^n . n <= 0: an inflow
//              needs a second condition besides eta, without it the tangential velocity
//              entering is undetermined and grows), free where it leaves (an outflow takes one
//              condition; a second one there makes a boundary layer of the tangential velocity
//              when eddies leave), normal velocity free. At a node shared with another group,
//              the other wins.
//   discharge: u = -n U_i at the group's nodes, U_i = c sqrt(H_i) so that the unit discharge is
//              proportional to H^(3/2); c makes the discrete flux of term (10) equal Q(t).
//   velocity:  u = u_b(t).
//   wall:      slip u . n = 0 with n averaged from the adjacent wall edges (curved edges: the
//              exact normal of the P2 edge at the node); where two wall edges meet at a corner
//              sharper than corner_angle the node is held at u = 0.
//   noslip:    u = 0.
// Mesh groups the case does not name are walls. A group may carry an elevation together with a
// velocity or discharge (both imposed); any other pair is an error.
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "io/case.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

constexpr double corner_angle_deg = 30.0;  // [deg] wall normals further apart make a corner

struct ElevationNode {
  int vertex;     // P1 node
  int condition;  // index into FlowConfig::boundaries
  Vec2 outward;   // unit outward normal of the elevation boundary at the vertex
};

struct VelocityNode {
  enum class Kind { zero, velocity, discharge } kind;
  int node;                    // P2 node
  int condition = -1;          // index into FlowConfig::boundaries (velocity, discharge)
  Vec2 normal = Vec2::Zero();  // discharge: averaged outward normal of the group at the node
};

struct SlipNode {
  int node;
  Vec2 normal;  // unit direction in which the velocity is held at zero, u . normal = 0 [-]:
                // the outward normal on a wall, the tangent on an elevation boundary
  Vec2 outward = Vec2::Zero();  // elevation boundary: its outward normal; the tangent is held
                                // only where water enters (u^n . outward <= 0). Wall: zero
};

struct OpenEdge {
  int boundary_edge;  // index into Mesh::boundary
  int condition;      // discharge or velocity condition
};

struct BoundaryConditions {
  std::vector<int> group_condition;  // per mesh group: its velocity-kind condition (or elevation
                                     // alone), index into FlowConfig::boundaries; -1: wall
  std::vector<ElevationNode> elevation_nodes;
  std::vector<VelocityNode> velocity_nodes;
  std::vector<SlipNode> slip_nodes;
  std::vector<OpenEdge> open_edges;  // carry term (10) of the continuity equation
};

/// Checks the case's conditions against the mesh and resolves them. Throws InputError (naming
/// `case_file`, the group and the mesh) for a group absent from the mesh or a group given two
/// conditions (for instance a discharge on a group also declared a wall).
BoundaryConditions resolve_boundary_conditions(const Mesh& mesh, const FlowConfig& flow,
                                               const std::string& case_file);

const char* boundary_kind_name(BoundaryCondition::Kind kind);

}  // namespace flotsam
