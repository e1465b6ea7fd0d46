#pragma once
// The contact stage of a body step (spec 4). plan() groups, at the start of a flow step, the
// bodies that may touch (contact_planner.hpp); then, after each contact interval of a group, one
// call of step() reads as the pipeline
//
//   update_boxes -> find_pairs (broad phase) -> collide (narrow phase, islands, warm start)
//   -> solve (impulses) -> correct_positions
//
// each stage timed into ContactProfile, as Box2D's b2World_Step. The world keeps what makes the
// next step cheap: the sweep order, and last step's contacts, indexed by body, to warm-start the
// solver (each new contact takes the impulses of its pair's last contact).
// Bodies whose state is `gone` take no part.
#include <memory>
#include <tuple>
#include <utility>
#include <vector>

#include "bodies/body_set.hpp"
#include "contact/boundary_segments.hpp"
#include "contact/contact_planner.hpp"
#include "contact/contact_report.hpp"
#include "contact/contact_solver.hpp"
#include "contact/impulse_solver.hpp"
#include "contact/island_sleep.hpp"
#include "contact/islands.hpp"
#include "contact/sweep_and_prune.hpp"
#include "io/case.hpp"

namespace flotsam {

struct ContactProfile {
  double boxes = 0.0;            // [s] bounding boxes
  double broad_phase = 0.0;      // [s] body pairs and body-wall candidates
  double narrow_phase = 0.0;     // [s] manifolds
  double solve = 0.0;            // [s] impulses
  double positions = 0.0;        // [s] position correction
  int body_pairs = 0;            // candidate body pairs from the broad phase
  int wall_pairs = 0;            // candidate (body, segment) pairs
  int contacts = 0;              // manifolds with at least one point
  int points = 0;                // contact points
  int warm_started_points = 0;   // points matched to one of the last step's
  int velocity_sweeps = 0;       // the most any island took
  int islands = 0;               // groups of bodies joined by contacts (contact/islands.hpp)
  int largest_island = 0;        // contacts in the largest island
  double largest_overlap = 0.0;  // [m] after position correction
  int second_solves = 0;         // 1 when the interval was solved again with grown margins
  int sleeping_islands = 0;      // islands set aside asleep (contact/island_sleep.hpp)
  int sleeping_contacts = 0;     // their contacts
};

enum class BroadPhase { sweep_and_prune, brute_force };

class ContactWorld {
 public:
  explicit ContactWorld(const ContactConfig& config, double added_mass_coefficient = 0.5);

  /// Detects the contacts of the current poses and resolves them: velocities get the impulses,
  /// poses are put where the interval started moved on by `interval` times the new velocity,
  /// then the overlap correction.
  /// `interval` h [s] is the time the bodies have just been moved over since the last call (one
  /// contact interval of BodyIntegrator::advance, not the whole flow step): the move redoes that
  /// interval with the new velocities, and gaps may close within the next h (speculative
  /// contact). h >= 0. With `members`, only those bodies take part (a contact group): the
  /// contacts of the others are kept as they are. With `lengths`, body i's h is lengths[i].
  void step(BodySet& bodies, const BoundarySegments& walls, double interval,
            const std::vector<int>* members = nullptr,
            const std::vector<double>* lengths = nullptr);

  /// Detection alone (boxes, broad phase, narrow phase): fills contacts().
  void detect(const BodySet& bodies, const BoundarySegments& walls,
              const std::vector<int>* members = nullptr);

  /// The contact groups of the next flow step of length dt [s] (contact_planner.hpp); the
  /// contacts of bodies left free are dropped (nothing is within their reach).
  ContactSchedule plan(const BodySet& bodies, const BoundarySegments& walls, double dt);

  const std::vector<ContactConstraint>& contacts() const { return contacts_; }
  const std::vector<BodyPair>& body_pairs() const { return body_pairs_; }
  const std::vector<std::pair<int, int>>& wall_pairs() const { return wall_pairs_; }
  const ContactProfile& profile() const { return profile_; }
  ContactReport report(const BoundarySegments& walls, int body_count) const;

  void set_broad_phase(BroadPhase method) { broad_phase_ = method; }

  /// The z of each body's underside and top [m], for the walls that stop bodies only in a band
  /// of heights (BoundarySegments::stops: a bridge deck's face). A body without levels is stopped.
  void set_body_levels(std::vector<double> bottom, std::vector<double> top) {
    level_bottom_ = std::move(bottom);
    level_top_ = std::move(top);
  }

