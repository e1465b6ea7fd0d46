#pragma once
// The graded channel of the finite-volume well-balancing and local time stepping cases: 100 m x
// 40 m, two piers of radius 3 m across the middle, 3 m cells refined to 1.5 m within 10 m of the
// piers (Gmsh), over a bed with bumps up to 0.7 m and an island rising to 1.6 m.
#include "io/case.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_generator.hpp"

namespace flotsam::test {

inline const Mesh& island_channel_mesh() {
  static const Mesh mesh = [] {
    ChannelGeometry channel;
    channel.length = 100.0;
    channel.width = 40.0;
    channel.piers = {{Vec2(50.0, 13.0), 3.0}, {Vec2(50.0, 27.0), 3.0}};
    channel.mesh_size = 3.0;
    channel.pier_mesh_size = 1.5;
    channel.refine_distance = 10.0;
    return build_mesh(generate_channel_mesh(channel));
  }();
  return mesh;
}

inline void set_island_bed(Case& c) {
  c.bed.kind = BedConfig::Kind::expression;
  c.bed.expression = Expression(
      "0.3 * sin(0.2 * x) * cos(0.25 * y) + 0.4 * exp(-((x - 30)^2 + (y - 20)^2) / 20)"
      " + 1.6 * exp(-((x - 75)^2 + (y - 20)^2) / 60)",
      "bumpy bed with an island");
}

}  // namespace flotsam::test
