#pragma once
// Impulse response (spec 4.3): sequential impulses over all contacts, then a position
// correction. Box2D v2.4's contact solver, with the spec's (M-9) as its one-contact case.
//
// Velocity stage. At a contact point M with r_A = M - G_A, r_B = M - G_B and normal n (B -> A):
//
//   v_n = [ (u_A + omega_A k x r_A) - (u_B + omega_B k x r_B) ] . n                  (M-9), (P-25)
//   K   = 1/m_A + 1/m_B + (r_A x n)^2 / I_A + (r_B x n)^2 / I_B
//
// The impulse j n that brings v_n to the target v* is j = -(v_n - v*) / K. A pushed body's pose
// will be put at x_0 + h u (x_0: where the interval h started, sequential_impulses.cpp), so the
// target is set from the separation there, s_0 = s - n . (d_A - d_B), the detected s less what
// the free move closed (d: the point's move since x_0):
//
//   s > 0 (a gap, within the detection margin):  v* = -max(min(s, s_0), 0) / h   (speculative:
//          it may close during the interval, no faster, and is never held open)
//   s <= 0, a new impact approaching faster than the restitution threshold:  v* = -e v_n^0
//   s <= 0 otherwise (resting: the point carried an impulse last interval, or a slow approach):
//          v* = -max(s_0, 0) / h   (held where it is, or brought to the face it crossed)
//
// with v_n^0 the normal velocity before the solve. For one new contact starting from
// v_n = v_n^0 this is (M-9)'s j = -(1 + e) v_n^0 / K. Restitution is never applied to a resting
// contact, whatever e: a jam pushed by a steady drag approaches its supports by F h / m every
// interval, and with e = 1 it would bounce off them for ever. With many contacts each point's j is
// accumulated over sweeps and the running sum clamped to >= 0 (contacts push, never pull) until the
// normal velocities settle. When an island so solved gains kinetic energy (Newton's law with
// friction can), its restitution is bounded by the energy the compression took
// (restitution_energy.hpp, solve_contact_island). Two-point manifolds are solved as one 2x2
// complementarity problem (block solver), so that parallel logs do not converge slowly through
// their nearly dependent rows. Friction: the tangential impulse accumulated at each point stays
// within +- mu_c times its normal impulse.
//
// Position stage (non-linear Gauss-Seidel). The separation s of each point is re-measured from
// the current poses; a pseudo-impulse -C/K along n, C = beta (s + slop) clamped to
// [-max_correction, 0], moves the two bodies apart. It changes positions and angles only, never
// velocities, so it adds no kinetic energy.
#include <array>
#include <span>
#include <vector>

#include "bodies/body_set.hpp"
#include "contact/contact_geometry.hpp"
#include "io/case.hpp"

