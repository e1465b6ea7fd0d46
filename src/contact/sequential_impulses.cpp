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
// contacts acted; the impulses belong to the same interval, so the poses of the bodies a contact
// pushed are put where the interval started moved on by h times the new velocity (x_1 = x_0 +
// h u_1, semi-implicit Euler, as Box2D); a body whose contacts carry no impulse (a gap within the
// detection margin) keeps the pose its RKF45 sub-steps gave it. The targets were set for that move
// (prepare_contacts: a gap's separation at the interval's start): a body held against a face stays
// there (moving it on by h (u_1 - u^-), the change of velocity alone, backed it off by F h^2 / 2m,
// the part of the free move the steady force made, and took it out of contact one interval in
// three), and a resting jam does not creep into its supports. h must be the interval the bodies
// have just been moved over. Each island is solved on its own, the islands in parallel
// (contact/islands.hpp).
int SequentialImpulses::solve(std::vector<ContactConstraint>& contacts, const Islands& islands,
                              BodySet& bodies, const SolverMasses& masses,
                              const std::vector<double>& intervals, const BodyVelocities& /*start*/,
                              const BodyPoses& start_pose) {
  // The bodies of the contacts: the only ones whose velocities the solve changes.
  const auto n = static_cast<std::size_t>(bodies.size());
  touched_.resize(n, 0);
  for (const int i : moved_) touched_[i] = 0;
  moved_.clear();
  for (const ContactConstraint& c : contacts) {
    for (const int i : {c.a, c.b}) {
      if (i < 0 || touched_[i]) continue;
      touched_[i] = 1;
      moved_.push_back(i);
    }
  }
  velocity_before_.resize(n), angular_velocity_before_.resize(n), pushed_.resize(n, 0);
  pose_before_.position.resize(n), pose_before_.angle.resize(n);
  for (const int i : moved_) {
    velocity_before_[i] = bodies.velocity[i];
    angular_velocity_before_[i] = bodies.angular_velocity[i];
    pose_before_.position[i] = bodies.position[i];
    pose_before_.angle[i] = bodies.angle[i];
  }
  const std::vector<int>& order = islands.largest_first();
  const int count = islands.count();
  auto solve_island = [&](int k) {
    return solve_contact_island(islands.island(contacts, order[k]), bodies, masses, config_);
  };
  int sweeps = 0;
  if (in_parallel(contacts, islands)) {
#pragma omp parallel for schedule(dynamic) reduction(max : sweeps)
    for (int k = 0; k < count; ++k) sweeps = std::max(sweeps, solve_island(k));
  } else {  // no parallel region: it costs about a microsecond even on one thread
    for (int k = 0; k < count; ++k) sweeps = std::max(sweeps, solve_island(k));
  }
  // Bodies pushed by a contact (a point of theirs carries a normal impulse) go to x_0 + h u; the
  // others keep the body step's pose, moved on by what a neighbour's impulse changed, if any.
  for (const int i : moved_) pushed_[i] = 0;
  for (const ContactConstraint& c : contacts) {
    for (int k = 0; k < c.point_count; ++k) {
      if (!(c.points[static_cast<std::size_t>(k)].normal_impulse > 0.0)) continue;
      pushed_[c.a] = 1;
      if (c.b >= 0) pushed_[c.b] = 1;
    }
  }
  for (const int i : moved_) {
    if (masses.inverse_mass[i] == 0.0 && masses.inverse_inertia[i] == 0.0) continue;  // fixed
    if (pushed_[i]) {
      bodies.position[i] = start_pose.position[i] + intervals[i] * bodies.velocity[i];
      bodies.angle[i] = start_pose.angle[i] + intervals[i] * bodies.angular_velocity[i];
    } else {
      bodies.position[i] += intervals[i] * (bodies.velocity[i] - velocity_before_[i]);
      bodies.angle[i] += intervals[i] * (bodies.angular_velocity[i] - angular_velocity_before_[i]);
    }
  }
  return sweeps;
}

void SequentialImpulses::undo(BodySet& bodies) {
  for (const int i : moved_) {
    bodies.position[i] = pose_before_.position[i];
    bodies.angle[i] = pose_before_.angle[i];
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
  auto correct_island = [&](int k) {
    return correct_contact_positions(islands.island(contacts, order[k]), bodies, masses, config_);
  };
  double worst = 0.0;  // [m]
  if (in_parallel(contacts, islands)) {
#pragma omp parallel for schedule(dynamic) reduction(max : worst)
    for (int k = 0; k < count; ++k) worst = std::max(worst, correct_island(k));
  } else {
    for (int k = 0; k < count; ++k) worst = std::max(worst, correct_island(k));
  }
  return worst;
}

}  // namespace flotsam
