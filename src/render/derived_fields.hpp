#pragma once
// Fields worth a picture that the solver does not keep: speed and vorticity from the P2
// velocity (u_x, u_y) [m/s].
#include <span>
#include <vector>

#include "mesh/mesh.hpp"

namespace flotsam {

/// |u| = sqrt(u_x^2 + u_y^2) at every node [m/s] (a P2 field).
std::vector<double> speed_field(std::span<const double> u_x, std::span<const double> u_y);

/// Vorticity omega = d u_y / dx - d u_x / dy at every vertex [1/s] (a P1 field): the P2
/// velocity's gradient at the vertex (mesh/interpolation.hpp), averaged over the elements
/// around it with their areas as weights (the gradient jumps between elements).
std::vector<double> vorticity_at_vertices(const Mesh& mesh, std::span<const double> u_x,
                                          std::span<const double> u_y);

}  // namespace flotsam
