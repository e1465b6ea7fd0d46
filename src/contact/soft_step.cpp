#include "contact/soft_step.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/constants.hpp"
#include "core/vector_clones.hpp"

// The lanes' helpers below take and return 32-byte vectors; they stay within this file, so the
// calling convention GCC notes (AVX's differs from SSE2's) is never crossed.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace flotsam {
namespace {

constexpr double max_push_speed = 3.0;       // v_max [m/s] (S-2): fastest push-out of an overlap
constexpr double max_hertz_per_rate = 0.25;  // f at most this fraction of the sub-step rate [-]
// [-] Threads pay off from a few thousand contacts: each sub-step waits for the threads 3 times
// per colour, and a colour of a few hundred contacts is solved in microseconds.
constexpr std::size_t parallel_contacts = 2000;

using Lanes = SoftStep::Lanes;
using Mask = SoftStep::Mask;
using SmallMask = SoftStep::SmallMask;
constexpr int lanes = SoftStep::lanes;

Mask widen(SmallMask m) {
  return __builtin_convertvector(m, Mask);
}
bool any(const Mask& m) {
  for (int l = 0; l < lanes; ++l)
    if (m[l]) return true;
  return false;
}
// std::max, std::min of each lane, as the one-contact solve took them (same bits, -0 included).
Lanes max(const Lanes& a, const Lanes& b) {
  return a < b ? b : a;
}
Lanes min(const Lanes& a, const Lanes& b) {
  return b < a ? b : a;
}
Lanes broadcast(double x) {
  return Lanes{} + x;
}

struct Velocities {  // of the lanes' A or B bodies
  Lanes x, y, w;     // u [m/s], omega [rad/s]
};
struct Poses {
  Lanes sx, sy, qx, qy;  // D [m], (cos, sin) Theta
};

Velocities gather_velocities(const SoftStep::Body* body, const std::array<int, lanes>& slot) {
  Velocities v;
  for (int l = 0; l < lanes; ++l) {
    const SoftStep::Body& b = body[slot[static_cast<std::size_t>(l)]];
    v.x[l] = b.velocity.x(), v.y[l] = b.velocity.y(), v.w[l] = b.spin;
  }
  return v;
}
Poses gather_poses(const SoftStep::Body* body, const std::array<int, lanes>& slot) {
  Poses p;
  for (int l = 0; l < lanes; ++l) {
    const SoftStep::Body& b = body[slot[static_cast<std::size_t>(l)]];
    p.sx[l] = b.shift.x(), p.sy[l] = b.shift.y();
    p.qx[l] = b.rotation.x(), p.qy[l] = b.rotation.y();
  }
  return p;
}
void scatter_velocities(SoftStep::Body* body, const std::array<int, lanes>& slot, SmallMask movable,
                        const Velocities& v) {
  for (int l = 0; l < lanes; ++l) {
    if (!movable[l]) continue;
    SoftStep::Body& b = body[slot[static_cast<std::size_t>(l)]];
    b.velocity = {v.x[l], v.y[l]};
    b.spin = v.w[l];
  }
}

// The relative velocity at point q along (dx, dy):
// [(u_A + omega_A k x r_A) - (u_B + omega_B k x r_B)] . d.
Lanes relative(const Velocities& A, const Velocities& B, const SoftStep::WidePoint& q,
               const Lanes& dx, const Lanes& dy) {
  const Lanes x = ((A.x + A.w * (-q.r_ay)) - B.x) - B.w * (-q.r_by);
  const Lanes y = ((A.y + A.w * q.r_ax) - B.y) - B.w * q.r_bx;
  return x * dx + y * dy;
}

// (S-1): s = s_1 + n . [(D_A + R(Theta_A) r_A - r_A) - (D_B + R(Theta_B) r_B - r_B)].
Lanes separation(const SoftStep::Wide& c, const SoftStep::WidePoint& q, const Poses& A,
                 const Poses& B) {
  const Lanes dx = A.sx - B.sx, dy = A.sy - B.sy;
  const Lanes x = (dx + (A.qx * q.r_ax - A.qy * q.r_ay)) - (B.qx * q.r_bx - B.qy * q.r_by);
  const Lanes y = (dy + (A.qy * q.r_ax + A.qx * q.r_ay)) - (B.qy * q.r_bx + B.qx * q.r_by);
  return q.base_separation + (c.nx * x + c.ny * y);
}

// The impulse P at point q, in the lanes of m: u_A += P / m_A, omega_A += (r_A x P) / I_A, and
// the opposite for B.
void apply(const SoftStep::Wide& c, const SoftStep::WidePoint& q, const Lanes& px, const Lanes& py,
           const Mask& m, Velocities& A, Velocities& B) {
  const Lanes ax = A.x + c.inverse_mass_a * px, ay = A.y + c.inverse_mass_a * py;
  const Lanes aw = A.w + c.inverse_inertia_a * (q.r_ax * py - q.r_ay * px);
  const Lanes bx = B.x - c.inverse_mass_b * px, by = B.y - c.inverse_mass_b * py;
  const Lanes bw = B.w - c.inverse_inertia_b * (q.r_bx * py - q.r_by * px);
  A.x = m ? ax : A.x, A.y = m ? ay : A.y, A.w = m ? aw : A.w;
  B.x = m ? bx : B.x, B.y = m ? by : B.y, B.w = m ? bw : B.w;
}

// Two points at once (Box2D v2.4's block solver, as in impulse_solver.cpp): the accumulated
// impulses x >= 0 that bring the normal velocities vn to the targets, with w = K x + b >= 0 and
// x_i w_i = 0, b = vn - target - K old; the four cases in turn. Gives old when none holds.
// Inlined so that it takes the instruction set of its caller's clone.
[[gnu::always_inline]] inline void solve_block(const SoftStep::WideBlock& k, const Lanes vn[2],
                                               const Lanes target[2], const Lanes old[2],
                                               Lanes x[2]) {
  const Lanes b0 = (vn[0] - target[0]) - (k.k00 * old[0] + k.k01 * old[1]);
  const Lanes b1 = (vn[1] - target[1]) - (k.k10 * old[0] + k.k11 * old[1]);
  const Lanes zero{};
  const Lanes both0 = -(k.m00 * b0 + k.m01 * b1), both1 = -(k.m10 * b0 + k.m11 * b1);
  const Mask both = (both0 >= 0.0) & (both1 >= 0.0);
  const Lanes first = -b0 / k.k00;
  const Mask only_first = (first >= 0.0) & (k.k10 * first + b1 >= 0.0);
  const Lanes second = -b1 / k.k11;
  const Mask only_second = (second >= 0.0) & (k.k01 * second + b0 >= 0.0);
  const Mask none = (b0 >= 0.0) & (b1 >= 0.0);
  x[0] = both ? both0 : only_first ? first : only_second ? zero : none ? zero : old[0];
  x[1] = both ? both1 : only_first ? zero : only_second ? second : none ? zero : old[1];
}

// The contacts of a Wide's lanes (k < 0: an empty lane) asked from memory ahead of their use
// in colour order they are scattered over the contacts. Inlined: GCC takes a function of only
// prefetches for one without effects and drops its calls.
constexpr int ahead = 2;  // [Wides]
[[gnu::always_inline]] inline void fetch_lanes(const std::vector<ContactConstraint>& contacts,
                                               const std::vector<int>& order,
                                               const int* lane_contact, bool for_write) {
  for (int l = 0; l < lanes; ++l) {
    const int k = lane_contact[l];
    if (k < 0) continue;
    const char* p = reinterpret_cast<const char*>(&contacts[static_cast<std::size_t>(order[k])]);
    for (std::size_t b = 0; b < sizeof(ContactConstraint); b += 64)
      for_write ? __builtin_prefetch(p + b, 1) : __builtin_prefetch(p + b, 0);
  }
}

}  // namespace