  /// What the next step starts from besides the bodies: the last contacts (warm start) and the
  /// sweep order. A checkpoint keeps it; restore() puts it back.
  const SweepAndPrune& sweep() const { return sweep_; }
  void restore(std::vector<ContactConstraint> contacts, std::vector<int> sweep_order,
               int sweep_axis) {
    contacts_ = std::move(contacts);
    sweep_.restore(std::move(sweep_order), sweep_axis);
    after_known_.clear();
    pose_known_.clear();
    sleep_.wake_all();
  }
  /// Whether body i is asleep (contact/island_sleep.hpp).
  bool asleep(int i) const { return sleep_.asleep(i); }
  const ContactConfig& config() const { return config_; }

 private:
  void select(const BodySet& bodies, const std::vector<int>* members);
  void update_boxes(const BodySet& bodies);
  void find_pairs(const BoundarySegments& walls);
  void find_interval_start(const BodySet& bodies);
  void collide(const BodySet& bodies, const BoundarySegments& walls);
  void keep_touching(int body_pairs);
  void index_previous(int body_count);
  int warm_start(ContactConstraint& c, int& hint) const;
  void solve(BodySet& bodies);
  bool grow_reach(const BodySet& bodies);
  void correct_positions(BodySet& bodies);

  ContactConfig config_;
  double added_mass_coefficient_;  // C_a [-], used when config_.added_mass_in_contact
  BroadPhase broad_phase_ = BroadPhase::sweep_and_prune;
  SweepAndPrune sweep_;
  std::vector<Aabb> boxes_;
  std::vector<Rectangle> rectangles_;  // footprints of this detection (update_boxes())
  std::vector<Manifold> manifolds_;    // of the body pairs, then of the wall pairs
  std::vector<char> active_;           // 1 for the bodies of this step (in_step_)
  std::vector<int> in_step_;           // this step's bodies, ascending (select())
  std::vector<BodyPair> body_pairs_;
  std::vector<std::pair<int, int>> wall_pairs_;  // (body, segment)
  std::vector<ContactConstraint> contacts_, previous_;
  // previous_ by body A (index_previous()): a list per body, and each one's (b, segment).
  std::vector<int> first_previous_, next_previous_;
  std::vector<std::pair<int, int>> previous_key_;
  std::vector<char> touching_;             // 1 for a pair whose manifold has points
  std::vector<int> kept_;                  // the pairs (body pairs, then wall pairs) with a contact
  std::vector<int> run_start_;             // keep_touching(): where each thread's run starts
  std::vector<BodyPair> ends_;             // their bodies (b = -1: a wall)
  std::vector<int> source_;                // contacts_[d] is of the pair kept_[source_[d]]
  std::vector<ContactConstraint> others_;  // contacts of the bodies outside this step's group
  ContactPlanner planner_;
  std::unique_ptr<ContactSolver> solver_;  // by config_.solver
  double margin_;  // detection margin in slops (ContactSolver::margin_in_slops)
  SolverMasses masses_;
  Islands islands_;
  IslandSleep sleep_;
  std::vector<ContactConstraint> resting_;       // contacts of the sleeping islands of this step
  std::vector<Vec2> velocity_before_;            // [m/s]
  std::vector<double> angular_velocity_before_;  // [rad/s]
  BodyVelocities after_;           // each body's velocities at the end of its last step here
  std::vector<char> after_known_;  // 1 while after_ holds the start of the body's next interval
  BodyVelocities interval_start_;  // this step's bodies at the start of their interval
  BodyPoses start_pose_;           // each body's pose where its interval starts: at the end of
                                   // its last step here, or at the flow step's start (plan())
  std::vector<char> pose_known_;   // 1 where start_pose_ holds it
  std::vector<double> reach_;      // [m] per body, added to its detection margin (see step())
  std::vector<int> grown_;         // the bodies whose reach_ the last step grew
  std::vector<double> lengths_;    // h per body [s]
  std::vector<double> level_bottom_, level_top_;  // [m] per body (set_body_levels)
  struct WallQuery {  // one thread's grid query (BoundarySegments::query) and the pairs it found
    std::vector<int> found, stamp;
    int stamp_value = 0;
    std::vector<std::pair<int, int>> pairs;
  };
  std::vector<WallQuery> wall_queries_;
  ContactProfile profile_;
};

/// One stateless contact solve (no warm start): for callers that keep no world.
void contact_step(BodySet& bodies, const BoundarySegments& walls, const ContactConfig& config,
                  double interval);

/// The footprint of body i.
Rectangle body_rectangle(const BodySet& bodies, int i);

}  // namespace flotsam
