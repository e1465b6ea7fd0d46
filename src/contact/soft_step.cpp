#include "contact/soft_step.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "contact/restitution_energy.hpp"

#include "core/constants.hpp"

namespace flotsam {
namespace {

constexpr double max_push_speed = 3.0;       // v_max [m/s] (S-2): fastest push-out of an overlap
constexpr double max_hertz_per_rate = 0.25;  // f at most this fraction of the sub-step rate [-]
// [-] Threads pay off from a few thousand contacts: each sub-step waits for the threads 3 times
// per colour, and a colour of a few hundred contacts is solved in microseconds.
constexpr std::size_t parallel_contacts = 2000;

// Two points at once (Box2D v2.4's block solver, as in impulse_solver.cpp): the accumulated
// impulses x >= 0 that bring the normal velocities vn to the targets, with w = K x + b >= 0 and
// x_i w_i = 0, b = vn - target - K old; the four cases in turn. Returns old when none holds.
Vec2 solve_block(const Mat2& K, const Mat2& mass, const Vec2& vn, const Vec2& target,
                 const Vec2& old) {
  const Vec2 b = vn - target - K * old;
  Vec2 x = -(mass * b);
  if (x.x() >= 0.0 && x.y() >= 0.0) return x;
  x = Vec2(-b.x() / K(0, 0), 0.0);
  if (x.x() >= 0.0 && K(1, 0) * x.x() + b.y() >= 0.0) return x;
  x = Vec2(0.0, -b.y() / K(1, 1));
  if (x.y() >= 0.0 && K(0, 1) * x.y() + b.x() >= 0.0) return x;
  if (b.x() >= 0.0 && b.y() >= 0.0) return Vec2::Zero();
  return old;
}

Vec2 rotate(const Vec2& q, const Vec2& r) {  // R(Theta) r with q = (cos Theta, sin Theta)
  return {q.x() * r.x() - q.y() * r.y(), q.y() * r.x() + q.x() * r.y()};
}

}  // namespace

// Runs f(contact) over every contact, colour after colour; inside a parallel region, the
// contacts of a colour are shared among the threads (none shares a movable body with another),
// the overflow's taken by one thread. The threads meet once per colour.
template <class F>
void SoftStep::each_colour(F&& f) {
  for (int g = 0; g < colours_.groups(); ++g) {
    const int begin = colours_.start(g), end = colours_.start(g + 1);
    if (begin == end) continue;  // an empty overflow: no meeting of the threads
    if (colours_.is_overflow(g)) {
#pragma omp single
      for (int k = begin; k < end; ++k) f(soft_[static_cast<std::size_t>(k)]);
    } else {
#pragma omp for schedule(static)
      for (int k = begin; k < end; ++k) f(soft_[static_cast<std::size_t>(k)]);
    }
  }
}

int SoftStep::solve(std::vector<ContactConstraint>& contacts, const Islands& /*islands*/,
                    BodySet& bodies, const SolverMasses& masses,
                    const std::vector<double>& intervals, const BodyVelocities& start) {
  prepare(contacts, bodies, masses, intervals, start);
  const int substeps = config_.substeps;
  double largest = 0.0;  // [m] overlap at the end
  const bool threads = contacts.size() >= parallel_contacts && choice_.threads();
  const auto start_time = std::chrono::steady_clock::now();
#pragma omp parallel if (threads)
  {
    for (int k = 0; k < substeps; ++k) {
      each_colour([&](Contact& c) { warm_start(c); });
      each_colour([&](Contact& c) { solve_contact(c, true); });
      each_colour([&](Contact& c) {
        if (c.first_of_a) move_pose(c.a);  // before any contact of the body reads its pose
        if (c.first_of_b) move_pose(c.b);
        solve_contact(c, false);
        for (int p = 0; p < c.count; ++p) {  // this sub-step's impulses join the interval's
          Point& q = c.points[static_cast<std::size_t>(p)];
          q.total_normal += q.normal_impulse;
          q.total_tangent += q.tangent_impulse;
          if (k == 0) q.first = {q.normal_impulse, q.tangent_impulse};
          // Sub-step 1 starts from the last interval's last sub-step.
          if (k == 0 && substeps > 1)
            q.normal_impulse = q.later.x(), q.tangent_impulse = q.later.y();
        }
      });
    }
    double worst = 0.0;  // [m]
    each_colour([&](Contact& c) {
      for (const auto& [first, i] : {std::pair{c.first_of_a, c.a}, std::pair{c.first_of_b, c.b}})
        if (first) mid_velocity_[i] = velocity_[i], mid_spin_[i] = spin_[i];  // before restitution
      worst = std::max(worst, restitute(c));
    });
#pragma omp critical
    largest = std::max(largest, worst);
  }
  if (contacts.size() >= parallel_contacts)
    choice_.record(
        threads,
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count(),
        static_cast<double>(contacts.size()));
  largest_overlap_ = largest;
  bound_restitution();
  store(contacts, bodies);
  return contacts.empty() ? 0 : 2 * substeps;
}

// Flat copies of the contacts in colour order, with their soft coefficients (S-2), and of the
// bodies they touch, each put back where the interval started: D = -h u^0, Theta = -h omega^0.
void SoftStep::prepare(const std::vector<ContactConstraint>& contacts, const BodySet& bodies,
                       const SolverMasses& masses, const std::vector<double>& intervals,
                       const BodyVelocities& start) {
  const int n = bodies.size(), wall = n;
  const auto slots = static_cast<std::size_t>(n + 1);
  movable_.assign(slots, 0);
  for (int i = 0; i < n; ++i)
    movable_[i] = masses.inverse_mass[i] > 0.0 || masses.inverse_inertia[i] > 0.0;
  colours_.assign(contacts, movable_);
  velocity_.resize(slots), shift_.resize(slots), rotation_.resize(slots), gain_.resize(slots);
  spin_gain_.resize(slots);
  spin_.resize(slots), turn_.resize(slots), step_.resize(slots);
  inverse_mass_.resize(slots), inverse_inertia_.resize(slots);
  velocity_[wall] = shift_[wall] = gain_[wall] = Vec2::Zero();
  spin_gain_[wall] = 0.0;
  rotation_[wall] = Vec2::UnitX();
  spin_[wall] = turn_[wall] = step_[wall] = inverse_mass_[wall] = inverse_inertia_[wall] = 0.0;
  std::vector<char> seen(slots, 0);
  moving_.clear();
  auto add_body = [&](int i) {
    if (seen[i]) return;
    seen[i] = 1;
    // Back to the pose the interval started from (x_1 = x_0 + h u^0), the velocity before the
    // forces, and the forces' share of each sub-step.
    const double h = intervals[i], m = config_.substeps;  // [s], [-]
    gain_[i] = (bodies.velocity[i] - start.linear[i]) / m;
    spin_gain_[i] = (bodies.angular_velocity[i] - start.angular[i]) / m;
    velocity_[i] = start.linear[i];
    spin_[i] = start.angular[i];
    shift_[i] = -h * bodies.velocity[i];
    turn_[i] = -h * bodies.angular_velocity[i];
    rotation_[i] = {std::cos(turn_[i]), std::sin(turn_[i])};
    step_[i] = h / config_.substeps;
    inverse_mass_[i] = masses.inverse_mass[i];
    inverse_inertia_[i] = masses.inverse_inertia[i];
    if (movable_[i]) moving_.push_back(i);
  };
  const std::vector<int>& order = colours_.order();
  soft_.resize(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    const ContactConstraint& src = contacts[static_cast<std::size_t>(order[k])];
    Contact& c = soft_[k];
    add_body(src.a);
    if (src.b >= 0) add_body(src.b);
    c.a = src.a;
    c.b = src.b >= 0 ? src.b : wall;
    c.count = src.point_count;
    c.normal = src.normal;
    c.friction = src.friction;
    c.slop = src.slop;
    c.use_block = src.use_block;
    c.K = src.K;
    c.block_mass = src.normal_mass;
    const double h =
        src.b >= 0 ? std::max(intervals[src.a], intervals[src.b]) : intervals[src.a];  // [s]
    const double h_s = h / config_.substeps;                                           // [s]
    if (h_s > 0.0) {
      const double hertz = std::min(config_.contact_hertz, max_hertz_per_rate / h_s);  // [Hz]
      const double omega = 2.0 * pi * hertz;                                           // [rad/s]
      const double zeta = config_.damping_ratio;
      const double a = h_s * omega * (2.0 * zeta + h_s * omega);  // [-]
      c.inverse_substep = 1.0 / h_s;
      c.bias_rate = omega / (2.0 * zeta + h_s * omega);
      c.mass_scale = a / (1.0 + a);
      c.impulse_scale = 1.0 / (1.0 + a);
    } else {  // no time to move: a rigid velocity solve
      c.inverse_substep = c.bias_rate = c.impulse_scale = 0.0;
      c.mass_scale = 1.0;
    }
    for (int p = 0; p < c.count; ++p) {
      const ContactPointConstraint& s = src.points[static_cast<std::size_t>(p)];
      Point& q = c.points[static_cast<std::size_t>(p)];
      q = Point{};
      q.r_a = s.r_a;
      q.r_b = s.r_b;
      q.base_separation = s.separation - c.normal.dot(s.r_a - s.r_b);
      q.normal_mass = s.normal_mass;
      q.tangent_mass = s.tangent_mass;
      q.approach = s.approach_velocity;
      q.normal_impulse = s.first_impulse.x();  // for sub-step 0
      q.tangent_impulse = s.first_impulse.y();
      q.later = s.last_impulse;  // for sub-step 1
      q.resting = s.resting;
    }
  }
  // Each movable body's first contact in colour order.
  std::fill(seen.begin(), seen.end(), 0);
  for (Contact& c : soft_) {
    c.first_of_a = movable_[c.a] && !seen[c.a];
    c.first_of_b = movable_[c.b] && !seen[c.b];
    seen[c.a] = seen[c.b] = 1;
  }
  saved_position_.resize(moving_.size()), saved_velocity_.resize(moving_.size());
  saved_angle_.resize(moving_.size()), saved_spin_.resize(moving_.size());
  mid_velocity_.resize(slots), mid_spin_.resize(slots);
  for (std::size_t m = 0; m < moving_.size(); ++m) {
    const int i = moving_[m];
    saved_position_[m] = bodies.position[i], saved_velocity_[m] = bodies.velocity[i];
    saved_angle_[m] = bodies.angle[i], saved_spin_[m] = bodies.angular_velocity[i];
  }
}

// The impulses a contact starts a sub-step from (sub-step 0: the first sub-step's of the last
// interval, which took the forces' velocity of the whole interval; sub-step 1: the last
// sub-step's; the later ones: the sub-step before). At a body's first contact in colour order,
// the body takes this sub-step's share of the forces' velocity first.
void SoftStep::warm_start(Contact& c) {
  Vec2 va = velocity_[c.a], vb = velocity_[c.b];
  double wa = spin_[c.a], wb = spin_[c.b];
  if (c.first_of_a) va += gain_[c.a], wa += spin_gain_[c.a];
  if (c.first_of_b) vb += gain_[c.b], wb += spin_gain_[c.b];
  const Vec2 tangent = -perp(c.normal);
  for (int p = 0; p < c.count; ++p) {
    const Point& q = c.points[static_cast<std::size_t>(p)];
    const Vec2 P = q.normal_impulse * c.normal + q.tangent_impulse * tangent;
    va += inverse_mass_[c.a] * P;
    wa += inverse_inertia_[c.a] * cross(q.r_a, P);
    vb -= inverse_mass_[c.b] * P;
    wb -= inverse_inertia_[c.b] * cross(q.r_b, P);
  }
  if (movable_[c.a]) velocity_[c.a] = va, spin_[c.a] = wa;
  if (movable_[c.b]) velocity_[c.b] = vb, spin_[c.b] = wb;
}

// Body i's pose moves by h_s u; (cos, sin) turned.
void SoftStep::move_pose(int i) {
  const double h = step_[i], turn = h * spin_[i];  // [s], [rad]
  shift_[i] += h * velocity_[i];
  turn_[i] += turn;
  const Vec2 q = rotation_[i] + turn * perp(rotation_[i]);
  rotation_[i] = q / q.norm();
}

// One iteration over the points of a contact: normal impulses (S-2), then friction.
void SoftStep::solve_contact(Contact& c, bool bias) {
  Vec2 va = velocity_[c.a], vb = velocity_[c.b];
  double wa = spin_[c.a], wb = spin_[c.b];
  const double ima = inverse_mass_[c.a], imb = inverse_mass_[c.b];
  const double iia = inverse_inertia_[c.a], iib = inverse_inertia_[c.b];
  const Vec2 dp = shift_[c.a] - shift_[c.b];
  const Vec2 qa = rotation_[c.a], qb = rotation_[c.b];
  // The relax of two points at once: v_n to 0, or to -s/h_s at a gap.
  const int single = !bias && c.use_block ? 0 : c.count;  // points solved one by one
  if (single == 0) {
    Point &p1 = c.points[0], &p2 = c.points[1];
    Vec2 target, vn;
    for (int p = 0; p < 2; ++p) {
      const Point& q = c.points[static_cast<std::size_t>(p)];
      const double s =
          q.base_separation + c.normal.dot(dp + rotate(qa, q.r_a) - rotate(qb, q.r_b));  // (S-1)
      target[p] = s > 0.0 ? -s * c.inverse_substep : 0.0;
      vn[p] = (va + wa * perp(q.r_a) - vb - wb * perp(q.r_b)).dot(c.normal);
    }
    const Vec2 old(p1.normal_impulse, p2.normal_impulse);
    const Vec2 x = solve_block(c.K, c.block_mass, vn, target, old);
    for (int p = 0; p < 2; ++p) {
      Point& q = c.points[static_cast<std::size_t>(p)];
      const Vec2 P = (x[p] - old[p]) * c.normal;
      q.normal_impulse = x[p];
      q.largest_normal = std::max(q.largest_normal, x[p]);
      va += ima * P, wa += iia * cross(q.r_a, P);
      vb -= imb * P, wb -= iib * cross(q.r_b, P);
    }
  }
  for (int p = 0; p < single; ++p) {
    Point& q = c.points[static_cast<std::size_t>(p)];
    const double s =
        q.base_separation + c.normal.dot(dp + rotate(qa, q.r_a) - rotate(qb, q.r_b));  // (S-1)
    double target = 0.0, mass_scale = 1.0, impulse_scale = 0.0;                        // v* [m/s]
    if (s > 0.0) {
      target = -s * c.inverse_substep;  // the gap may close within the sub-step
    } else if (bias) {
      target = std::min(-c.bias_rate * s, max_push_speed);
      mass_scale = c.mass_scale;
      impulse_scale = c.impulse_scale;
    }
    const double vn = (va + wa * perp(q.r_a) - vb - wb * perp(q.r_b)).dot(c.normal);  // [m/s]
    const double updated = std::max(q.normal_impulse - q.normal_mass * mass_scale * (vn - target) -
                                        impulse_scale * q.normal_impulse,
                                    0.0);
    const Vec2 P = (updated - q.normal_impulse) * c.normal;
    q.normal_impulse = updated;
    q.largest_normal = std::max(q.largest_normal, updated);
    va += ima * P, wa += iia * cross(q.r_a, P);
    vb -= imb * P, wb -= iib * cross(q.r_b, P);
  }
  const Vec2 tangent = -perp(c.normal);
  for (int p = 0; p < c.count; ++p) {
    Point& q = c.points[static_cast<std::size_t>(p)];
    const double vt = (va + wa * perp(q.r_a) - vb - wb * perp(q.r_b)).dot(tangent);  // [m/s]
    const double bound = c.friction * q.normal_impulse;                              // [N s]
    const double updated = std::clamp(q.tangent_impulse - q.tangent_mass * vt, -bound, bound);
    const Vec2 P = (updated - q.tangent_impulse) * tangent;
    q.tangent_impulse = updated;
    va += ima * P, wa += iia * cross(q.r_a, P);
    vb -= imb * P, wb -= iib * cross(q.r_b, P);
  }
  if (movable_[c.a]) velocity_[c.a] = va, spin_[c.a] = wa;
  if (movable_[c.b]) velocity_[c.b] = vb, spin_[c.b] = wb;
}

// Newton's law with friction may gain energy (restitution_energy.hpp): when the bodies end with
// more kinetic energy than they came with, the restitution's change is cut to the fraction that
// gives back e^2 of what the compression took. The step's moving bodies are taken together.
void SoftStep::bound_restitution() {
  constexpr double round_off = 1e-12;         // [-] relative energy change taken for rounding
  double before = 0.0, mid = 0.0, end = 0.0;  // [J]
  RestitutionEnergy change;
  for (std::size_t m = 0; m < moving_.size(); ++m) {
    const int i = moving_[m];
    const double w = inverse_mass_[i], w_i = inverse_inertia_[i];
    before += solver_kinetic_energy(saved_velocity_[m], saved_spin_[m], w, w_i);
    mid += solver_kinetic_energy(mid_velocity_[i], mid_spin_[i], w, w_i);
    end += solver_kinetic_energy(velocity_[i], spin_[i], w, w_i);
    change.add(mid_velocity_[i], mid_spin_[i], velocity_[i], spin_[i], w, w_i);
  }
  if (end <= before * (1.0 + round_off)) return;
  const double s = change.fraction(before, mid, config_.restitution);  // [-]
  for (std::size_t m = 0; m < moving_.size(); ++m) {
    const int i = moving_[m];
    velocity_[i] = mid_velocity_[i] + s * (velocity_[i] - mid_velocity_[i]);
    spin_[i] = mid_spin_[i] + s * (spin_[i] - mid_spin_[i]);
  }
}

// Restitution (M-9) at the points struck in this interval: v_n -> -e v_n^0. Returns the
// largest overlap at the end of the interval (S-1) [m].
double SoftStep::restitute(Contact& c) {
  Vec2 va = velocity_[c.a], vb = velocity_[c.b];
  double wa = spin_[c.a], wb = spin_[c.b];
  const Vec2 dp = shift_[c.a] - shift_[c.b];
  double worst = 0.0;  // [m]
  auto struck = [&](const Point& q) {
    return !q.resting && q.approach < -config_.restitution_threshold && q.largest_normal > 0.0;
  };
  // Two points struck together are restituted at once (one after the other, the second would
  // undo part of the first: a log meeting another end to end would leave spinning).
  const bool block = c.use_block && struck(c.points[0]) && struck(c.points[1]);
  if (block) {
    Vec2 target, vn, old;
    for (int p = 0; p < 2; ++p) {
      const Point& q = c.points[static_cast<std::size_t>(p)];
      target[p] = -config_.restitution * q.approach;  // v* = -e v_n^0 (M-9)
      vn[p] = (va + wa * perp(q.r_a) - vb - wb * perp(q.r_b)).dot(c.normal);
      old[p] = q.total_normal;
    }
    const Vec2 x = solve_block(c.K, c.block_mass, vn, target, old);
    for (int p = 0; p < 2; ++p) {
      Point& q = c.points[static_cast<std::size_t>(p)];
      const Vec2 P = (x[p] - old[p]) * c.normal;
      q.total_normal = x[p];
      va += inverse_mass_[c.a] * P, wa += inverse_inertia_[c.a] * cross(q.r_a, P);
      vb -= inverse_mass_[c.b] * P, wb -= inverse_inertia_[c.b] * cross(q.r_b, P);
    }
  }
  for (int p = 0; p < c.count; ++p) {
    Point& q = c.points[static_cast<std::size_t>(p)];
    const double s = q.base_separation + c.normal.dot(dp + rotate(rotation_[c.a], q.r_a) -
                                                      rotate(rotation_[c.b], q.r_b));
    worst = std::max(worst, -s);
    if (block || !struck(q)) continue;
    const double vn = (va + wa * perp(q.r_a) - vb - wb * perp(q.r_b)).dot(c.normal);  // [m/s]
    const double total =
        std::max(q.total_normal - q.normal_mass * (vn + config_.restitution * q.approach), 0.0);
    const Vec2 P = (total - q.total_normal) * c.normal;
    q.total_normal = total;
    va += inverse_mass_[c.a] * P, wa += inverse_inertia_[c.a] * cross(q.r_a, P);
    vb -= inverse_mass_[c.b] * P, wb -= inverse_inertia_[c.b] * cross(q.r_b, P);
  }
  if (movable_[c.a]) velocity_[c.a] = va, spin_[c.a] = wa;
  if (movable_[c.b]) velocity_[c.b] = vb, spin_[c.b] = wb;
  return worst;
}

// The impulses go back to the contacts (warm start of the next interval, reports), the
// velocities and the poses to the bodies: x = x_1 + D, theta = theta_1 + Theta.
void SoftStep::store(std::vector<ContactConstraint>& contacts, BodySet& bodies) {
  const std::vector<int>& order = colours_.order();
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Contact& c = soft_[k];
    ContactConstraint& dst = contacts[static_cast<std::size_t>(order[k])];
    for (int p = 0; p < c.count; ++p) {
      const Point& q = c.points[static_cast<std::size_t>(p)];
      ContactPointConstraint& d = dst.points[static_cast<std::size_t>(p)];
      d.normal_impulse = q.total_normal;
      d.tangent_impulse = q.total_tangent;
      d.first_impulse = q.first;
      d.last_impulse = {q.normal_impulse, q.tangent_impulse};
    }
  }
  for (const int i : moving_) {
    bodies.velocity[i] = velocity_[i];
    bodies.angular_velocity[i] = spin_[i];
    bodies.position[i] += shift_[i];
    bodies.angle[i] += turn_[i];
  }
}

void SoftStep::undo(BodySet& bodies) {
  for (std::size_t m = 0; m < moving_.size(); ++m) {
    const int i = moving_[m];
    bodies.position[i] = saved_position_[m], bodies.velocity[i] = saved_velocity_[m];
    bodies.angle[i] = saved_angle_[m], bodies.angular_velocity[i] = saved_spin_[m];
  }
}

}  // namespace flotsam
