#include "contact/contact_planner.hpp"

#include <algorithm>
#include <cmath>

namespace flotsam {
namespace {

constexpr double safety = 1.5;                // s [-] on the predicted travel
constexpr int most_intervals = 1000;          // cap on K [-]
constexpr double travel_per_interval = 0.25;  // [-] of the thinner width: the l/4 rule

// Distance between two boxes [m], 0 when they overlap.
double box_gap(const Aabb& a, const Aabb& b) {
  const Vec2 d = (a.lower - b.upper).cwiseMax(b.lower - a.upper).cwiseMax(0.0);
  return d.norm();
}

int root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];  // path halving
  return i;
}

// Largest speed at which a point of body i and a point of body j at the same place close on
// each other [m/s]. At a place p, with d = x_j - x_i and omega_i k x (p - x_i) =
// omega_j k x (p - x_j) + omega_j k x d + (omega_i - omega_j) k x (p - x_i), the difference of the
// two bodies' velocities is
//   (u_i - u_j) + omega_j k x d + (omega_i - omega_j) k x (p - x_i),  |p - x_i| <= R_i
// (R_i half body i's diagonal). Bodies turning together (a raft) close only by the first two
// terms: the velocity difference that is not their common rotation.
double closing_speed(const BodySet& b, int i, int j) {
  const Vec2 d = b.position[j] - b.position[i];                                        // [m]
  const double R = 0.5 * std::hypot(b.length[i], b.width[i]);                          // [m]
  const Vec2 rigid = b.velocity[i] - b.velocity[j] + b.angular_velocity[j] * perp(d);  // [m/s]
  return rigid.norm() + std::abs(b.angular_velocity[i] - b.angular_velocity[j]) * R;
}

// How much faster than now a body may drift in the step because a contact slowed it against the
// flow since its last sub-step [m/s]: its speed relative to the water grew from |u_rel| (the
// last sub-step's, F_drag / K) to |u_f - u_p|, and the drag alone never carries it past the
// water's velocity. A log just stopped against a deck takes the drag of a body at rest, many
// times what it felt drifting, and must not cross the step unplanned.
double slowed_drift(const BodySet& b, int i) {
  if (!(b.drag_rate[i] > 0.0)) return 0.0;  // no drag yet (just placed) or none (no water)
  const double last = b.drag_force[i].norm() / b.drag_rate[i];  // [m/s]
  return std::max(0.0, (b.flow_velocity[i] - b.velocity[i]).norm() - last);
}

// The fewest equal intervals of a step dt in which a pair closing at speed c [m/s] with relative
// acceleration a [m/s^2] closes by at most a quarter of the thinner width l: within an interval
// of length h the contacts have stopped nothing yet, so the closing is s (c h + a h^2 / 2), and
//   s a h^2 / 2 + s c h - l/4 <= 0   =>   h <= (l/4) / (s c / 2 + sqrt((s c / 2)^2 + s a l/8))
// (the positive root, written without cancellation).
int intervals_for(double c, double a, double width, double dt) {
  const double allowed = travel_per_interval * width;  // [m]
  const double b = 0.5 * safety * c;                   // [m/s]
  const double root_term = b + std::sqrt(b * b + 0.5 * safety * a * allowed);
  if (root_term <= 0.0) return 1;
  const double K = std::ceil(dt * root_term / allowed * (1.0 - 1e-12));
  return static_cast<int>(std::clamp(K, 1.0, static_cast<double>(most_intervals)));
}

}  // namespace