// The impulses a contact starts a sub-step from (sub-step 0: the first sub-step's of the last
// interval, which took the forces' velocity of the whole interval; sub-step 1: the last
// sub-step's; the later ones: the sub-step before). At a body's first contact in colour order,
// the body takes this sub-step's share of the forces' velocity first.
FLOTSAM_VECTOR_CLONES
void soft_warm_start(const SoftStep::Wide& c, SoftStep::Body* body,
                     const SoftStep::BodyStep* step) {
  Velocities A = gather_velocities(body, c.a), B = gather_velocities(body, c.b);
  for (int l = 0; l < lanes; ++l) {
    const std::size_t i = static_cast<std::size_t>(l);
    if (c.first_of_a[l]) {
      const SoftStep::BodyStep& s = step[c.a[i]];
      A.x[l] += s.gain.x(), A.y[l] += s.gain.y(), A.w[l] += s.spin_gain;
    }
    if (c.first_of_b[l]) {
      const SoftStep::BodyStep& s = step[c.b[i]];
      B.x[l] += s.gain.x(), B.y[l] += s.gain.y(), B.w[l] += s.spin_gain;
    }
  }
  for (int p = 0; p < 2; ++p) {
    const SoftStep::WidePoint& q = c.points[p];
    // P = lambda_n n + lambda_t t, t = -k x n = (n_y, -n_x)
    const Lanes px = q.normal_impulse * c.nx + q.tangent_impulse * c.ny;
    const Lanes py = q.normal_impulse * c.ny + q.tangent_impulse * (-c.nx);
    apply(c, q, px, py, widen(c.point[p]), A, B);
  }
  scatter_velocities(body, c.a, c.movable_a, A);
  scatter_velocities(body, c.b, c.movable_b, B);
}

