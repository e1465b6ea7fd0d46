#pragma once
// The soft step (Box2D v3's solver: E. Catto, "Solver2D", box2d.org blog, 2024; soft constraints:
// E. Catto, "Soft Constraints", GDC 2011), behind the ContactSolver interface
// (`bodies.contact.solver: soft_step`). Equations: docs/model.md "Soft step".
//
// The bodies arrive moved over h with their velocities u^0 before the contacts. The interval is
// redone in n sub-steps of h_s = h / n from the poses it started from, each carried as a
// displacement D and a turn Theta from the detected pose (anchors: the separations follow the
// bodies within the interval without detecting again), D = -h u^0, Theta = -h omega^0 at the start:
//
//   for each sub-step: warm start (this sub-step's impulses of the last interval),
//                      solve (soft contacts, with bias), move the poses by h_s u, relax (no bias)
//   then restitution, once, at the points that were struck.
//
// Separation of a point with anchors r_A, r_B (at detection) and fixed normal n (B -> A):
//
//   s = s_1 + n . [ (D_A + R(Theta_A) r_A - r_A) - (D_B + R(Theta_B) r_B - r_B) ]           (S-1)
//
// Normal impulse per iteration at a point, with m = 1/K its effective mass and lambda its impulse
// in this sub-step so far (clamped so that the sum stays >= 0):
//
//   s > 0 (a gap):        d lambda = -m (v_n + s / h_s)                       (speculative)
//   s <= 0, solve:        d lambda = -m a/(1+a) (v_n - v*) - lambda / (1+a),               (S-2)
//                         v* = min(-b min(0, s + slop), v_max)
//   s <= 0, relax:        d lambda = -m v_n
//
// with omega = 2 pi f (f = contact_hertz, at most a quarter of the sub-step rate), zeta the
// damping ratio, a = h_s omega (2 zeta + h_s omega), b = omega / (2 zeta + h_s omega): a spring
// k = m omega^2 and damper c = 2 m zeta omega on the overlap, integrated implicitly over h_s. The
// relax iterations remove the velocity the bias added (the push-out moves the poses, it leaves no
// kinetic energy). Friction: |lambda_t| <= mu_c lambda_n per sub-step, no bias. Restitution
// (M-9), after the sub-steps, at a point that carried an impulse, was not resting and approached
// faster than the restitution threshold: v_n -> -e v_n^0.
//
// All contacts of the group are solved at once, colour by colour (contact_colours.hpp), the
// colours' contacts in parallel: the same result on any number of threads.
#include "contact/contact_colours.hpp"
#include "contact/contact_solver.hpp"
#include "contact/thread_choice.hpp"

namespace flotsam {

class SoftStep final : public ContactSolver {
 public:
  explicit SoftStep(const ContactConfig& config) : config_(config) {}

  /// Gaps up to 4 % of the thinner width are detected (Box2D v3's speculative distance, 2 cm,
  /// for logs 0.5 m wide): a jam still moving then rarely needs the second solve.
  double margin_in_slops() const override { return 16.0; }
  int solve(std::vector<ContactConstraint>& contacts, const Islands& islands, BodySet& bodies,
            const SolverMasses& masses, const std::vector<double>& intervals,
            const BodyVelocities& start) override;
  void undo(BodySet& bodies) override;
  /// Nothing left to do: the sub-steps pushed the overlaps out. Returns the largest overlap at
  /// the end of the last sub-step (S-1).
  double correct_positions(std::vector<ContactConstraint>&, const Islands&, BodySet&,
                           const SolverMasses&) override {
    return largest_overlap_;
  }

  struct Point {
    Vec2 r_a = Vec2::Zero(), r_b = Vec2::Zero();  // anchors from G_A, G_B at detection [m]
    double base_separation = 0.0;  // s_1 - n . (r_A - r_B) [m], so that (S-1) is one dot
    double normal_mass = 0.0, tangent_mass = 0.0;        // 1/K [kg]
    double approach = 0.0;                               // v_n^0 [m/s]
    double normal_impulse = 0.0, tangent_impulse = 0.0;  // lambda of this sub-step [N s]
    double total_normal = 0.0, total_tangent = 0.0;      // over the interval [N s]
    Vec2 first = Vec2::Zero();                           // (lambda_n, lambda_t) of sub-step 0 [N s]
    Vec2 later = Vec2::Zero();    // of the last interval's last sub-step: sub-step 1 starts there
    double largest_normal = 0.0;  // [N s] over the sub-steps
    bool resting = false;
  };
  struct Contact {
    int a = 0, b = 0;  // body slots; a wall is the slot after the last body
    int count = 0;
    Vec2 normal = Vec2::UnitX();
    double friction = 0.0, slop = 0.0;                 // mu_c [-], [m]
    double inverse_substep = 0.0;                      // 1 / h_s [1/s]
    double bias_rate = 0.0;                            // b [1/s]
    double mass_scale = 1.0, impulse_scale = 0.0;      // a/(1+a), 1/(1+a) [-]
    bool use_block = false;                            // two points relaxed and restituted at once
    bool first_of_a = false, first_of_b = false;       // the body's first contact in colour order
    Mat2 K = Mat2::Zero(), block_mass = Mat2::Zero();  // [1/kg], K^-1 [kg]
    std::array<Point, 2> points;
  };

 private:
  void prepare(const std::vector<ContactConstraint>& contacts, const BodySet& bodies,
               const SolverMasses& masses, const std::vector<double>& intervals,
               const BodyVelocities& start);
  void store(std::vector<ContactConstraint>& contacts, BodySet& bodies);
  void solve_contact(Contact& c, bool bias);
  void warm_start(Contact& c);
  void move_pose(int body);
  double restitute(Contact& c);
  void bound_restitution();
  template <class F>
  void each_colour(F&& f);

  ContactConfig config_;
  ContactColours colours_;
  ThreadChoice choice_;  // whether the colours are shared among the threads (same bits either way)
  std::vector<Contact> soft_;  // in colour order
  std::vector<int> source_;    // soft_[k] is contacts[source_[k]]
  // Per body slot (bodies.size() + 1, the last a wall): velocity, pose from the detected one.
  std::vector<Vec2> velocity_, shift_, rotation_;  // u [m/s], D [m], (cos, sin) Theta
  std::vector<double> spin_, turn_, step_;         // omega [rad/s], Theta [rad], h_s [s]
  std::vector<Vec2> gain_;                         // the forces' velocity per sub-step [m/s]
  std::vector<double> spin_gain_;                  // [rad/s]
  std::vector<double> inverse_mass_, inverse_inertia_;
  std::vector<char> movable_;
  std::vector<int> moving_;  // movable bodies in contact
  // What undo() puts back.
  std::vector<Vec2> saved_position_, saved_velocity_;
  std::vector<double> saved_angle_, saved_spin_;
  // The velocities after the compression, before restitution (per body slot).
  std::vector<Vec2> mid_velocity_;
  std::vector<double> mid_spin_;
  double largest_overlap_ = 0.0;  // [m]
};

}  // namespace flotsam