ContactSchedule ContactPlanner::plan(const BodySet& bodies, const BoundarySegments& walls,
                                     double dt, const ContactConfig& config) {
  const int n = bodies.size();
  const auto N = static_cast<std::size_t>(n);
  footprint_.resize(N), swept_.resize(N), active_.resize(N);
  reach_.resize(N), speed_.resize(N), drift_.resize(N), spin_.resize(N), acceleration_.resize(N);
  fine_parent_.resize(N), intervals_.assign(N, 0);
  for (int i = 0; i < n; ++i) {
    active_[i] = bodies.state[i] != BodyState::gone && !bodies.anchored[i];
    const Vec2 u = bodies.axis(i), h = bodies.half_extents(i);
    const Vec2 extent(std::abs(u.x()) * h.x() + std::abs(u.y()) * h.y(),
                      std::abs(u.y()) * h.x() + std::abs(u.x()) * h.y());
    footprint_[i] = {bodies.position[i] - extent, bodies.position[i] + extent};
    speed_[i] = bodies.velocity[i].norm();
    drift_[i] = slowed_drift(bodies, i);
    spin_[i] = std::abs(bodies.angular_velocity[i]) * 0.5 *
               std::hypot(bodies.length[i], bodies.width[i]);            // [m/s] of its corners
    const Vec2 added = bodies.reaction_force[i] - bodies.drag_force[i];  // [N]
    acceleration_[i] =
        (bodies.drag_force[i].norm() + bodies.bed_force[i].norm() + added.norm()) / bodies.mass[i];
    const double margin = 2.0 * config.allowed_overlap * bodies.width[i];  // [m]
    reach_[i] =
        safety * ((speed_[i] + drift_[i] + spin_[i]) * dt + 0.5 * acceleration_[i] * dt * dt);
    const Vec2 grow = Vec2::Constant(reach_[i] + margin);
    swept_[i] = {footprint_[i].lower - grow, footprint_[i].upper + grow};
  }
  // An anchored body does not move but can be hit: it takes part in pairs with zero reach.
  std::vector<char> present(N);
  for (int i = 0; i < n; ++i) present[i] = bodies.state[i] != BodyState::gone;
  for (int i = 0; i < n; ++i) {
    if (present[i] && !active_[i]) {
      reach_[i] = speed_[i] = drift_[i] = spin_[i] = acceleration_[i] = 0.0;
      const Vec2 grow = Vec2::Constant(2.0 * config.allowed_overlap * bodies.width[i]);
      swept_[i] = {footprint_[i].lower - grow, footprint_[i].upper + grow};
    }
  }

  // Body pairs within reach of each other.
  sweep_.find_pairs(swept_, present, pairs_);
  std::vector<std::pair<int, int>> links;  // (body, body) with their K
  std::vector<int> link_intervals;
  for (const auto& [i, j] : pairs_) {
    if (!active_[i] && !active_[j]) continue;  // two anchored bodies
    const double margin = 2.0 * config.allowed_overlap * (bodies.width[i] + bodies.width[j]);
    const double c = std::min({closing_speed(bodies, i, j), closing_speed(bodies, j, i),
                               speed_[i] + spin_[i] + speed_[j] + spin_[j]}) +
                     drift_[i] + drift_[j];                        // [m/s]
    const double a = acceleration_[i] + acceleration_[j];          // [m/s^2]
    const double closing = safety * (c * dt + 0.5 * a * dt * dt);  // [m]
    if (box_gap(footprint_[i], footprint_[j]) > closing + margin) continue;
    links.emplace_back(i, j);
    link_intervals.push_back(intervals_for(c, a, std::min(bodies.width[i], bodies.width[j]), dt));
  }
  // Walls within reach: the body needs intervals of its own.
  for (int i = 0; i < n; ++i) {
    if (!active_[i]) continue;
    walls.query(swept_[i], found_, stamp_, stamp_value_);
    const double margin = 2.0 * config.allowed_overlap * bodies.width[i];
    for (const int s : found_) {
      const Aabb segment{walls.start[s].cwiseMin(walls.end[s]),
                         walls.start[s].cwiseMax(walls.end[s])};
      if (box_gap(footprint_[i], segment) > reach_[i] + margin) continue;
      intervals_[i] = std::max(intervals_[i], intervals_for(speed_[i] + drift_[i] + spin_[i],
                                                            acceleration_[i], bodies.width[i], dt));
    }
  }
  // Fine groups: the components of the links that need more than one interval (and of the
  // bodies whose wall does); every linked body is resolved at the step's end.
  std::vector<char> linked(N, 0);
  for (int i = 0; i < n; ++i) {
    fine_parent_[i] = i;
    linked[i] = intervals_[i] > 0;  // a wall within reach
  }
  for (std::size_t k = 0; k < links.size(); ++k) {
    const auto [i, j] = links[k];
    linked[i] = linked[j] = 1;
    if (link_intervals[k] <= 1) continue;
    const int ri = root(fine_parent_, i), rj = root(fine_parent_, j);
    if (ri != rj) fine_parent_[std::max(ri, rj)] = std::min(ri, rj);
  }
  std::vector<int> fine(N, 0);  // K of each fine component, at its root
  for (int i = 0; i < n; ++i) {
    const int r = root(fine_parent_, i);
    fine[r] = std::max(fine[r], intervals_[i]);
  }
  for (std::size_t k = 0; k < links.size(); ++k) {
    if (link_intervals[k] <= 1) continue;
    const int r = root(fine_parent_, links[k].first);
    fine[r] = std::max(fine[r], link_intervals[k]);
  }

  // Groups in the order of their smallest member.
  ContactSchedule schedule;
  std::vector<int> group_of(N, -1);
  for (int i = 0; i < n; ++i) {
    if (!present[i]) continue;
    if (linked[i]) schedule.at_end.push_back(i);
    const int r = root(fine_parent_, i);
    if (fine[r] <= 1) {
      schedule.free.push_back(i);
      continue;
    }
    if (group_of[r] < 0) {
      group_of[r] = static_cast<int>(schedule.groups.size());
      schedule.groups.emplace_back().intervals = fine[r];
    }
    schedule.groups[group_of[r]].bodies.push_back(i);
  }
  return schedule;
}

}  // namespace flotsam
