#include "contact/jam_scene.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "core/constants.hpp"

namespace flotsam {

JamScene make_jam_scene(const JamSceneSpec& spec) {
  JamScene scene;
  constexpr double pier_spacing = 8.0;  // [m] centre to centre
  constexpr double first_pier = 6.0;    // [m] y of pier 0
  scene.pier_radius = 2.0;
  scene.channel_width = 2.0 * first_pier + pier_spacing * (spec.pier_count - 1);
  const double W = scene.channel_width;

  // Banks long enough for the rows upstream; the water is between them.
  // Two consecutive rows hold one log per gap between piers.
  const int rows = 2 * ((spec.log_count + spec.pier_count - 2) / (spec.pier_count - 1)) + 1;
  const double row_pitch = spec.log_width + spec.row_gap;  // [m]
  const double upstream = scene.pier_x - scene.pier_radius - 1.0 - rows * row_pitch - 10.0;
  const double downstream = scene.pier_x + 50.0;
  BoundarySegments& walls = scene.walls;
  walls.group_names = {"bank_right", "bank_left"};
  walls.add_segment({upstream, 0.0}, {downstream, 0.0}, 0);
  walls.add_segment({downstream, W}, {upstream, W}, 1);
  for (int j = 0; j < spec.pier_count; ++j) {
    walls.group_names.push_back("pier_" + std::to_string(j + 1));
    walls.add_circle_hole({scene.pier_x, first_pier + pier_spacing * j}, scene.pier_radius,
                          spec.pier_sides, 2 + j);
  }
  walls.build_grid(2.0 * scene.pier_radius);

  // Rows of logs across the flow, each log centred midway between piers j and j + 1 so that it
  // spans the gap and bears on both: row r holds the gaps j = r % 2, r % 2 + 2, ... (logs 16 m
  // apart, 6 m of free space between them); with two piers every row holds the one gap.
  std::mt19937 rng(spec.seed);
  std::uniform_real_distribution<double> jitter(-spec.angle_jitter, spec.angle_jitter);
  int placed = 0;
  for (int r = 0; placed < spec.log_count; ++r) {
    const double x = scene.pier_x - scene.pier_radius - 0.5 * spec.log_width - 0.5 - r * row_pitch;
    const int first_gap = spec.pier_count > 2 ? r % 2 : 0;
    for (int j = first_gap; j < spec.pier_count - 1 && placed < spec.log_count; j += 2) {
      const double y = first_pier + pier_spacing * (j + 0.5);  // [m]
      BodySpec body;
      body.length = spec.log_length;
      body.width = spec.log_width;
      body.position = {x, y};
      body.angle = 0.5 * pi + jitter(rng);
      scene.bodies.add(body);
      ++placed;
    }
  }
  return scene;
}

ContactConfig jam_contact_config() {
  ContactConfig config;
  config.restitution = 0.3;
  config.iterations = 200;
  config.position_iterations = 20;
  return config;
}

double move_jam_logs(JamScene& scene) {
  BodySet& b = scene.bodies;
  double dt = jam_max_step;
  for (int i = 0; i < b.size(); ++i) {
    const double speed = (b.velocity[i] + Vec2(jam_push * jam_max_step, 0.0)).norm() +
                         std::abs(b.angular_velocity[i]) * 0.5 * b.length[i];  // [m/s]
    if (speed > 0.0) dt = std::min(dt, 0.25 * b.width[i] / speed);
  }
  for (int i = 0; i < b.size(); ++i) {
    b.velocity[i].x() += jam_push * dt;
    b.position[i] += dt * b.velocity[i];
    b.angle[i] += dt * b.angular_velocity[i];
  }
  return dt;
}

}  // namespace flotsam