namespace flotsam {

struct ContactPointConstraint {
  Vec2 r_a = Vec2::Zero(), r_b = Vec2::Zero();  // M - G_A, M - G_B [m]
  double normal_mass = 0.0;                     // 1/K along n [kg]
  double tangent_mass = 0.0;                    // 1/K along the tangent [kg]
  double normal_impulse = 0.0;                  // accumulated j [N s]
  double tangent_impulse = 0.0;                 // accumulated friction impulse [N s]
  double approach_velocity = 0.0;               // v_n before the solve [m/s]
  double target_velocity = 0.0;                 // v* [m/s]
  double separation = 0.0;                      // s at detection [m]
  // Soft step (soft_step.hpp): the (normal, tangential) impulse of its first and of its last
  // sub-step [N s], to warm-start the same sub-steps of the next interval.
  Vec2 first_impulse = Vec2::Zero(), last_impulse = Vec2::Zero();
  Vec2 local_incident = Vec2::Zero();  // incident point, incident body frame [m]
  int feature = 0;
  bool resting = false;  // matched to a point of the last interval that carried an impulse
};

/// One manifold between body a and body b, or between body a and a wall segment (b = -1).
struct ContactConstraint {
  int a = -1, b = -1;           // body indices; b = -1 for a wall
  int segment = -1;             // wall segment index when b = -1
  Vec2 normal = Vec2::UnitX();  // n, unit, from B towards A
  int point_count = 0;
  std::array<ContactPointConstraint, 2> points;
  double friction = 0.0;  // mu_c [-]
  double slop = 0.0;      // overlap left uncorrected so that resting contacts persist [m]
  double width = 0.0;     // l of the thinner body (of A for a wall) [m]
  // Two-point block solver: K and its inverse, when well conditioned.
  bool use_block = false;
  Mat2 K = Mat2::Zero();            // [1/kg]
  Mat2 normal_mass = Mat2::Zero();  // K^-1 [kg]
  // Reference face in its body's frame, for the position stage.
  bool reference_on_a = true;
  Vec2 local_normal = Vec2::UnitX();
  Vec2 local_plane_point = Vec2::Zero();  // [m]
};

struct BodyVelocities {
  std::vector<Vec2> linear;     // u [m/s]
  std::vector<double> angular;  // omega [rad/s]
};

struct BodyPoses {
  std::vector<Vec2> position;  // x [m]
  std::vector<double> angle;   // theta [rad]
};

/// Inverse masses and inertias used by the solver (added mass included when configured).
struct SolverMasses {
  std::vector<double> inverse_mass;     // 1/m [1/kg], 0 for gone bodies
  std::vector<double> inverse_inertia;  // 1/I [1/(kg m^2)]
};

SolverMasses make_solver_masses(const BodySet& bodies, const ContactConfig& config,
                                double added_mass_coefficient);

/// The same for the `listed` bodies only, in `masses` sized to the body count (entries of bodies
/// not listed are left as they were, zero when new): a contact group's step costs its own size.
void set_solver_masses(SolverMasses& masses, const BodySet& bodies, const ContactConfig& config,
                       double added_mass_coefficient, std::span<const int> listed);

/// Fills the effective masses, approach and target velocities of every point; `intervals[i]` h
/// [s] is the time over which the solved velocities will move body i from `start[i]`, its pose
/// where the interval started (speculative target: the longer of the two bodies' h).
void prepare_contacts(std::span<ContactConstraint> contacts, const BodySet& bodies,
                      const SolverMasses& masses, const ContactConfig& config,
                      const std::vector<double>& intervals, const BodyPoses& start);

/// Applies the accumulated impulses the points start with (warm start from the last step).
void warm_start_contacts(std::span<const ContactConstraint> contacts, BodySet& bodies,
                         const SolverMasses& masses);

/// Sequential impulses until the largest change of a point's normal or tangential velocity in
/// a sweep is below config.velocity_tolerance, or config.iterations sweeps. Returns the number
/// of sweeps.
int solve_contact_velocities(std::span<ContactConstraint> contacts, BodySet& bodies,
                             const SolverMasses& masses, const ContactConfig& config);

/// One island's velocities: warm start, then solve_contact_velocities. When that gains kinetic
/// energy (Newton's law with friction, restitution_energy.hpp), the island is solved again from
/// its start in two passes, compression (struck points to v_n = 0, friction) then restitution
/// (normal impulses only), the restitution kept within e^2 of the energy the compression took.
/// Returns the number of sweeps.
int solve_contact_island(std::span<ContactConstraint> island, BodySet& bodies,
                         const SolverMasses& masses, const ContactConfig& config);

/// Non-linear Gauss-Seidel position correction, until every overlap is within 1.5 times its
/// slop or config.position_iterations sweeps; returns the largest overlap seen in the last
/// sweep [m].
double correct_contact_positions(std::span<const ContactConstraint> contacts, BodySet& bodies,
                                 const SolverMasses& masses, const ContactConfig& config);

}  // namespace flotsam
