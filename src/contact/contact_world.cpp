#include "contact/contact_world.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cassert>
#include <chrono>
#include <cmath>
#include <numeric>
#include <tuple>

#include <omp.h>

#include "core/parallel_for.hpp"

namespace flotsam {
namespace {

constexpr int parallel_pairs = 2000;  // [-] threads pay off from a few thousand

class Stopwatch {
 public:
  double lap() {  // [s] since the last lap
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return seconds;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// Contact points of a manifold become solver points; r_A, r_B are filled by prepare_contacts.
ContactConstraint make_constraint(const Manifold& m, int a, int b, int segment, double friction,
                                  double slop, double width) {
  ContactConstraint c;
  c.a = a, c.b = b, c.segment = segment;
  c.normal = m.normal;
  c.point_count = m.point_count;
  c.friction = friction;
  c.slop = slop;
  c.width = width;
  c.reference_on_a = m.reference_on_a;
  c.local_normal = m.local_normal;
  c.local_plane_point = m.local_plane_point;
  for (int k = 0; k < m.point_count; ++k) {
    const ManifoldPoint& mp = m.points[static_cast<std::size_t>(k)];
    ContactPointConstraint& p = c.points[static_cast<std::size_t>(k)];
    p.separation = mp.separation;
    p.local_incident = mp.local_incident;
    p.feature = mp.feature;
    p.r_a = mp.point;  // world point for now; made relative in collide()
    p.r_b = mp.point;
  }
  return c;
}

}  // namespace

Rectangle body_rectangle(const BodySet& bodies, int i) {
  return {{bodies.position[i], bodies.axis(i)}, bodies.half_extents(i)};
}

ContactWorld::ContactWorld(const ContactConfig& config, double added_mass_coefficient)
    : config_(config),
      added_mass_coefficient_(added_mass_coefficient),
      solver_(make_contact_solver(config)),
      margin_(solver_->margin_in_slops()),
      sleep_(config.sleep_time, config.sleep_speed) {}

// The solve moves each body by about h times its change of velocity. Detection only saw the gaps
// within its margin (2 slop), so a body pushed further than that by a neighbour (a log struck
// from upstream, pushed towards a pier a few centimetres away) may be moved into a contact
// nobody detected, and across a pier in one interval. Then the interval is solved again from
// the same state, each body's detection margin grown by the distance the first solve moved it:
// the contacts it would have run into are now seen as gaps, whose speculative target (v* = -s/h)
// lets it close them and no more.
void ContactWorld::step(BodySet& bodies, const BoundarySegments& walls, double interval,
                        const std::vector<int>* members, const std::vector<double>* lengths) {
  assert(interval >= 0.0);  // a programming error, not bad input
  select(bodies, members);
  if (lengths) {
    lengths_ = *lengths;
  } else {
    lengths_.resize(static_cast<std::size_t>(bodies.size()));
    for (const int i : in_step_) lengths_[i] = interval;
  }
  reach_.resize(static_cast<std::size_t>(bodies.size()), 0.0);
  for (const int i : grown_) reach_[i] = 0.0;  // the last step's
  grown_.clear();
  find_interval_start(bodies);
  if (sleep_.enabled()) sleep_.check_forces(bodies, interval_start_, lengths_, active_);
  detect(bodies, walls, members);
  if (sleep_.wake_touched(contacts_, bodies)) {  // detected again with the woken bodies' poses
    contacts_ = previous_;
    contacts_.insert(contacts_.end(), others_.begin(), others_.end());
    detect(bodies, walls, members);
  }
  solve(bodies);
  if (grow_reach(bodies)) {
    solver_->undo(bodies);
    contacts_ = previous_;  // the last interval's contacts again, for the warm start
    contacts_.insert(contacts_.end(), others_.begin(), others_.end());
    detect(bodies, walls, members);
    solve(bodies);
    profile_.second_solves = 1;
  } else {
    profile_.second_solves = 0;
  }
  correct_positions(bodies);
  sleep_.update(contacts_, islands_, bodies, lengths_, active_);
  contacts_.insert(contacts_.end(), resting_.begin(), resting_.end());
  contacts_.insert(contacts_.end(), others_.begin(), others_.end());
  others_.clear();
  for (const int i : in_step_) {
    after_.linear[i] = bodies.velocity[i];
    after_.angular[i] = bodies.angular_velocity[i];
    after_known_[i] = 1;
    start_pose_.position[i] = bodies.position[i];  // where its next interval starts
    start_pose_.angle[i] = bodies.angle[i];
  }
}

// The velocities the bodies of this step had at the start of the interval: those this world
// left them with at the end of their last interval, when they were in it (the body step has
// since added the forces' change); else the present ones (as if the forces acted at the start).
// Their poses then: where this world left them, or where plan() found them at the start of the
// flow step; else as if they had moved with their present velocities, x - h u.
// Only the step's bodies' entries are written (the others are read by nobody).
void ContactWorld::find_interval_start(const BodySet& bodies) {
  const auto n = static_cast<std::size_t>(bodies.size());
  after_.linear.resize(n, Vec2::Zero());
  after_.angular.resize(n, 0.0);
  after_known_.resize(n, 0);
  start_pose_.position.resize(n, Vec2::Zero());
  start_pose_.angle.resize(n, 0.0);
  pose_known_.resize(n, 0);
  interval_start_.linear.resize(n);
  interval_start_.angular.resize(n);
  for (const int i : in_step_) {
    interval_start_.linear[i] = after_known_[i] ? after_.linear[i] : bodies.velocity[i];
    interval_start_.angular[i] = after_known_[i] ? after_.angular[i] : bodies.angular_velocity[i];
    if (pose_known_[i]) continue;
    const double h = lengths_[i];  // [s]
    start_pose_.position[i] = bodies.position[i] - h * bodies.velocity[i];
    start_pose_.angle[i] = bodies.angle[i] - h * bodies.angular_velocity[i];
    pose_known_[i] = 1;  // step() keeps its end pose from now on
  }
}

// The bodies of this step, in_step_ (ascending), and their flags active_: the members that are
// not gone, or every body that is not. The flags of the last step's bodies are cleared, so a
// small group's step costs its own size, not the body count.
void ContactWorld::select(const BodySet& bodies, const std::vector<int>* members) {
  const auto n = static_cast<std::size_t>(bodies.size());
  if (active_.size() != n) {
    active_.assign(n, 0);
  } else {
    for (const int i : in_step_) active_[i] = 0;
  }
  in_step_.clear();
  if (members) {
    for (const int i : *members) {
      if (bodies.state[i] == BodyState::gone || active_[i]) continue;
      active_[i] = 1;
      in_step_.push_back(i);
    }
    if (!std::is_sorted(in_step_.begin(), in_step_.end()))
      std::sort(in_step_.begin(), in_step_.end());
  } else {
    for (int i = 0; i < bodies.size(); ++i) {
      if (bodies.state[i] == BodyState::gone) continue;
      active_[i] = 1;
      in_step_.push_back(i);
    }
  }
}

// reach_i = how far the solve moved body i's farthest point, h (|du| + |d omega| R), where it is
// more than its detection margin; true when some body's is.
bool ContactWorld::grow_reach(const BodySet& bodies) {
  bool grown = false;
  for (const int i : in_step_) {  // the others' velocities did not change
    const double R = 0.5 * std::hypot(bodies.length[i], bodies.width[i]);  // [m]
    const double moved =
        lengths_[i] * ((bodies.velocity[i] - velocity_before_[i]).norm() +
                       std::abs(bodies.angular_velocity[i] - angular_velocity_before_[i]) * R);
    if (moved > margin_ * config_.allowed_overlap * bodies.width[i])
      reach_[i] = moved, grown = true, grown_.push_back(i);
  }
  return grown;
}

ContactSchedule ContactWorld::plan(const BodySet& bodies, const BoundarySegments& walls,
                                   double dt) {
  ContactSchedule schedule = planner_.plan(bodies, walls, dt, config_);
  start_pose_.position = bodies.position;  // where every body's first interval starts
  start_pose_.angle = bodies.angle;
  pose_known_.assign(static_cast<std::size_t>(bodies.size()), 1);
  std::vector<char> free(static_cast<std::size_t>(bodies.size()), 0);
  for (const int i : schedule.free) free[i] = 1;
  after_known_.resize(free.size(), 0);
  for (const int i : schedule.free) {
    after_known_[i] = 0;  // its next interval starts unknown
    sleep_.wake(i);
  }
  std::erase_if(contacts_,
                [&](const ContactConstraint& c) { return free[c.a] || (c.b >= 0 && free[c.b]); });
  return schedule;
}

void ContactWorld::detect(const BodySet& bodies, const BoundarySegments& walls,
                          const std::vector<int>* members) {
  Stopwatch clock;
  select(bodies, members);
  update_boxes(bodies);
  profile_.boxes = clock.lap();
  find_pairs(walls);
  profile_.broad_phase = clock.lap();
  collide(bodies, walls);
  profile_.narrow_phase = clock.lap();
}

// Each box is the body's footprint grown by its contact margin 2 * allowed_overlap * l (and its
// reach, see step()), so that every pair the narrow phase would keep (gap <= margin) is a
// candidate.
void ContactWorld::update_boxes(const BodySet& bodies) {
  const int n = bodies.size();
  reach_.resize(static_cast<std::size_t>(n), 0.0);  // zero unless step() grew it
  boxes_.resize(static_cast<std::size_t>(n));
  rectangles_.resize(static_cast<std::size_t>(n));
  const auto box = [&](int i) {  // one cos, sin per body: its footprint is kept for collide()
    const Rectangle r = body_rectangle(bodies, i);
    const Vec2 u = r.frame.axis, h = r.half;
    const double grow = margin_ * config_.allowed_overlap * bodies.width[i] + reach_[i];  // [m]
    const Vec2 extent(std::abs(u.x()) * h.x() + std::abs(u.y()) * h.y() + grow,
                      std::abs(u.y()) * h.x() + std::abs(u.x()) * h.y() + grow);
    boxes_[i] = {bodies.position[i] - extent, bodies.position[i] + extent};
    rectangles_[i] = r;
  };
  parallel_for(static_cast<int>(in_step_.size()), parallel_pairs,
               [&](int k) { box(in_step_[static_cast<std::size_t>(k)]); });
}

void ContactWorld::find_pairs(const BoundarySegments& walls) {
  if (broad_phase_ == BroadPhase::sweep_and_prune) {
    sweep_.find_pairs(boxes_, active_, in_step_, body_pairs_);
  } else {
    brute_force_pairs(boxes_, active_, body_pairs_);
  }
  // The (body, segment) pairs of a run of in_step_, in its order, into one thread's list.
  const auto find_wall_pairs = [&](std::size_t begin, std::size_t end, WallQuery& q) {
    q.pairs.clear();
    for (std::size_t k = begin; k < end; ++k) {
      const int i = in_step_[k];
      if (broad_phase_ == BroadPhase::sweep_and_prune) {
        walls.query(boxes_[i], q.found, q.stamp, q.stamp_value);
      } else {
        q.found.resize(static_cast<std::size_t>(walls.size()));
        for (int s = 0; s < walls.size(); ++s) q.found[s] = s;
      }
      const bool levelled = static_cast<std::size_t>(i) < level_bottom_.size();
      for (const int s : q.found) {
        const Aabb segment_box{walls.start[s].cwiseMin(walls.end[s]),
                               walls.start[s].cwiseMax(walls.end[s])};
        if (!segment_box.overlaps(boxes_[i])) continue;
        if (levelled &&
            !walls.stops(s, rectangles_[i].frame.origin, level_bottom_[i], level_top_[i]))
          continue;
        q.pairs.emplace_back(i, s);
      }
    }
  };
  // Each thread a run of the bodies (one run below parallel_pairs), the runs joined in order: the
  // same pairs on any number of threads.
  const std::size_t count = in_step_.size();
  const bool parallel = count >= static_cast<std::size_t>(parallel_pairs);
  wall_queries_.resize(static_cast<std::size_t>(parallel ? omp_get_max_threads() : 1));
  const std::size_t runs = wall_queries_.size();
  parallel_for(runs, std::size_t{2}, [&](std::size_t r) {
    find_wall_pairs(count * r / runs, count * (r + 1) / runs, wall_queries_[r]);
  });
  wall_pairs_.clear();
  for (const WallQuery& q : wall_queries_)
    wall_pairs_.insert(wall_pairs_.end(), q.pairs.begin(), q.pairs.end());
  profile_.body_pairs = static_cast<int>(body_pairs_.size());
  profile_.wall_pairs = static_cast<int>(wall_pairs_.size());
}

// The last contacts of this step's bodies become previous_ (for the warm start); those of the
// other bodies are set aside in others_ and put back after the solve. The new contacts are built
// in parallel straight into their islands' order (islands.hpp), each matched to its pair's last
// contact (warm_start()): nothing is sorted, and no contact is moved after it is built.
void ContactWorld::collide(const BodySet& bodies, const BoundarySegments& walls) {
  const auto of_step = [&](const ContactConstraint& c) {
    return active_[c.a] || (c.b >= 0 && active_[c.b]);
  };
  others_.clear();
  std::atomic<bool> all_of_step = true;  // read through in parallel: a contact is 512 bytes
  parallel_for(static_cast<int>(contacts_.size()), parallel_pairs, [&](int m) {
    if (!of_step(contacts_[static_cast<std::size_t>(m)]))
      all_of_step.store(false, std::memory_order_relaxed);
  });
  if (all_of_step) {
    previous_.swap(contacts_);  // all of them (one group, the whole set): no copy
  } else {
    previous_.clear();
    for (ContactConstraint& c : contacts_) (of_step(c) ? previous_ : others_).push_back(c);
  }
  // The manifolds in parallel (each pair on its own), then kept in the pairs' order: the same
  // contacts on any number of threads.
  const int body_pairs = static_cast<int>(body_pairs_.size());
  const int wall_pairs = static_cast<int>(wall_pairs_.size());
  manifolds_.resize(static_cast<std::size_t>(body_pairs + wall_pairs));
  touching_.resize(manifolds_.size());
  auto collide_pair = [&](int k) {
    if (k < body_pairs) {
      const auto [i, j] = body_pairs_[static_cast<std::size_t>(k)];
      const double slop = config_.allowed_overlap * std::min(bodies.width[i], bodies.width[j]);
      manifolds_[k] = collide_rectangles(rectangles_[i], rectangles_[j],
                                         margin_ * slop + reach_[i] + reach_[j], 0.1 * slop);
    } else {
      const auto [i, s] = wall_pairs_[static_cast<std::size_t>(k - body_pairs)];
      const double slop = config_.allowed_overlap * bodies.width[i];  // [m]
      manifolds_[k] =
          collide_rectangle_segment(rectangles_[i], walls.start[s], walls.end[s], walls.normal[s],
                                    margin_ * slop + reach_[i], 0.1 * slop);
    }
    touching_[k] = manifolds_[k].point_count > 0;
  };
  const int pairs = body_pairs + wall_pairs;
  if (pairs >= parallel_pairs) {
#pragma omp parallel
    {
#pragma omp single nowait
      index_previous(bodies.size());  // meanwhile the other threads take the first pairs
#pragma omp for schedule(dynamic, 256)
      for (int k = 0; k < pairs; ++k) collide_pair(k);
      keep_touching(body_pairs);
    }
  } else {  // no parallel region: it costs about a microsecond even on one thread
    index_previous(bodies.size());
    for (int k = 0; k < pairs; ++k) collide_pair(k);
    keep_touching(body_pairs);
  }
  const std::vector<int>& destination = islands_.number(ends_, bodies.size());
  const int count = static_cast<int>(kept_.size());
  source_.resize(kept_.size());
  contacts_.resize(kept_.size());  // every one overwritten below
  // Contact d of the new order, from the pair's manifold; `hint` follows the last contacts
  // matched (warm_start()). Returns the points warm-started.
  auto build = [&](int d, int& hint) {
    const int k = kept_[static_cast<std::size_t>(source_[static_cast<std::size_t>(d)])];
    const Manifold& manifold = manifolds_[static_cast<std::size_t>(k)];
    ContactConstraint& c = contacts_[static_cast<std::size_t>(d)];
    if (k < body_pairs) {
      const auto [i, j] = body_pairs_[static_cast<std::size_t>(k)];
      const double width = std::min(bodies.width[i], bodies.width[j]);  // [m]
      c = make_constraint(manifold, i, j, -1, config_.friction, config_.allowed_overlap * width,
                          width);
    } else {
      const auto [i, s] = wall_pairs_[static_cast<std::size_t>(k - body_pairs)];
      const double width = bodies.width[i];  // [m]
      c = make_constraint(manifold, i, -1, s, config_.friction, config_.allowed_overlap * width,
                          width);
    }
    for (int q = 0; q < c.point_count; ++q) {
      auto& p = c.points[static_cast<std::size_t>(q)];
      p.r_a = p.r_a - bodies.position[c.a];
      p.r_b = c.b >= 0 ? Vec2(p.r_b - bodies.position[c.b]) : Vec2::Zero();
    }
    return warm_start(c, hint);
  };
  int points = 0, warm_started = 0;
  if (count >= parallel_pairs) {
#pragma omp parallel reduction(+ : points, warm_started)
    {
#pragma omp for schedule(static)
      for (int m = 0; m < count; ++m) source_[static_cast<std::size_t>(destination[m])] = m;
      int hint = 0;  // each thread's block of contacts in order (schedule static)
#pragma omp for schedule(static)
      for (int d = 0; d < count; ++d) {
        warm_started += build(d, hint);
        points += contacts_[static_cast<std::size_t>(d)].point_count;
      }
    }
  } else {
    for (int m = 0; m < count; ++m) source_[static_cast<std::size_t>(destination[m])] = m;
    int hint = 0;
    for (int d = 0; d < count; ++d) {
      warm_started += build(d, hint);
      points += contacts_[static_cast<std::size_t>(d)].point_count;
    }
  }
  profile_.contacts = count;
  profile_.points = points;
  profile_.warm_started_points = warm_started;
}

// The pairs that touch (kept_), body pairs then wall pairs in their order, and their bodies
// (ends_, b = -1 for a wall). Called by every thread of a parallel region, or outside one: each
// thread counts the touching pairs of its run, then writes them where the runs before it end.
void ContactWorld::keep_touching(int body_pairs) {
  const auto [begin, end] = team_run(touching_.size());
  int touching = 0;
  for (std::size_t k = begin; k < end; ++k) touching += touching_[k];
  auto d = static_cast<std::size_t>(team_offset(run_start_, touching));
#pragma omp single
  {
    kept_.resize(static_cast<std::size_t>(run_start_.back()));
    ends_.resize(kept_.size());
  }
  for (std::size_t k = begin; k < end; ++k) {
    if (!touching_[k]) continue;
    const int pair = static_cast<int>(k);
    kept_[d] = pair;
    ends_[d++] = pair < body_pairs
                     ? body_pairs_[k]
                     : BodyPair(wall_pairs_[k - static_cast<std::size_t>(body_pairs)].first, -1);
  }
}

// previous_ listed by body A: first_previous_[a], then next_previous_[m], in ascending order.
// Only the entries of the step's bodies and of previous_'s are written: a small group's step
// costs its own size.
void ContactWorld::index_previous(int body_count) {
  first_previous_.resize(static_cast<std::size_t>(body_count), -1);
  for (const int i : in_step_) first_previous_[i] = -1;
  for (const ContactConstraint& c : previous_) first_previous_[c.a] = -1;
  next_previous_.resize(previous_.size());
  previous_key_.resize(previous_.size());
  for (int m = static_cast<int>(previous_.size()) - 1; m >= 0; --m) {
    const ContactConstraint& c = previous_[static_cast<std::size_t>(m)];
    previous_key_[m] = {c.b, c.segment};
    next_previous_[m] = first_previous_[c.a];
    first_previous_[c.a] = m;
  }
}

// Last interval's accumulated impulses seed this one's (warm start): a resting jam then needs
// few sweeps. A contact is matched to the last one of its pair (a, b, segment), its points by
// feature, else by position: the nearest old point within a tenth of the thinner width (measured
// as r_A, which moves by at most l/4 per interval). The feature alone is not enough: when two
// logs of equal length lie side by side with their ends aligned, an end point flips between
// "incident vertex" and "clipped at the side plane" from one interval to the next; losing its
// impulse then throws the load of the whole jam behind it onto the next sweeps. A point that
// carried an impulse is resting: restitution is not applied to it again. Returns the points
// warm-started; `hint` is the index in previous_ after the last one matched (updated).
int ContactWorld::warm_start(ContactConstraint& c, int& hint) const {
  // The contacts come in nearly the same order from step to step: the one after the last one
  // matched is tried first (a pair has one contact, so whichever is found is the one), and last
  // step's are read one after another.
  const bool next = hint < static_cast<int>(previous_.size()) && previous_[hint].a == c.a &&
                    previous_key_[hint] == std::pair(c.b, c.segment);
  int found = next ? hint : first_previous_[c.a];
  while (found >= 0 && previous_key_[found] != std::pair(c.b, c.segment))
    found = next_previous_[found];
  if (found < 0) return 0;
  hint = found + 1;
  const ContactConstraint* it = &previous_[static_cast<std::size_t>(found)];
  std::array<bool, 2> used{false, false};
  std::array<int, 2> match{-1, -1};
  for (int k = 0; k < c.point_count; ++k) {
    for (int q = 0; q < it->point_count; ++q) {
      if (!used[q] && it->points[q].feature == c.points[k].feature) {
        match[k] = q, used[q] = true;
        break;
      }
    }
  }
  const double tolerance = 0.1 * c.width;  // [m]
  for (int k = 0; k < c.point_count; ++k) {
    double nearest = tolerance;  // [m]
    for (int q = 0; q < it->point_count && match[k] < 0; ++q) {
      const double d = (it->points[q].r_a - c.points[k].r_a).norm();
      if (!used[q] && d <= nearest) nearest = d, match[k] = q;
    }
    if (match[k] >= 0) used[match[k]] = true;
  }
  int warm = 0;
  for (int k = 0; k < c.point_count; ++k) {
    if (match[k] < 0) continue;
    ContactPointConstraint& p = c.points[k];
    const ContactPointConstraint& old = it->points[match[k]];
    p.normal_impulse = old.normal_impulse;
    p.tangent_impulse = old.tangent_impulse;
    p.first_impulse = old.first_impulse;
    p.last_impulse = old.last_impulse;
    p.resting = old.normal_impulse > 0.0;
    ++warm;
  }
  return warm;
}

// The solver (contact_solver.hpp) changes the velocities and moves the poses over the interval.
void ContactWorld::solve(BodySet& bodies) {
  Stopwatch clock;
  set_solver_masses(masses_, bodies, config_, added_mass_coefficient_, in_step_);
  profile_.sleeping_islands = sleep_.set_aside(contacts_, islands_, resting_, bodies);
  profile_.sleeping_contacts = static_cast<int>(resting_.size());
  if (profile_.sleeping_islands > 0) islands_.group(contacts_, bodies.size());
  prepare_contacts(contacts_, bodies, masses_, config_, lengths_, start_pose_);
  profile_.islands = islands_.count();
  profile_.largest_island = islands_.largest();
  velocity_before_.resize(bodies.velocity.size());
  angular_velocity_before_.resize(bodies.angular_velocity.size());
  for (const int i : in_step_) {  // for grow_reach()
    velocity_before_[i] = bodies.velocity[i];
    angular_velocity_before_[i] = bodies.angular_velocity[i];
  }
  profile_.velocity_sweeps =
      solver_->solve(contacts_, islands_, bodies, masses_, lengths_, interval_start_, start_pose_);
  profile_.solve = clock.lap();
}

void ContactWorld::correct_positions(BodySet& bodies) {
  Stopwatch clock;
  profile_.largest_overlap = solver_->correct_positions(contacts_, islands_, bodies, masses_);
  profile_.positions = clock.lap();
}

ContactReport ContactWorld::report(const BoundarySegments& walls, int body_count) const {
  return make_contact_report(contacts_, walls.group, body_count);
}

void contact_step(BodySet& bodies, const BoundarySegments& walls, const ContactConfig& config,
                  double interval) {
  ContactWorld world(config);
  world.step(bodies, walls, interval);
}

}  // namespace flotsam