// One iteration over the points of the lanes' contacts: normal impulses (S-2), then friction.
// The relax (no bias) takes a lane's two points at once when it has the block solver.
FLOTSAM_VECTOR_CLONES
void soft_solve(SoftStep::Wide& c, const SoftStep::WideBlock& k, SoftStep::Body* body, bool bias) {
  Velocities A = gather_velocities(body, c.a), B = gather_velocities(body, c.b);
  const Poses PA = gather_poses(body, c.a), PB = gather_poses(body, c.b);
  const Mask block = bias ? Mask{} : widen(c.block);
  if (any(block)) {  // v_n to 0, or to -s/h_s at a gap
    Lanes target[2], vn[2], old[2], x[2];
    for (int p = 0; p < 2; ++p) {
      const SoftStep::WidePoint& q = c.points[p];
      const Lanes s = separation(c, q, PA, PB);
      target[p] = s > 0.0 ? -s * c.inverse_substep : Lanes{};
      vn[p] = relative(A, B, q, c.nx, c.ny);
      old[p] = q.normal_impulse;
    }
    solve_block(k, vn, target, old, x);
    for (int p = 0; p < 2; ++p) {
      SoftStep::WidePoint& q = c.points[p];
      const Lanes d = x[p] - old[p];
      q.normal_impulse = block ? x[p] : q.normal_impulse;
      q.largest_normal = block ? max(q.largest_normal, x[p]) : q.largest_normal;
      apply(c, q, d * c.nx, d * c.ny, block, A, B);
    }
  }
  const Lanes max_push = broadcast(max_push_speed), one = broadcast(1.0);
  for (int p = 0; p < 2; ++p) {  // the other lanes' points one by one
    SoftStep::WidePoint& q = c.points[p];
    const Mask m = widen(c.point[p]) & ~block;
    const Lanes s = separation(c, q, PA, PB);
    const Mask gap = s > 0.0;
    Lanes target{}, mass_scale = one, impulse_scale{};  // v* [m/s], [-], [-]
    if (bias) {
      target = min(-c.bias_rate * s, max_push);
      mass_scale = c.mass_scale;
      impulse_scale = c.impulse_scale;
    }
    target = gap ? -s * c.inverse_substep : target;  // the gap may close within the sub-step
    mass_scale = gap ? one : mass_scale;
    impulse_scale = gap ? Lanes{} : impulse_scale;
    const Lanes vn = relative(A, B, q, c.nx, c.ny);  // [m/s]
    const Lanes updated = max(q.normal_impulse - q.normal_mass * mass_scale * (vn - target) -
                                  impulse_scale * q.normal_impulse,
                              Lanes{});
    const Lanes d = updated - q.normal_impulse;
    q.normal_impulse = m ? updated : q.normal_impulse;
    q.largest_normal = m ? max(q.largest_normal, updated) : q.largest_normal;
    apply(c, q, d * c.nx, d * c.ny, m, A, B);
  }
  const Lanes tx = c.ny, ty = -c.nx;  // t = -k x n
  for (int p = 0; p < 2; ++p) {
    SoftStep::WidePoint& q = c.points[p];
    const Lanes vt = relative(A, B, q, tx, ty);         // [m/s]
    const Lanes bound = c.friction * q.normal_impulse;  // [N s]
    const Lanes updated = min(max(q.tangent_impulse - q.tangent_mass * vt, -bound), bound);
    const Lanes d = updated - q.tangent_impulse;
    const Mask m = widen(c.point[p]);
    q.tangent_impulse = m ? updated : q.tangent_impulse;
    apply(c, q, d * tx, d * ty, m, A, B);
  }
  scatter_velocities(body, c.a, c.movable_a, A);
  scatter_velocities(body, c.b, c.movable_b, B);
}

