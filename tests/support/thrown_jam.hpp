#pragma once
// A jam scene (contact/jam_scene.hpp) whose logs are thrown about: velocities uniform in
// [-1, 1] m/s per component and spins in [-0.1, 0.1] rad/s, from a fixed seed, so that runs on
// different thread counts start alike.
#include <omp.h>

#include <algorithm>
#include <random>

#include "contact/contact_world.hpp"
#include "contact/jam_scene.hpp"

namespace flotsam::test {

inline JamScene thrown_jam_scene(int log_count, int pier_count, double row_gap /* [m] */) {
  JamSceneSpec spec;
  spec.log_count = log_count;
  spec.pier_count = pier_count;
  spec.row_gap = row_gap;
  JamScene scene = make_jam_scene(spec);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> speed(-1.0, 1.0);  // [m/s]
  for (int i = 0; i < scene.bodies.size(); ++i) {
    scene.bodies.velocity[i] = {speed(rng), speed(rng)};
    scene.bodies.angular_velocity[i] = 0.1 * speed(rng);  // [rad/s]
  }
  return scene;
}

/// `scene`'s bodies after `steps` contact steps with `config` on `threads` OpenMP threads, each
/// step pushed by move_jam_logs; `largest` is the largest `measure(world.profile())` of the steps.
template <class Measure>
BodySet stepped_on_threads(JamScene scene, const ContactConfig& config, int threads, int steps,
                           Measure measure, int& largest) {
  const int old_threads = omp_get_max_threads();
  omp_set_num_threads(threads);
  ContactWorld world(config);
  largest = 0;
  for (int step = 0; step < steps; ++step) {
    world.step(scene.bodies, scene.walls, move_jam_logs(scene));
    largest = std::max(largest, measure(world.profile()));
  }
  omp_set_num_threads(old_threads);
  return scene.bodies;
}

/// How many bodies of `one` and `two` differ in pose or velocity, compared exactly.
inline int count_different_states(const BodySet& one, const BodySet& two) {
  int differ = 0;
  for (int i = 0; i < one.size(); ++i)
    differ += one.position[i] != two.position[i] || one.angle[i] != two.angle[i] ||
              one.velocity[i] != two.velocity[i] ||
              one.angular_velocity[i] != two.angular_velocity[i];
  return differ;
}

}  // namespace flotsam::test
