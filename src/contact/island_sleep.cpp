#include "contact/island_sleep.hpp"

#include <cmath>

namespace flotsam {
namespace {

double half_diagonal(const BodySet& bodies, int i) {  // R [m]
  return 0.5 * std::hypot(bodies.length[i], bodies.width[i]);
}

}  // namespace

void IslandSleep::resize(int n) {
  const auto size = static_cast<std::size_t>(n);
  if (asleep_.size() >= size) return;
  asleep_.resize(size, 0), group_.resize(size, -1), woken_.resize(size, 0);
  stashed_.resize(size, 0);
  in_contact_.resize(size, 0), last_known_.resize(size, 0);
  rest_position_.resize(size, Vec2::Zero()), rest_acceleration_.resize(size, Vec2::Zero());
  rest_angle_.resize(size, 0.0), rest_angular_.resize(size, 0.0), still_time_.resize(size, 0.0);
  acceleration_.resize(size, Vec2::Zero()), angular_acceleration_.resize(size, 0.0);
  last_position_.resize(size, Vec2::Zero()), last_angle_.resize(size, 0.0);
  moved_position_.resize(size, Vec2::Zero()), moved_velocity_.resize(size, Vec2::Zero());
  moved_angle_.resize(size, 0.0), moved_spin_.resize(size, 0.0);
}

void IslandSleep::wake(int i) {
  if (i >= static_cast<int>(asleep_.size())) return;
  sleeping_ -= asleep_[i];
  asleep_[i] = 0, still_time_[i] = 0.0, last_known_[i] = 0;
}

void IslandSleep::wake_all() {
  for (std::size_t i = 0; i < asleep_.size(); ++i) wake(static_cast<int>(i));
}

// Wakes every body of the sleeping groups marked in woken_, in one pass; with `bodies`, each is
// put back where the body step left it (check_forces moved it to its sleeping pose).
void IslandSleep::wake_marked(BodySet* bodies) {
  for (std::size_t i = 0; i < asleep_.size(); ++i) {
    if (!asleep_[i] || !woken_[group_[i]]) continue;
    asleep_[i] = 0, still_time_[i] = 0.0, --sleeping_;
    if (!bodies || !stashed_[i]) continue;
    bodies->position[i] = moved_position_[i], bodies->angle[i] = moved_angle_[i];
    bodies->velocity[i] = moved_velocity_[i], bodies->angular_velocity[i] = moved_spin_[i];
  }
}

void IslandSleep::check_forces(BodySet& bodies, const BodyVelocities& start,
                               const std::vector<double>& lengths,
                               const std::vector<char>& in_step) {
  if (!enabled()) return;
  const int n = bodies.size();
  resize(n);
  for (int i = 0; i < n; ++i) {
    if (!in_step[i]) continue;
    const double h = lengths[i];  // [s]
    acceleration_[i] = h > 0.0 ? Vec2((bodies.velocity[i] - start.linear[i]) / h) : Vec2::Zero();
    angular_acceleration_[i] = h > 0.0 ? (bodies.angular_velocity[i] - start.angular[i]) / h : 0.0;
  }
  if (sleeping_ == 0) return;
  std::fill(woken_.begin(), woken_.end(), 0);
  std::fill(stashed_.begin(), stashed_.end(), 0);
  bool any = false;
  for (int i = 0; i < n; ++i) {
    if (asleep_[i] && bodies.state[i] == BodyState::gone) woken_[group_[i]] = 1, any = true;
    if (!in_step[i] || !asleep_[i] || lengths[i] <= 0.0) continue;
    const double R = half_diagonal(bodies, i);  // [m]
    const bool changed =                        // (Z-2)
        (acceleration_[i] - rest_acceleration_[i]).norm() * time_ > speed_ ||
        std::abs(angular_acceleration_[i] - rest_angular_[i]) * R * time_ > speed_;
    if (changed) woken_[group_[i]] = 1, any = true;
  }
  if (any) wake_marked(nullptr);
  for (int i = 0; i < n; ++i) {
    if (!in_step[i] || !asleep_[i]) continue;
    stashed_[i] = 1;
    moved_position_[i] = bodies.position[i], moved_angle_[i] = bodies.angle[i];
    moved_velocity_[i] = bodies.velocity[i], moved_spin_[i] = bodies.angular_velocity[i];
    bodies.position[i] = rest_position_[i], bodies.angle[i] = rest_angle_[i];
    bodies.velocity[i] = Vec2::Zero(), bodies.angular_velocity[i] = 0.0;
  }
}

bool IslandSleep::wake_touched(const std::vector<ContactConstraint>& contacts, BodySet& bodies) {
  if (sleeping_ == 0) return false;
  std::fill(woken_.begin(), woken_.end(), 0);
  bool any = false;
  for (const ContactConstraint& c : contacts) {
    if (c.b < 0 || (!asleep_[c.a] && !asleep_[c.b])) continue;
    if (asleep_[c.a] && asleep_[c.b] && group_[c.a] == group_[c.b]) continue;
    if (asleep_[c.a]) woken_[group_[c.a]] = 1;
    if (asleep_[c.b]) woken_[group_[c.b]] = 1;
    any = true;
  }
  if (any) wake_marked(&bodies);
  return any;
}

int IslandSleep::set_aside(std::vector<ContactConstraint>& contacts, const Islands& islands,
                           std::vector<ContactConstraint>& resting, BodySet& bodies) {
  resting.clear();
  if (sleeping_ == 0) return 0;
  std::vector<ContactConstraint> awake;
  int moved = 0;
  for (int k = 0; k < islands.count(); ++k) {
    const auto island = islands.island(contacts, k);
    bool all = true, some = false;
    for (const ContactConstraint& c : island) {
      const bool a = asleep_[c.a] != 0, b = c.b < 0 || asleep_[c.b] != 0;
      all = all && a && b;
      some = some || a || (c.b >= 0 && asleep_[c.b]);
    }
    if (all) {
      resting.insert(resting.end(), island.begin(), island.end());
      ++moved;
      continue;
    }
    if (some) {  // touched in a second detection: woken where it sleeps, at rest
      for (const ContactConstraint& c : island) {
        for (const int i : {c.a, c.b}) {
          if (i < 0 || !asleep_[i]) continue;
          asleep_[i] = 0, still_time_[i] = 0.0, --sleeping_;
          bodies.velocity[i] = Vec2::Zero(), bodies.angular_velocity[i] = 0.0;
        }
      }
    }
    awake.insert(awake.end(), island.begin(), island.end());
  }
  if (moved > 0) contacts.swap(awake);
  return moved;
}

void IslandSleep::update(std::vector<ContactConstraint>& contacts, const Islands& islands,
                         BodySet& bodies, const std::vector<double>& lengths,
                         const std::vector<char>& in_step) {
  if (!enabled()) return;
  const int n = bodies.size();
  resize(n);
  {
    std::fill(in_contact_.begin(), in_contact_.end(), 0);
    for (const ContactConstraint& c : contacts) {
      in_contact_[c.a] = 1;
      if (c.b >= 0) in_contact_[c.b] = 1;
    }
    for (int i = 0; i < n; ++i) {  // (Z-1)
      if (!in_step[i] || asleep_[i]) continue;
      const double R = half_diagonal(bodies, i), h = lengths[i];  // [m], [s]
      const bool still = in_contact_[i] && last_known_[i] && bodies.velocity[i].norm() < speed_ &&
                         std::abs(bodies.angular_velocity[i]) * R < speed_ &&
                         (bodies.position[i] - last_position_[i]).norm() <= speed_ * h &&
                         std::abs(bodies.angle[i] - last_angle_[i]) * R <= speed_ * h;
      still_time_[i] = still ? still_time_[i] + h : 0.0;
    }
    for (int k = 0; k < islands.count(); ++k) {
      const auto island = islands.island(contacts, k);
      bool still = true;
      for (const ContactConstraint& c : island)
        still = still && still_time_[c.a] >= time_ && (c.b < 0 || still_time_[c.b] >= time_);
      if (!still) continue;
      const int group = island.front().a;
      for (const ContactConstraint& c : island) {
        for (const int i : {c.a, c.b}) {
          if (i < 0 || asleep_[i]) continue;
          asleep_[i] = 1, group_[i] = group, ++sleeping_;
          rest_position_[i] = bodies.position[i], rest_angle_[i] = bodies.angle[i];
          rest_acceleration_[i] = acceleration_[i], rest_angular_[i] = angular_acceleration_[i];
          bodies.velocity[i] = Vec2::Zero(), bodies.angular_velocity[i] = 0.0;
        }
      }
    }
  }
  for (int i = 0; i < n; ++i) {
    if (!in_step[i]) continue;
    last_position_[i] = bodies.position[i], last_angle_[i] = bodies.angle[i];
    last_known_[i] = 1;
  }
}

}  // namespace flotsam