// Restitution (M-9) at the points struck in this interval: v_n -> -e v_n^0. Returns the
// largest overlap of the lanes' points at the end of the interval (S-1) [m].
FLOTSAM_VECTOR_CLONES
double soft_restitute(SoftStep::Wide& c, const SoftStep::WideBlock& k,
                      const std::array<SoftStep::WideStart, 2>& start, SoftStep::Body* body,
                      double restitution, double threshold) {
  Velocities A = gather_velocities(body, c.a), B = gather_velocities(body, c.b);
  const Poses PA = gather_poses(body, c.a), PB = gather_poses(body, c.b);
  Mask struck[2];
  for (int p = 0; p < 2; ++p)
    struck[p] = widen(c.point[p]) & ~start[p].resting & (start[p].approach < -threshold) &
                (c.points[p].largest_normal > 0.0);
  // Two points struck together are restituted at once (one after the other, the second would
  // undo part of the first: a log meeting another end to end would leave spinning).
  const Mask block = widen(c.block) & struck[0] & struck[1];
  if (any(block)) {
    Lanes target[2], vn[2], old[2], x[2];
    for (int p = 0; p < 2; ++p) {
      target[p] = -restitution * start[p].approach;  // v* = -e v_n^0 (M-9)
      vn[p] = relative(A, B, c.points[p], c.nx, c.ny);
      old[p] = c.points[p].total_normal;
    }
    solve_block(k, vn, target, old, x);
    for (int p = 0; p < 2; ++p) {
      SoftStep::WidePoint& q = c.points[p];
      const Lanes d = x[p] - old[p];
      q.total_normal = block ? x[p] : q.total_normal;
      apply(c, q, d * c.nx, d * c.ny, block, A, B);
    }
  }
  double worst = 0.0;  // [m]
  for (int p = 0; p < 2; ++p) {
    SoftStep::WidePoint& q = c.points[p];
    const Lanes s = separation(c, q, PA, PB);
    for (int l = 0; l < lanes; ++l)
      if (c.point[p][l]) worst = std::max(worst, -s[l]);
    const Mask m = struck[p] & ~block;
    const Lanes vn = relative(A, B, q, c.nx, c.ny);  // [m/s]
    const Lanes updated =
        max(q.total_normal - q.normal_mass * (vn + restitution * start[p].approach), Lanes{});
    const Lanes d = updated - q.total_normal;
    q.total_normal = m ? updated : q.total_normal;
    apply(c, q, d * c.nx, d * c.ny, m, A, B);
  }
  scatter_velocities(body, c.a, c.movable_a, A);
  scatter_velocities(body, c.b, c.movable_b, B);
  return worst;
}

// Runs f(w) over every Wide wide_[w], colour after colour; inside a parallel region, the Wides
// of a colour are shared among the threads (none shares a movable body with another), the
// overflow's taken by one thread. The threads meet once per colour.
template <class F>
void SoftStep::each_colour(F&& f) {
  for (int g = 0; g < colours_.groups(); ++g) {
    const int begin = wide_start_[g], end = wide_start_[g + 1];
    if (begin == end) continue;  // an empty overflow: no meeting of the threads
    if (colours_.is_overflow(g)) {
#pragma omp single
      for (int w = begin; w < end; ++w) f(static_cast<std::size_t>(w));
    } else {
#pragma omp for schedule(static)
      for (int w = begin; w < end; ++w) {
        if (w + ahead < end) fetch_bodies(wide_[static_cast<std::size_t>(w + ahead)]);
        f(static_cast<std::size_t>(w));
      }
    }
  }
}

// The bodies of a Wide's lanes asked from memory ahead of their use (a colour's bodies are
// scattered over the bodies).
void SoftStep::fetch_bodies(const Wide& c) const {
  for (int l = 0; l < lanes; ++l) {
    const std::size_t lane = static_cast<std::size_t>(l);
    __builtin_prefetch(&body_[c.a[lane]], 1), __builtin_prefetch(&body_[c.b[lane]], 1);
    __builtin_prefetch(&body_step_[c.a[lane]]), __builtin_prefetch(&body_step_[c.b[lane]]);
  }
}

