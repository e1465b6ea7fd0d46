// Verifies the paper's jam case (spec 8.2, paper section 6.2), shortened: in the paper's channel
// with its flow (two-way), logs carried onto the first bridge are stopped by the piers and rest
// against them: at least one log touches a pier, no log is inside a pier or across it, no two
// bodies overlap by more than 1% of a log's width, and the water balance closes to 1e-9.
// Reference: the contact conditions of spec 4.3 and the balance of spec 6.2.
#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "coupling/simulation.hpp"
#include "io/case_file.hpp"
#include "mesh/mesh_generator.hpp"
#include "mesh/point_locator.hpp"

namespace flotsam {
namespace {

TEST(LogsStopAtBridgePiers, ThePapersChannelShortened) {
  Case c = read_case(std::string(FLOTSAM_SOURCE_DIR) + "/examples/bridge_piers.yaml");
  c.time.end = 150.0;  // [s]
  c.time.step = 5.0;   // [s] flow step; the logs take their own RKF45 sub-steps
  c.bodies.bodies.clear();
  auto log = [&](double x, double y, double angle_deg) {
    BodySpec b;
    b.length = 20.0;
    b.width = 1.0;
    b.position = Vec2(x, y);
    b.angle = angle_deg * pi / 180.0;
    c.bodies.bodies.push_back(b);
  };
  log(555.0, 42.5, 90.0);   // broadside, just upstream of pier_1 (600, 42.5), r = 30 m
  log(550.0, 127.5, 80.0);  // nearly broadside in front of pier_2 (600, 127.5)
  log(530.0, 85.0, 0.0);    // along the flow, towards the gap between the piers
  log(520.0, 50.0, 90.0);   // behind the first: it will push on it
  Simulation s(
      c, generate_mesh(c.mesh),
      {.output_directory = {}, .overwrite = false, .write_output = false, .progress = false});
  s.run();

  const JamStatistics jams = s.jam_statistics();
  const Mesh& mesh = s.flow().mesh();
  int touching_piers = 0;
  for (int g = 0; g < static_cast<int>(mesh.group_names.size()); ++g)
    if (mesh.group_names[g].starts_with("pier")) touching_piers += jams.touching[g];
  EXPECT_GE(touching_piers, 1);

  // No log inside a pier or across it: points every metre along each log, and its corners, are
  // in the water (a pier is a hole in the mesh).
  const PointLocator locator(mesh);
  const BodySet& b = s.bodies();
  for (int i = 0; i < b.size(); ++i) {
    const Vec2 axis = b.axis(i), side = perp(axis) * 0.5 * b.width[i];
    for (int k = 0; k <= 20; ++k) {
      const Vec2 p = b.position[i] + (k / 20.0 - 0.5) * b.length[i] * axis;
      for (const Vec2& q : {Vec2(p + side), Vec2(p - side)})
        EXPECT_TRUE(locator.locate(q).inside) << "log " << b.id[i] << " at " << q.transpose();
    }
  }
  EXPECT_LE(s.contacts().profile().largest_overlap, 0.01 * 1.0);  // 1% of a log's width [m]
  EXPECT_LT(std::abs(s.flow().water_balance().relative_error()), 1e-9);
}

}  // namespace
}  // namespace flotsam
