#include "contact/sequential_impulses.hpp"

#include <algorithm>

namespace flotsam {
namespace {

// Threads pay off from a few hundred contacts (a parallel region costs a few microseconds).
bool in_parallel(const std::vector<ContactConstraint>& contacts, const Islands& islands) {
  constexpr std::size_t parallel_contacts = 256;  // [-]
  return contacts.size() >= parallel_contacts && islands.count() > 1;
}

}  // namespace

// The interval that brought the bodies here moved them with their velocities before the
// contacts acted; the impulses belong to the same interval, so the poses are moved on by h times
// the change of velocity (x_n+1 = x_n + h u_n+1, semi-implicit Euler). A resting jam pushed by a
// steady force then does not creep into its supports by F h^2 / m per interval. h must be the
// interval the bodies have just been moved over, not a longer step: the move would otherwise
// be too long by the ratio (and a bounce could carry a body through a wall).
// Each island is solved on its own, the islands in parallel (contact/islands.hpp).
int SequentialImpulses::solve(std::vector<ContactConstraint>& contacts, const Islands& islands,
                              BodySet& bodies, const SolverMasses& masses,
                              const std::vector<double>& intervals,
                              const BodyVelocities& /*start*/) {
  velocity_before_ = bodies.velocity;
  angular_velocity_before_ = bodies.angular_velocity;
  intervals_ = intervals;
  const std::vector<int>& order = islands.largest_first();
  const int count = islands.count();
  int sweeps = 0;
#pragma omp parallel for schedule(dynamic) reduction(max \
                                                     : sweeps) if (in_parallel(contacts, islands))
  for (int k = 0; k < count; ++k) {
    const std::span<ContactConstraint> island = islands.island(contacts, order[k]);
    sweeps = std::max(sweeps, solve_contact_island(island, bodies, masses, config_));
  }
  for (int i = 0; i < bodies.size(); ++i) {
    bodies.position[i] += intervals[i] * (bodies.velocity[i] - velocity_before_[i]);
    bodies.angle[i] += intervals[i] * (bodies.angular_velocity[i] - angular_velocity_before_[i]);
  }
  return sweeps;
}

void SequentialImpulses::undo(BodySet& bodies) {
  for (int i = 0; i < bodies.size(); ++i) {
    bodies.position[i] -= intervals_[i] * (bodies.velocity[i] - velocity_before_[i]);
    bodies.angle[i] -= intervals_[i] * (bodies.angular_velocity[i] - angular_velocity_before_[i]);
    bodies.velocity[i] = velocity_before_[i];
    bodies.angular_velocity[i] = angular_velocity_before_[i];
  }
}

// Each island stops its sweeps once its own overlaps are within the slop.
double SequentialImpulses::correct_positions(std::vector<ContactConstraint>& contacts,
                                             const Islands& islands, BodySet& bodies,
                                             const SolverMasses& masses) {
  const std::vector<int>& order = islands.largest_first();
  const int count = islands.count();
  double worst = 0.0;  // [m]
#pragma omp parallel for schedule(dynamic) reduction(max \
                                                     : worst) if (in_parallel(contacts, islands))
  for (int k = 0; k < count; ++k) {
    worst = std::max(worst, correct_contact_positions(islands.island(contacts, order[k]), bodies,
                                                      masses, config_));
  }
  return worst;
}

}  // namespace flotsam