int SoftStep::solve(std::vector<ContactConstraint>& contacts, const Islands& /*islands*/,
                    BodySet& bodies, const SolverMasses& masses,
                    const std::vector<double>& intervals, const BodyVelocities& start,
                    const BodyPoses& start_pose) {
  const bool threads = contacts.size() >= parallel_contacts && choice_.threads();
  const auto start_time = std::chrono::steady_clock::now();
  prepare(contacts, bodies, masses, intervals, start, start_pose, threads);
  const int substeps = config_.substeps;
  double largest = 0.0;  // [m] overlap at the end
  Body* body = body_.data();
  const BodyStep* step = body_step_.data();
#pragma omp parallel if (threads)
  {
    for (int k = 0; k < substeps; ++k) {
      each_colour([&](std::size_t w) { soft_warm_start(wide_[w], body, step); });
      each_colour([&](std::size_t w) { soft_solve(wide_[w], block_[w], body, true); });
      each_colour([&](std::size_t w) { relax(w, k); });
    }
    double worst = 0.0;  // [m]
    each_colour([&](std::size_t w) {
      const Wide& c = wide_[w];
      for (int l = 0; l < lanes; ++l) {  // before restitution
        const std::size_t i = static_cast<std::size_t>(l);
        if (c.first_of_a[l])
          mid_velocity_[c.a[i]] = body[c.a[i]].velocity, mid_spin_[c.a[i]] = body[c.a[i]].spin;
        if (c.first_of_b[l])
          mid_velocity_[c.b[i]] = body[c.b[i]].velocity, mid_spin_[c.b[i]] = body[c.b[i]].spin;
      }
      worst = std::max(worst, soft_restitute(wide_[w], block_[w], start_[w], body,
                                             config_.restitution, config_.restitution_threshold));
    });
#pragma omp critical
    largest = std::max(largest, worst);
    const int moving = static_cast<int>(moving_.size());
#pragma omp for schedule(static)
    for (int m = 0; m < moving; ++m) energy_[static_cast<std::size_t>(m)] = body_energy(m);
  }
  largest_overlap_ = largest;
  bound_restitution();
  store(contacts, bodies, threads);
  if (contacts.size() >= parallel_contacts)
    choice_.record(
        threads,
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count(),
        static_cast<double>(contacts.size()));
  return contacts.empty() ? 0 : 2 * substeps;
}

