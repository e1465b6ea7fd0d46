#include "contact/impulse_solver.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "contact/restitution_energy.hpp"
#include "core/parallel_for.hpp"

namespace flotsam {
namespace {

constexpr double position_stiffness = 0.2;  // beta [-]: fraction of an overlap removed per sweep
                                            // (Box2D's Baumgarte factor); 1 overshoots
constexpr double max_correction_fraction = 0.25;  // [-] largest move per sweep, of the thinner
                                                  // width (guards against far jumps)
constexpr double max_condition_number = 1000.0;   // [-] of the 2x2 block (Box2D's choice)

// Velocity of body i's material point at offset r from G; zero for a wall (i < 0).
Vec2 point_velocity(const BodySet& bodies, int i, const Vec2& r) {
  if (i < 0) return Vec2::Zero();
  return bodies.velocity[i] + bodies.angular_velocity[i] * perp(r);
}

// Applies the impulse P at offset r_a to A and -P at offset r_b to B.       (M-9)
void apply_impulse(BodySet& bodies, const SolverMasses& masses, const ContactConstraint& c,
                   const Vec2& r_a, const Vec2& r_b, const Vec2& P) {
  bodies.velocity[c.a] += masses.inverse_mass[c.a] * P;
  bodies.angular_velocity[c.a] += masses.inverse_inertia[c.a] * cross(r_a, P);
  if (c.b >= 0) {
    bodies.velocity[c.b] -= masses.inverse_mass[c.b] * P;
    bodies.angular_velocity[c.b] -= masses.inverse_inertia[c.b] * cross(r_b, P);
  }
}

// 1/K for direction d at offsets r_a, r_b: K = 1/m_A + 1/m_B + (r_A x d)^2/I_A + (r_B x d)^2/I_B.
double effective_mass(const SolverMasses& m, const ContactConstraint& c, const Vec2& r_a,
                      const Vec2& r_b, const Vec2& d) {
  double K = m.inverse_mass[c.a] + m.inverse_inertia[c.a] * std::pow(cross(r_a, d), 2);
  if (c.b >= 0) K += m.inverse_mass[c.b] + m.inverse_inertia[c.b] * std::pow(cross(r_b, d), 2);
  return K > 0.0 ? 1.0 / K : 0.0;
}

double normal_velocity(const BodySet& bodies, const ContactConstraint& c,
                       const ContactPointConstraint& p) {
  return (point_velocity(bodies, c.a, p.r_a) - point_velocity(bodies, c.b, p.r_b)).dot(c.normal);
}

// How far body i's material point at offset r from G has moved since `start`, to first order in
// the turn (as its velocity u + omega k x r); zero for a wall (i < 0).
Vec2 point_move(const BodySet& bodies, const BodyPoses& start, int i, const Vec2& r) {
  if (i < 0) return Vec2::Zero();
  return bodies.position[i] - start.position[i] + (bodies.angle[i] - start.angle[i]) * perp(r);
}

// Friction at each point: the tangential impulse that stops sliding, accumulated and kept in
// the Coulomb cone |j_t| <= mu_c j_n. Returns the largest velocity change [m/s].
double solve_friction(ContactConstraint& c, BodySet& bodies, const SolverMasses& masses) {
  const Vec2 tangent = -perp(c.normal);
  double change = 0.0;
  for (int k = 0; k < c.point_count; ++k) {
    ContactPointConstraint& p = c.points[static_cast<std::size_t>(k)];
    const Vec2 dv = point_velocity(bodies, c.a, p.r_a) - point_velocity(bodies, c.b, p.r_b);
    const double bound = c.friction * p.normal_impulse;  // [N s]
    const double updated =
        std::clamp(p.tangent_impulse - p.tangent_mass * dv.dot(tangent), -bound, bound);
    const double lambda = updated - p.tangent_impulse;
    p.tangent_impulse = updated;
    apply_impulse(bodies, masses, c, p.r_a, p.r_b, lambda * tangent);
    if (p.tangent_mass > 0.0) change = std::max(change, std::abs(lambda) / p.tangent_mass);
  }
  return change;
}

// One point: j = -(v_n - v*)/K, accumulated impulse clamped to >= 0.
double solve_normal_point(ContactConstraint& c, ContactPointConstraint& p, BodySet& bodies,
                          const SolverMasses& masses) {
  const double vn = normal_velocity(bodies, c, p);
  const double updated = std::max(p.normal_impulse - p.normal_mass * (vn - p.target_velocity), 0.0);
  const double lambda = updated - p.normal_impulse;
  p.normal_impulse = updated;
  apply_impulse(bodies, masses, c, p.r_a, p.r_b, lambda * c.normal);
  return p.normal_mass > 0.0 ? std::abs(lambda) / p.normal_mass : 0.0;
}

// Two points at once (Box2D v2.4 block solver). With x the new accumulated impulses and
// b = v_n - v* - K a (a: the old ones), find x >= 0 with w = K x + b >= 0 and x_i w_i = 0 by
// trying the four cases: both active, only 1, only 2, none.
double solve_normal_block(ContactConstraint& c, BodySet& bodies, const SolverMasses& masses) {
  ContactPointConstraint &p1 = c.points[0], &p2 = c.points[1];
  const Vec2 a(p1.normal_impulse, p2.normal_impulse);
  const Vec2 vn(normal_velocity(bodies, c, p1), normal_velocity(bodies, c, p2));
  const Vec2 b = vn - Vec2(p1.target_velocity, p2.target_velocity) - c.K * a;
  Vec2 x = -(c.normal_mass * b);
  if (!(x.x() >= 0.0 && x.y() >= 0.0)) {
    x = Vec2(-b.x() / c.K(0, 0), 0.0);
    if (!(x.x() >= 0.0 && c.K(1, 0) * x.x() + b.y() >= 0.0)) {
      x = Vec2(0.0, -b.y() / c.K(1, 1));
      if (!(x.y() >= 0.0 && c.K(0, 1) * x.y() + b.x() >= 0.0)) {
        x = Vec2::Zero();
        if (!(b.x() >= 0.0 && b.y() >= 0.0)) x = a;  // no case holds (degenerate): keep a
      }
    }
  }
  const Vec2 d = x - a;
  apply_impulse(bodies, masses, c, p1.r_a, p1.r_b, d.x() * c.normal);
  apply_impulse(bodies, masses, c, p2.r_a, p2.r_b, d.y() * c.normal);
  p1.normal_impulse = x.x();
  p2.normal_impulse = x.y();
  return std::max(std::abs(d.x()) * c.K(0, 0), std::abs(d.y()) * c.K(1, 1));
}

Frame body_frame(const BodySet& bodies, int i) {
  if (i < 0) return {};
  return {bodies.position[i], bodies.axis(i)};
}

}  // namespace

SolverMasses make_solver_masses(const BodySet& bodies, const ContactConfig& config,
                                double added_mass_coefficient) {
  SolverMasses m;
  std::vector<int> all(static_cast<std::size_t>(bodies.size()));
  std::iota(all.begin(), all.end(), 0);
  set_solver_masses(m, bodies, config, added_mass_coefficient, all);
  return m;
}

void set_solver_masses(SolverMasses& m, const BodySet& bodies, const ContactConfig& config,
                       double added_mass_coefficient, std::span<const int> listed) {
  const auto n = static_cast<std::size_t>(bodies.size());
  m.inverse_mass.resize(n, 0.0);
  m.inverse_inertia.resize(n, 0.0);
  for (const int i : listed) {
    m.inverse_mass[i] = m.inverse_inertia[i] = 0.0;
    if (bodies.state[i] == BodyState::gone || bodies.anchored[i]) continue;  // immovable: 1/m = 0
    // A floating body displaces its own mass (m_f = m_p, spec 2): added mass C_a m_p (M-5).
    const bool add = config.added_mass_in_contact && bodies.state[i] == BodyState::floating;
    const double factor = add ? 1.0 + added_mass_coefficient : 1.0;  // [-]
    m.inverse_mass[i] = 1.0 / (factor * bodies.mass[i]);
    m.inverse_inertia[i] = 1.0 / (factor * bodies.inertia[i]);
  }
}

void prepare_contacts(std::span<ContactConstraint> contacts, const BodySet& bodies,
                      const SolverMasses& masses, const ContactConfig& config,
                      const std::vector<double>& intervals, const BodyPoses& start) {
  // Each contact on its own: in parallel, the same on any number of threads.
  const auto count = static_cast<std::ptrdiff_t>(contacts.size());
  auto prepare = [&](std::ptrdiff_t m) {
    ContactConstraint& c = contacts[static_cast<std::size_t>(m)];
    const double interval = c.b >= 0 ? std::max(intervals[c.a], intervals[c.b]) : intervals[c.a];
    const Vec2 tangent = -perp(c.normal);
    for (int k = 0; k < c.point_count; ++k) {
      ContactPointConstraint& p = c.points[static_cast<std::size_t>(k)];
      p.normal_mass = effective_mass(masses, c, p.r_a, p.r_b, c.normal);
      p.tangent_mass = effective_mass(masses, c, p.r_a, p.r_b, tangent);
      p.approach_velocity = normal_velocity(bodies, c, p);
      // The separation where the interval started, s_0 = s - (what the free move closed): a
      // pushed body's pose is put at x_0 + h u after the solve (sequential_impulses.cpp), so
      // s_0 + h v_n.
      // A gap still open after the free move may close by no more than it (nor than s_0): a
      // body approaching it ends the interval short of the face by what the free move closed,
      // and closes the rest in the next one (letting it close s_0 at once left fast-turning
      // logs up to 1.5 % of their width deep in a pier: the turn is linearised).
      const double opened =
          (point_move(bodies, start, c.a, p.r_a) - point_move(bodies, start, c.b, p.r_b))
              .dot(c.normal);                                 // [m] by the free move
      const double start_separation = p.separation - opened;  // s_0 [m]
      const double closable =
          p.separation > 0.0 ? std::min(p.separation, start_separation) : start_separation;  // [m]
      if (p.separation <= 0.0 && !p.resting &&
          p.approach_velocity < -config.restitution_threshold) {
        p.target_velocity = -config.restitution * p.approach_velocity;  // v* = -e v_n^0 (M-9)
      } else {  // a gap may close within the interval, not faster; a touching point is held
        p.target_velocity = interval > 0.0 ? -std::max(closable, 0.0) / interval : 0.0;
      }
    }
    c.use_block = false;
    if (c.point_count == 2) {
      const auto& p1 = c.points[0];
      const auto& p2 = c.points[1];
      const double k11 = 1.0 / p1.normal_mass, k22 = 1.0 / p2.normal_mass;
      double k12 = masses.inverse_mass[c.a] +
                   masses.inverse_inertia[c.a] * cross(p1.r_a, c.normal) * cross(p2.r_a, c.normal);
      if (c.b >= 0) {
        k12 += masses.inverse_mass[c.b] +
               masses.inverse_inertia[c.b] * cross(p1.r_b, c.normal) * cross(p2.r_b, c.normal);
      }
      c.K << k11, k12, k12, k22;
      if (k11 * k11 < max_condition_number * (k11 * k22 - k12 * k12)) {
        c.use_block = true;
        c.normal_mass = c.K.inverse();
      }
    }
  };
  parallel_for(count, std::ptrdiff_t{2000}, prepare);  // [-] threads from a few thousand
}

void warm_start_contacts(std::span<const ContactConstraint> contacts, BodySet& bodies,
                         const SolverMasses& masses) {
  for (const ContactConstraint& c : contacts) {
    const Vec2 tangent = -perp(c.normal);
    for (int k = 0; k < c.point_count; ++k) {
      const ContactPointConstraint& p = c.points[static_cast<std::size_t>(k)];
      apply_impulse(bodies, masses, c, p.r_a, p.r_b,
                    p.normal_impulse * c.normal + p.tangent_impulse * tangent);
    }
  }
}

namespace {

// The sweeps of solve_contact_velocities; without friction, the normal impulses alone.
int sweep_velocities(std::span<ContactConstraint> contacts, BodySet& bodies,
                     const SolverMasses& masses, const ContactConfig& config, bool friction) {
  int sweep = 0;
  while (sweep < config.iterations) {
    ++sweep;
    double change = 0.0;  // largest velocity change of a point in this sweep [m/s]
    for (ContactConstraint& c : contacts) {
      if (c.use_block) {
        change = std::max(change, solve_normal_block(c, bodies, masses));
      } else {
        for (int k = 0; k < c.point_count; ++k) {
          change = std::max(
              change, solve_normal_point(c, c.points[static_cast<std::size_t>(k)], bodies, masses));
        }
      }
      if (friction) change = std::max(change, solve_friction(c, bodies, masses));
    }
    if (change <= config.velocity_tolerance) break;
  }
  return sweep;
}

// A struck point: in contact, with the restitution target v* = -e v_n^0 > 0.
bool struck(const ContactPointConstraint& p) {
  return p.separation <= 0.0 && p.target_velocity > 0.0;
}

}  // namespace

int solve_contact_velocities(std::span<ContactConstraint> contacts, BodySet& bodies,
                             const SolverMasses& masses, const ContactConfig& config) {
  return sweep_velocities(contacts, bodies, masses, config, true);
}

int solve_contact_island(std::span<ContactConstraint> island, BodySet& bodies,
                         const SolverMasses& masses, const ContactConfig& config) {
  constexpr double round_off = 1e-12;  // [-] relative energy change taken for rounding
  bool any_struck = false;
  for (const ContactConstraint& c : island)
    for (int k = 0; k < c.point_count; ++k) any_struck |= struck(c.points[k]);
  if (!any_struck) {  // no restitution target: Newton's law cannot add energy (resting contacts)
    warm_start_contacts(island, bodies, masses);
    return solve_contact_velocities(island, bodies, masses, config);
  }
  std::vector<int> members;
  for (const ContactConstraint& c : island) {
    members.push_back(c.a);
    if (c.b >= 0) members.push_back(c.b);
  }
  std::sort(members.begin(), members.end());
  members.erase(std::unique(members.begin(), members.end()), members.end());
  const std::size_t n = members.size();
  std::vector<Vec2> u0(n), u_mid(n);    // [m/s]
  std::vector<double> w0(n), w_mid(n);  // [rad/s]
  auto energy = [&] {                   // [J]
    double total = 0.0;
    for (const int i : members)
      total += solver_kinetic_energy(bodies.velocity[i], bodies.angular_velocity[i],
                                     masses.inverse_mass[i], masses.inverse_inertia[i]);
    return total;
  };
  for (std::size_t m = 0; m < n; ++m)
    u0[m] = bodies.velocity[members[m]], w0[m] = bodies.angular_velocity[members[m]];
  std::vector<std::array<ContactPointConstraint, 2>> start;  // the points as they came
  for (const ContactConstraint& c : island) start.push_back(c.points);
  const double e0 = energy();
  warm_start_contacts(island, bodies, masses);
  int sweeps = solve_contact_velocities(island, bodies, masses, config);
  if (energy() <= e0 * (1.0 + round_off)) return sweeps;
  // Newton's law gained energy: compression (struck points brought to v_n = 0, with friction),
  // then restitution (normal impulses only), kept within the bound (restitution_energy.hpp).
  for (std::size_t m = 0; m < n; ++m)
    bodies.velocity[members[m]] = u0[m], bodies.angular_velocity[members[m]] = w0[m];
  for (std::size_t k = 0; k < island.size(); ++k) {
    island[k].points = start[k];
    for (ContactPointConstraint& p : island[k].points)
      if (struck(p)) p.target_velocity = 0.0;
  }
  warm_start_contacts(island, bodies, masses);
  sweeps += solve_contact_velocities(island, bodies, masses, config);
  const double e_mid = energy();
  for (std::size_t m = 0; m < n; ++m)
    u_mid[m] = bodies.velocity[members[m]], w_mid[m] = bodies.angular_velocity[members[m]];
  std::vector<std::array<double, 2>> j_mid;  // [N s]
  for (std::size_t k = 0; k < island.size(); ++k) {
    j_mid.push_back({island[k].points[0].normal_impulse, island[k].points[1].normal_impulse});
    for (std::size_t q = 0; q < 2; ++q)
      island[k].points[q].target_velocity = start[k][q].target_velocity;
  }
  sweeps += sweep_velocities(island, bodies, masses, config, false);
  RestitutionEnergy change;
  for (std::size_t m = 0; m < n; ++m) {
    const int i = members[m];
    change.add(u_mid[m], w_mid[m], bodies.velocity[i], bodies.angular_velocity[i],
               masses.inverse_mass[i], masses.inverse_inertia[i]);
  }
  const double s = change.fraction(e0, e_mid, config.restitution);  // [-]
  for (std::size_t m = 0; m < n; ++m) {
    const int i = members[m];
    bodies.velocity[i] = u_mid[m] + s * (bodies.velocity[i] - u_mid[m]);
    bodies.angular_velocity[i] = w_mid[m] + s * (bodies.angular_velocity[i] - w_mid[m]);
  }
  for (std::size_t k = 0; k < island.size(); ++k) {
    for (std::size_t q = 0; q < 2; ++q) {
      double& j = island[k].points[q].normal_impulse;
      j = j_mid[k][q] + s * (j - j_mid[k][q]);
    }
  }
  return sweeps;
}

double correct_contact_positions(std::span<const ContactConstraint> contacts, BodySet& bodies,
                                 const SolverMasses& masses, const ContactConfig& config) {
  double worst = 0.0;  // largest overlap measured in the last sweep [m]
  for (int sweep = 0; sweep < config.position_iterations; ++sweep) {
    worst = 0.0;
    bool settled = true;  // every overlap within 1.5 times its slop
    for (const ContactConstraint& c : contacts) {
      const int reference = c.reference_on_a ? c.a : c.b;
      const int incident = c.reference_on_a ? c.b : c.a;
      const double max_correction = max_correction_fraction * c.width;  // [m]
      for (int k = 0; k < c.point_count; ++k) {
        const ContactPointConstraint& p = c.points[static_cast<std::size_t>(k)];
        // Re-measure s from the current poses: the incident point against the reference face.
        const Frame ref = body_frame(bodies, reference), inc = body_frame(bodies, incident);
        const Vec2 n_ref = ref.rotate(c.local_normal);
        const Vec2 x = inc.to_world(p.local_incident);
        const double s = (x - ref.to_world(c.local_plane_point)).dot(n_ref);
        const Vec2 n = c.reference_on_a ? Vec2(-n_ref) : n_ref;  // from B towards A
        worst = std::max(worst, -s);
        if (s < -1.5 * c.slop) settled = false;
        // C = beta (s + slop) in [-max_correction, 0]; pseudo-impulse -C/K along n.
        const double C = std::clamp(position_stiffness * (s + c.slop), -max_correction, 0.0);
        const Vec2 r_a = x - bodies.position[c.a];
        const Vec2 r_b = c.b >= 0 ? Vec2(x - bodies.position[c.b]) : Vec2::Zero();
        const Vec2 P = -C * effective_mass(masses, c, r_a, r_b, n) * n;
        bodies.position[c.a] += masses.inverse_mass[c.a] * P;
        bodies.angle[c.a] += masses.inverse_inertia[c.a] * cross(r_a, P);
        if (c.b >= 0) {
          bodies.position[c.b] -= masses.inverse_mass[c.b] * P;
          bodies.angle[c.b] -= masses.inverse_inertia[c.b] * cross(r_b, P);
        }
      }
    }
    if (settled) break;
  }
  return worst;
}

}  // namespace flotsam
