#pragma once
// The generated channel the mesh, locator and sampling tests share: 200 m x 60 m with two
// circular piers (radius 10 m at (60, 30), 8 m at (140, 25)), far-field elements of 8 m refined
// to `pier_mesh_size` within 20 m of the piers. Gmsh's second-order mesh: the elements on the
// piers are curved, their mid nodes on the circles.
#include "mesh/geometry.hpp"

namespace flotsam::test {

inline MeshSource two_pier_channel(double pier_mesh_size = 2.0) {  // [m]
  MeshSource source;
  source.kind = MeshSource::Kind::channel;
  source.channel = {.length = 200,
                    .width = 60,
                    .piers = {{{60, 30}, 10}, {{140, 25}, 8}},
                    .mesh_size = 8,
                    .pier_mesh_size = pier_mesh_size,
                    .refine_distance = 20};
  return source;
}

}  // namespace flotsam::test