// Flat copies of the contacts in colour order, four to a Wide, with their soft coefficients
// (S-2), and of the bodies they touch, each put back where the interval started: D = x_0 - x_1,
// Theta = theta_0 - theta_1.
void SoftStep::prepare(const std::vector<ContactConstraint>& contacts, const BodySet& bodies,
                       const SolverMasses& masses, const std::vector<double>& intervals,
                       const BodyVelocities& start, const BodyPoses& start_pose, bool threads) {
  const int n = bodies.size(), wall = n;
  const auto slots = static_cast<std::size_t>(n + 1);
  movable_.resize(slots);
  movable_[wall] = 0;
  // The contacts' bodies in a compact copy: the serial passes below read them in colour order.
  const int contact_count = static_cast<int>(contacts.size());
  ends_.resize(contacts.size());
#pragma omp parallel if (threads)
  {
#pragma omp for schedule(static) nowait
    for (int i = 0; i < n; ++i)
      movable_[i] = masses.inverse_mass[i] > 0.0 || masses.inverse_inertia[i] > 0.0;
#pragma omp for schedule(static)
    for (int m = 0; m < contact_count; ++m) {
      const ContactConstraint& c = contacts[static_cast<std::size_t>(m)];
      ends_[static_cast<std::size_t>(m)] = {c.a, c.b};
    }
  }
  colours_.assign(ends_, movable_);
  const std::vector<int>& order = colours_.order();
  // Colour g's contacts fill its Wides lane after lane; the overflow's one to a Wide.
  const int groups = colours_.groups();
  wide_start_.assign(static_cast<std::size_t>(groups + 1), 0);
  for (int g = 0; g < groups; ++g) {
    const int count = colours_.start(g + 1) - colours_.start(g);
    wide_start_[g + 1] =
        wide_start_[g] + (colours_.is_overflow(g) ? count : (count + lanes - 1) / lanes);
  }
  const int wides = wide_start_.back();
  lane_contact_.resize(static_cast<std::size_t>(lanes * wides));
  wide_.resize(static_cast<std::size_t>(wides)), block_.resize(static_cast<std::size_t>(wides));
  start_.resize(static_cast<std::size_t>(wides));
  body_.resize(slots), body_step_.resize(slots);
  inverse_mass_.resize(slots), inverse_inertia_.resize(slots);
  body_[wall] = Body{}, body_step_[wall] = BodyStep{};
  inverse_mass_[wall] = inverse_inertia_[wall] = 0.0;
#pragma omp parallel if (threads)
  {
    // The bodies in contact in the order of their first contact, and each movable body's first
    // contact in colour order (bit 0: of A, bit 1: of B): one thread, while the others ...
#pragma omp single nowait
    {
      seen_.assign(slots, 0);
      first_.assign(order.size(), 0);
      touched_.clear(), moving_.clear();
      for (std::size_t k = 0; k < order.size(); ++k) {
        const auto [a, b] = ends_[static_cast<std::size_t>(order[k])];
        for (const int i : {a, b}) {
          if (i < 0 || seen_[i]) continue;
          seen_[i] = 1;
          touched_.push_back(i);
          if (movable_[i]) moving_.push_back(i), first_[k] |= i == a ? 1 : 2;
        }
      }
    }
    // ... fill the lanes of colour g's Wides with its contacts in order, those of the overflow
    // one to a Wide (k = -1: an empty lane).
    for (int g = 0; g < groups; ++g) {
      const int begin = colours_.start(g), end = colours_.start(g + 1);
      const bool overflow = colours_.is_overflow(g);
#pragma omp for schedule(dynamic, 64) nowait
      for (int w = wide_start_[g]; w < wide_start_[g + 1]; ++w) {
        for (int l = 0; l < lanes; ++l) {
          const int k = overflow ? (l == 0 ? begin + w - wide_start_[g] : end)
                                 : begin + lanes * (w - wide_start_[g]) + l;
          lane_contact_[static_cast<std::size_t>(lanes * w + l)] = k < end ? k : -1;
        }
      }
    }
  }
  const int touched = static_cast<int>(touched_.size()), moving = static_cast<int>(moving_.size());
  saved_position_.resize(moving_.size()), saved_velocity_.resize(moving_.size());
  saved_angle_.resize(moving_.size()), saved_spin_.resize(moving_.size());
  mid_velocity_.resize(slots), mid_spin_.resize(slots);
  energy_.resize(moving_.size());
#pragma omp parallel if (threads)
  {
#pragma omp for schedule(static) nowait
    for (int m = 0; m < moving; ++m) {
      const int i = moving_[static_cast<std::size_t>(m)];
      saved_position_[m] = bodies.position[i], saved_velocity_[m] = bodies.velocity[i];
      saved_angle_[m] = bodies.angle[i], saved_spin_[m] = bodies.angular_velocity[i];
    }
#pragma omp for schedule(static)
    for (int m = 0; m < touched; ++m) {
      const int i = touched_[static_cast<std::size_t>(m)];
      // Back to the pose the interval started from, the velocity before the forces, and the
      // forces' share of each sub-step.
      const double h = intervals[i], substeps = config_.substeps;  // [s], [-]
      BodyStep& s = body_step_[i];
      Body& b = body_[i];
      s.gain = (bodies.velocity[i] - start.linear[i]) / substeps;
      s.spin_gain = (bodies.angular_velocity[i] - start.angular[i]) / substeps;
      b.velocity = start.linear[i];
      b.spin = start.angular[i];
      b.shift = start_pose.position[i] - bodies.position[i];
      s.turn = start_pose.angle[i] - bodies.angle[i];
      b.rotation = {std::cos(s.turn), std::sin(s.turn)};
      s.step = h / config_.substeps;
      inverse_mass_[i] = masses.inverse_mass[i];
      inverse_inertia_[i] = masses.inverse_inertia[i];
    }
#pragma omp for schedule(static)
    for (int w = 0; w < wides; ++w) {
      Wide& c = wide_[w];
      WideBlock& block = block_[w];
      std::array<WideStart, 2>& first = start_[w];
      c = Wide{}, block = WideBlock{}, first = {};
      if (w + ahead < wides)
        fetch_lanes(contacts, order, &lane_contact_[lanes * (w + ahead)], false);
      for (int l = 0; l < lanes; ++l) {
        const std::size_t lane = static_cast<std::size_t>(l);
        const int k = lane_contact_[static_cast<std::size_t>(lanes * w + l)];
        c.a[lane] = c.b[lane] = wall;  // an empty lane
        if (k < 0) continue;
        const ContactConstraint& src = contacts[static_cast<std::size_t>(order[k])];
        const int a = src.a, b = src.b >= 0 ? src.b : wall;
        c.a[lane] = a, c.b[lane] = b;
        c.block[l] = src.use_block ? -1 : 0;
        c.first_of_a[l] = first_[k] & 1 ? -1 : 0;
        c.first_of_b[l] = first_[k] & 2 ? -1 : 0;
        c.movable_a[l] = movable_[a] ? -1 : 0, c.movable_b[l] = movable_[b] ? -1 : 0;
        c.nx[l] = src.normal.x(), c.ny[l] = src.normal.y();
        c.friction[l] = src.friction;
        c.inverse_mass_a[l] = masses.inverse_mass[a];
        c.inverse_inertia_a[l] = masses.inverse_inertia[a];
        c.inverse_mass_b[l] = src.b >= 0 ? masses.inverse_mass[b] : 0.0;
        c.inverse_inertia_b[l] = src.b >= 0 ? masses.inverse_inertia[b] : 0.0;
        block.k00[l] = src.K(0, 0), block.k01[l] = src.K(0, 1);
        block.k10[l] = src.K(1, 0), block.k11[l] = src.K(1, 1);
        block.m00[l] = src.normal_mass(0, 0), block.m01[l] = src.normal_mass(0, 1);
        block.m10[l] = src.normal_mass(1, 0), block.m11[l] = src.normal_mass(1, 1);
        const double h =
            src.b >= 0 ? std::max(intervals[src.a], intervals[src.b]) : intervals[src.a];  // [s]
        const double h_s = h / config_.substeps;                                           // [s]
        if (h_s > 0.0) {
          const double hertz = std::min(config_.contact_hertz, max_hertz_per_rate / h_s);  // [Hz]
          const double omega = 2.0 * pi * hertz;  // [rad/s]
          const double zeta = config_.damping_ratio;
          const double a_s = h_s * omega * (2.0 * zeta + h_s * omega);  // a [-]
          c.inverse_substep[l] = 1.0 / h_s;
          c.bias_rate[l] = omega / (2.0 * zeta + h_s * omega);
          c.mass_scale[l] = a_s / (1.0 + a_s);
          c.impulse_scale[l] = 1.0 / (1.0 + a_s);
        } else {  // no time to move: a rigid velocity solve
          c.inverse_substep[l] = c.bias_rate[l] = c.impulse_scale[l] = 0.0;
          c.mass_scale[l] = 1.0;
        }
        for (int p = 0; p < src.point_count; ++p) {
          const ContactPointConstraint& s = src.points[static_cast<std::size_t>(p)];
          WidePoint& q = c.points[p];
          c.point[p][l] = -1;
          q.r_ax[l] = s.r_a.x(), q.r_ay[l] = s.r_a.y();
          q.r_bx[l] = s.r_b.x(), q.r_by[l] = s.r_b.y();
          q.base_separation[l] = s.separation - src.normal.dot(s.r_a - s.r_b);
          q.normal_mass[l] = s.normal_mass;
          q.tangent_mass[l] = s.tangent_mass;
          q.normal_impulse[l] = s.first_impulse.x();  // for sub-step 0
          q.tangent_impulse[l] = s.first_impulse.y();
          WideStart& f = first[static_cast<std::size_t>(p)];
          f.later_normal[l] = s.last_impulse.x(), f.later_tangent[l] = s.last_impulse.y();
          f.approach[l] = s.approach_velocity;
          f.resting[l] = s.resting ? -1 : 0;
        }
      }
    }
  }
}

