#pragma once
// Box2D v2.4's contact solver (impulse_solver.hpp) behind the ContactSolver interface: each
// island's velocity sweeps until they settle, the islands in parallel; the poses of the bodies a
// contact pushed put at x_0 + h u_after (x_0 where the interval started); then the position stage
// per island.
#include "contact/contact_solver.hpp"

namespace flotsam {

class SequentialImpulses final : public ContactSolver {
 public:
  explicit SequentialImpulses(const ContactConfig& config) : config_(config) {}

  double margin_in_slops() const override { return 2.0; }
  int solve(std::vector<ContactConstraint>& contacts, const Islands& islands, BodySet& bodies,
            const SolverMasses& masses, const std::vector<double>& intervals,
            const BodyVelocities& start, const BodyPoses& start_pose) override;
  void undo(BodySet& bodies) override;
  double correct_positions(std::vector<ContactConstraint>& contacts, const Islands& islands,
                           BodySet& bodies, const SolverMasses& masses) override;

 private:
  ContactConfig config_;
  // The bodies of the last solve's contacts (moved_, marked in touched_) and, for them only,
  // what undo() puts back: a small group's solve costs its own size, not the body count.
  std::vector<int> moved_;
  std::vector<char> touched_;
  std::vector<Vec2> velocity_before_;            // [m/s]
  std::vector<double> angular_velocity_before_;  // [rad/s]
  BodyPoses pose_before_;                        // x [m], theta [rad]
  std::vector<char> pushed_;                     // 1: a contact of the body carries an impulse
};

}  // namespace flotsam
