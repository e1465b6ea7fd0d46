#pragma once
// Sampling finite-element fields at a located point (spec 4.4, 3: the flow seen by a body).
//
// A P1 field (elevation eta, bed z_b) holds vertex_count values, a P2 field (a velocity
// component) node_count() values, both in the mesh's vertex-first numbering. At a Location
// (element, r, s) from PointLocator:
//   f(p)      = sum_k f_k N_k(r, s)                           (N: shape_functions.hpp)
//   grad f(p) = J^-T sum_k f_k grad_rs N_k(r, s),   J = dx/d(r, s)
// with J the affine Jacobian of a straight element, or on a curved element the isoparametric
// J(r, s) = sum_k X_k grad_rs N_k^T of its six nodes; P1 fields on a curved element use the same
// map (P1 shape functions of (r, s)). Nothing here allocates; the location must be inside.
#include <span>

#include "core/vec.hpp"
#include "mesh/mesh.hpp"
#include "mesh/point_locator.hpp"

namespace flotsam {

/// dx/d(r, s) at the location [m]: affine, or isoparametric when location.curved.
Mat2 jacobian_at(const Mesh& mesh, const Location& location);

/// A scalar field: P1 (vertex_count values) or P2 (node_count() values), and its gradient
/// [field unit / m].
double interpolate_p1(const Mesh& mesh, const Location& location, std::span<const double> field);
double interpolate_p2(const Mesh& mesh, const Location& location, std::span<const double> field);
Vec2 gradient_p1(const Mesh& mesh, const Location& location, std::span<const double> field);
Vec2 gradient_p2(const Mesh& mesh, const Location& location, std::span<const double> field);

/// A vector field given by its components (u_x, u_y), and its gradient
/// grad(i, j) = d u_i / d x_j [field unit / m].
Vec2 interpolate_p1(const Mesh& mesh, const Location& location, std::span<const double> u_x,
                    std::span<const double> u_y);
Vec2 interpolate_p2(const Mesh& mesh, const Location& location, std::span<const double> u_x,
                    std::span<const double> u_y);
Mat2 gradient_p1(const Mesh& mesh, const Location& location, std::span<const double> u_x,
                 std::span<const double> u_y);
Mat2 gradient_p2(const Mesh& mesh, const Location& location, std::span<const double> u_x,
                 std::span<const double> u_y);

}  // namespace flotsam