// Body i's pose moves by h_s u; (cos, sin) turned.
void SoftStep::move_pose(int i) {
  Body& b = body_[i];
  BodyStep& s = body_step_[i];
  const double h = s.step, turn = h * b.spin;  // [s], [rad]
  b.shift += h * b.velocity;
  s.turn += turn;
  const Vec2 q = b.rotation + turn * perp(b.rotation);
  b.rotation = q / q.norm();
}

// The relax iteration of sub-step `substep` at wide_[w], its bodies' poses moved first; its
// impulses join the interval's.
void SoftStep::relax(std::size_t w, int substep) {
  Wide& c = wide_[w];
  for (int l = 0; l < lanes; ++l) {  // before any contact of the body reads its pose
    if (c.first_of_a[l]) move_pose(c.a[static_cast<std::size_t>(l)]);
    if (c.first_of_b[l]) move_pose(c.b[static_cast<std::size_t>(l)]);
  }
  soft_solve(c, block_[w], body_.data(), false);
  for (int p = 0; p < 2; ++p) {
    WidePoint& q = c.points[p];
    const Mask m = widen(c.point[p]);
    q.total_normal = m ? q.total_normal + q.normal_impulse : q.total_normal;
    q.total_tangent = m ? q.total_tangent + q.tangent_impulse : q.total_tangent;
    if (substep == 0) {
      WideStart& s = start_[w][static_cast<std::size_t>(p)];
      s.first_normal = q.normal_impulse, s.first_tangent = q.tangent_impulse;
      // Sub-step 1 starts from the last interval's last sub-step.
      if (config_.substeps > 1)
        q.normal_impulse = s.later_normal, q.tangent_impulse = s.later_tangent;
    }
  }
}

