#pragma once
// The soft step (Box2D v3's solver: E. Catto, "Solver2D", box2d.org blog, 2024; soft constraints:
// E. Catto, "Soft Constraints", GDC 2011), behind the ContactSolver interface
// (`bodies.contact.solver: soft_step`). Equations: docs/model.md "Soft step".
//
// The bodies arrive moved over h with their velocities u^0 before the contacts. The interval is
// redone in n sub-steps of h_s = h / n from the poses it started from, each carried as a
// displacement D and a turn Theta from the detected pose (anchors: the separations follow the
// bodies within the interval without detecting again), D = x_0 - x_1, Theta = theta_0 - theta_1
// at the start (x_0, theta_0: the pose the interval started from; x_1, theta_1: the detected one):
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
#include <cstdint>

#include "contact/contact_colours.hpp"
#include "contact/contact_solver.hpp"
#include "contact/restitution_energy.hpp"
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
            const BodyVelocities& start, const BodyPoses& start_pose) override;
  void undo(BodySet& bodies) override;
  /// Nothing left to do: the sub-steps pushed the overlaps out. Returns the largest overlap at
  /// the end of the last sub-step (S-1).
  double correct_positions(std::vector<ContactConstraint>&, const Islands&, BodySet&,
                           const SolverMasses&) override {
    return largest_overlap_;
  }

  // The solver's loops read only the hot data: per body slot one cache line (Body), per four
  // contacts of a colour one Wide (Box2D v3's wide constraints: one contact per lane, its
  // bodies' inverse masses copied in), in flat arrays, a colour's Wides one after another. The
  // lanes of a Wide share no movable body, so solving them at once gives the bits of solving
  // them one after another; each lane does exactly the operations of the one-contact solve, in
  // the same order (no contraction into FMA: CMakeLists.txt). The overflow's contacts take one
  // Wide each, its other lanes empty. What the sweeps do not read lives in arrays of the same
  // index (WideBlock, WideStart, BodyStep).
  static constexpr int lanes = 4;
  // Aligned to their size whatever the instruction set (without AVX, GCC would align them to 16).
  using Lanes = double __attribute__((vector_size(lanes * sizeof(double)), aligned(32)));
  using Mask = long long __attribute__((vector_size(lanes * sizeof(long long)), aligned(32)));
  using SmallMask = signed char __attribute__((vector_size(lanes)));  // a Mask's lanes, 0 or -1
  struct alignas(64) Body {
    Vec2 velocity = Vec2::Zero();   // u [m/s]
    double spin = 0.0;              // omega [rad/s]
    Vec2 shift = Vec2::Zero();      // D [m] from the detected pose
    Vec2 rotation = Vec2::UnitX();  // (cos, sin) Theta
  };
  struct WidePoint {
    Lanes r_ax, r_ay, r_bx, r_by;           // anchors from G_A, G_B at detection [m]
    Lanes base_separation;                  // s_1 - n . (r_A - r_B) [m], so that (S-1) is one dot
    Lanes normal_mass, tangent_mass;        // 1/K [kg]
    Lanes normal_impulse, tangent_impulse;  // lambda of this sub-step [N s]
    Lanes largest_normal;                   // [N s] over the sub-steps
    Lanes total_normal, total_tangent;      // over the interval [N s]
  };
  struct alignas(64) Wide {
    std::array<int, lanes> a, b;       // body slots; a wall (and an empty lane) is the last slot
    SmallMask point[2];                // the lane has point p
    SmallMask block;                   // two points relaxed and restituted at once
    SmallMask first_of_a, first_of_b;  // the body's first contact in colour order
    SmallMask movable_a, movable_b;    // 1/m or 1/I > 0
    Lanes nx, ny;                      // n
    Lanes friction;                    // mu_c [-]
    Lanes inverse_substep;             // 1 / h_s [1/s]
    Lanes bias_rate;                   // b [1/s]
    Lanes mass_scale, impulse_scale;   // a/(1+a), 1/(1+a) [-]
    Lanes inverse_mass_a, inverse_mass_b;        // [1/kg]
    Lanes inverse_inertia_a, inverse_inertia_b;  // [1/(kg m^2)]
    WidePoint points[2];
  };
  struct alignas(64) WideBlock {  // the two-point block solver's K [1/kg] and K^-1 [kg], row by row
    Lanes k00, k01, k10, k11, m00, m01, m10, m11;
  };
  struct alignas(32) WideStart {        // per point, read at the first sub-step and at the end
    Lanes first_normal, first_tangent;  // lambda of sub-step 0 [N s]
    Lanes later_normal, later_tangent;  // of the last interval's last sub-step [N s]
    Lanes approach;                     // v_n^0 [m/s]
    Mask resting;
  };
  struct BodyStep {            // per body slot, read once per sub-step
    Vec2 gain = Vec2::Zero();  // the forces' velocity per sub-step [m/s]
    double spin_gain = 0.0;    // [rad/s]
    double turn = 0.0;         // Theta [rad]
    double step = 0.0;         // h_s [s]
  };

 private:
  void prepare(const std::vector<ContactConstraint>& contacts, const BodySet& bodies,
               const SolverMasses& masses, const std::vector<double>& intervals,
               const BodyVelocities& start, const BodyPoses& start_pose, bool threads);
  void store(std::vector<ContactConstraint>& contacts, BodySet& bodies, bool threads);
  void relax(std::size_t w, int substep);
  void move_pose(int body);
  struct BodyEnergy {         // one moving body's kinetic energies [J]
    double before, mid, end;  // before the contacts, after the compression, at the end
    RestitutionTerms change;  // its share of E(s)
  };
  BodyEnergy body_energy(int m) const;
  void bound_restitution();
  template <class F>
  void each_colour(F&& f);
  [[gnu::always_inline]] inline void fetch_bodies(const Wide& c) const;

  ContactConfig config_;
  ContactColours colours_;
  ThreadChoice choice_;  // whether the colours are shared among the threads (same bits either way)
  std::vector<Wide> wide_;                       // colour after colour
  std::vector<WideBlock> block_;                 // of wide_[w]
  std::vector<std::array<WideStart, 2>> start_;  // of wide_[w]
  std::vector<int> wide_start_;    // colour g's Wides: wide_start_[g] to wide_start_[g + 1] - 1
  std::vector<int> lane_contact_;  // lane l of wide_[w]: contacts[lane_contact_[4 w + l]], or -1
  // Per body slot (bodies.size() + 1, the last a wall).
  std::vector<Body> body_;
  std::vector<BodyStep> body_step_;
  std::vector<double> inverse_mass_, inverse_inertia_;
  std::vector<char> movable_, seen_;
  std::vector<BodyPair> ends_;        // per contact: (a, b), b = -1 for a wall
  std::vector<unsigned char> first_;  // per contact in colour order: first of A (1), of B (2)
  std::vector<int> touched_;          // bodies in contact, in colour order of their first contact
  std::vector<int> moving_;           // the movable ones
  // What undo() puts back.
  std::vector<Vec2> saved_position_, saved_velocity_;
  std::vector<double> saved_angle_, saved_spin_;
  // The velocities after the compression, before restitution (per body slot).
  std::vector<Vec2> mid_velocity_;
  std::vector<double> mid_spin_;
  std::vector<BodyEnergy> energy_;  // per moving body
  double largest_overlap_ = 0.0;    // [m]
};

}  // namespace flotsam
