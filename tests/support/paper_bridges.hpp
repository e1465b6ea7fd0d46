#pragma once
// The paper's channel (spec 8.2) as the jam statistics' tests see it: 1500 m x 170 m, two
// bridges at x = 600 and 900 m, each of two piers of radius 30 m centred at y = 42.5 and
// 127.5 m (gaps of 12.5, 25 and 12.5 m), the mesh's groups in the generator's order, and logs
// 1 m thick (density 600 kg/m^3) placed by hand.
#include <string>
#include <vector>

#include "bodies/body_set.hpp"
#include "core/constants.hpp"
#include "coupling/jam_statistics.hpp"

namespace flotsam::test {

// Mesh group indices of the channel's groups, in the generator's order.
inline const std::vector<std::string> channel_groups = {
    "inflow", "outflow", "bank_right", "bank_left", "pier_1", "pier_2", "pier_3", "pier_4"};
constexpr int bank_right = 2, bank_left = 3, pier_1 = 4, pier_2 = 5, pier_4 = 7;

inline ChannelGeometry paper_channel() {
  ChannelGeometry c;
  c.length = 1500.0;
  c.width = 170.0;
  c.piers = {
      {{600.0, 42.5}, 30.0}, {{600.0, 127.5}, 30.0}, {{900.0, 42.5}, 30.0}, {{900.0, 127.5}, 30.0}};
  return c;
}

inline JamGeometry paper_geometry() {
  return jam_geometry_from_channel(paper_channel(), channel_groups, "test mesh");
}

/// A log of length L and width 1 m with its centre at (x, y), turned by `angle` from the x axis.
inline void add_log(BodySet& bodies, double x, double y, double angle, double L) {
  BodySpec spec;
  spec.length = L;
  spec.width = 1.0;
  spec.height = 1.0;
  spec.position = Vec2(x, y);
  spec.angle = angle;
  bodies.add(spec);
}

/// Three logs against pier_1 (two 6 m across the flow, a 20 m one along it): they cover 10 m of
/// the 25 m gap between the piers.
inline BodySet three_logs_against_pier_1() {
  BodySet bodies;
  add_log(bodies, 575.0, 75.5, pi / 2.0, 6.0);
  add_log(bodies, 575.0, 79.5, pi / 2.0, 6.0);
  add_log(bodies, 566.0, 82.0, 0.0, 20.0);
  return bodies;
}

}  // namespace flotsam::test