// Moving body m's kinetic energies before the contacts, after the compression and at the end,
// and its share of E(s) (restitution_energy.hpp).
SoftStep::BodyEnergy SoftStep::body_energy(int m) const {
  const auto k = static_cast<std::size_t>(m);
  const int i = moving_[k];
  const double w = inverse_mass_[i], w_i = inverse_inertia_[i];
  const Body& b = body_[i];
  return {solver_kinetic_energy(saved_velocity_[k], saved_spin_[k], w, w_i),
          solver_kinetic_energy(mid_velocity_[i], mid_spin_[i], w, w_i),
          solver_kinetic_energy(b.velocity, b.spin, w, w_i),
          restitution_terms(mid_velocity_[i], mid_spin_[i], b.velocity, b.spin, w, w_i)};
}

// Newton's law with friction may gain energy (restitution_energy.hpp): when the bodies end with
// more kinetic energy than they came with, the restitution's change is cut to the fraction that
// gives back e^2 of what the compression took. The step's moving bodies are taken together, their
// energies (body_energy(), found in parallel) summed in their order.
void SoftStep::bound_restitution() {
  constexpr double round_off = 1e-12;         // [-] relative energy change taken for rounding
  double before = 0.0, mid = 0.0, end = 0.0;  // [J]
  RestitutionEnergy change;
  for (const BodyEnergy& e : energy_) {
    before += e.before, mid += e.mid, end += e.end;
    change.add(e.change);
  }
  if (end <= before * (1.0 + round_off)) return;
  const double s = change.fraction(before, mid, config_.restitution);  // [-]
  for (const int i : moving_) {
    Body& b = body_[i];
    b.velocity = mid_velocity_[i] + s * (b.velocity - mid_velocity_[i]);
    b.spin = mid_spin_[i] + s * (b.spin - mid_spin_[i]);
  }
}

// The impulses go back to the contacts (warm start of the next interval, reports), the
// velocities and the poses to the bodies: x = x_1 + D, theta = theta_1 + Theta.
void SoftStep::store(std::vector<ContactConstraint>& contacts, BodySet& bodies, bool threads) {
  const std::vector<int>& order = colours_.order();
  const int wides = static_cast<int>(wide_.size()), moving = static_cast<int>(moving_.size());
#pragma omp parallel if (threads)
  {
#pragma omp for schedule(static) nowait
    for (int w = 0; w < wides; ++w) {
      const Wide& c = wide_[static_cast<std::size_t>(w)];
      if (w + ahead < wides)
        fetch_lanes(contacts, order, &lane_contact_[lanes * (w + ahead)], true);
      for (int l = 0; l < lanes; ++l) {
        const int k = lane_contact_[static_cast<std::size_t>(lanes * w + l)];
        if (k < 0) continue;
        ContactConstraint& dst = contacts[static_cast<std::size_t>(order[k])];
        for (int p = 0; p < dst.point_count; ++p) {
          const WidePoint& q = c.points[p];
          const WideStart& s = start_[static_cast<std::size_t>(w)][static_cast<std::size_t>(p)];
          ContactPointConstraint& d = dst.points[static_cast<std::size_t>(p)];
          d.normal_impulse = q.total_normal[l];
          d.tangent_impulse = q.total_tangent[l];
          d.first_impulse = {s.first_normal[l], s.first_tangent[l]};
          d.last_impulse = {q.normal_impulse[l], q.tangent_impulse[l]};
        }
      }
    }
#pragma omp for schedule(static)
    for (int m = 0; m < moving; ++m) {
      const int i = moving_[static_cast<std::size_t>(m)];
      const Body& b = body_[i];
      bodies.velocity[i] = b.velocity;
      bodies.angular_velocity[i] = b.spin;
      bodies.position[i] += b.shift;
      bodies.angle[i] += body_step_[i].turn;
    }
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
