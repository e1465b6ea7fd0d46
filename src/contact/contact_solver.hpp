#pragma once
// The solver stage of the contact pipeline (contact_world.hpp), chosen by
// `bodies.contact.solver` (docs/case-format.md): it takes the detected and prepared contacts
// (prepare_contacts in impulse_solver.hpp: effective masses, approach velocities, warm-start
// impulses) and resolves them, on bodies that have just been moved over their interval h_i with
// their velocities before the contacts.
//
//   sequential_impulses  Box2D v2.4: Gauss-Seidel sweeps on the velocities per island, the pushed
//                        bodies' poses put at x_0 + h u_after (x_0: the interval's start), then
//                        a position stage (sequential_impulses.hpp).
//   soft_step            Box2D v3: sub-steps with soft contacts, relaxed, restitution last, all
//                        contacts at once in colours (soft_step.hpp).
#include <memory>
#include <vector>

#include "bodies/body_set.hpp"
#include "contact/impulse_solver.hpp"
#include "contact/islands.hpp"
#include "io/case.hpp"

namespace flotsam {

class ContactSolver {
 public:
  virtual ~ContactSolver() = default;

  /// The detection margin in slops (allowed_overlap times the thinner width): gaps up to it are
  /// detected, as speculative contacts; a solve that moves a body further is done again with its
  /// margin grown (ContactWorld::step).
  virtual double margin_in_slops() const = 0;

  /// Resolves `contacts` (grouped by `islands`): new velocities, and poses moved over
  /// intervals[i] accordingly, from `start_pose`, the poses the bodies had at the start of their
  /// interval. `start` holds the velocities they had then, before its forces (the present ones
  /// where not known). Returns the most velocity sweeps a group of contacts took.
  virtual int solve(std::vector<ContactConstraint>& contacts, const Islands& islands,
                    BodySet& bodies, const SolverMasses& masses,
                    const std::vector<double>& intervals, const BodyVelocities& start,
                    const BodyPoses& start_pose) = 0;

  /// Puts back the velocities and poses the last solve() started from.
  virtual void undo(BodySet& bodies) = 0;

  /// What is done about the overlaps left after solve(); returns the largest overlap [m].
  virtual double correct_positions(std::vector<ContactConstraint>& contacts, const Islands& islands,
                                   BodySet& bodies, const SolverMasses& masses) = 0;
};

std::unique_ptr<ContactSolver> make_contact_solver(const ContactConfig& config);

}  // namespace flotsam
