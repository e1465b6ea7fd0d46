#pragma once
// Sleeping islands (Box2D's sleep; docs/model.md "Sleeping islands"), `bodies.contact.sleep_time`.
// A body is still over a contact step of length h when
//
//   |u| < v_s,  |omega| R < v_s,  |x - x_last| < v_s h,  |theta - theta_last| R < v_s h       (Z-1)
//
// (v_s = sleep_speed, R half the body's diagonal, x_last and theta_last its pose at the end of its
// last contact step: the poses' change includes what the solver pushed out). An island whose
// bodies have all been still and in contact for sleep_time falls asleep: velocities set to zero,
// poses kept, and the forces' acceleration a_z of each body (u^1 - u^0) / h of that step kept.
// Afterwards, at each step, a sleeping body's pose is put back exactly and its velocity to zero,
// and its island is not solved, until
//
//   the forces change:  |a - a_z| T_s > v_s  or  |alpha - alpha_z| R T_s > v_s          (Z-2)
//                       (T_s = sleep_time; the velocity the change would give over the time
//                        it took to fall asleep, had no contact taken it)
//   or it is touched:   a contact joins it to an awake body or to another sleeping island,
//
// either of which wakes the whole island (its bodies continue from where the body step moved
// them). Walls join nothing, so a log resting alone against a pier is an island of its own.
#include <vector>

#include "bodies/body_set.hpp"
#include "contact/contact_solver.hpp"
#include "contact/impulse_solver.hpp"
#include "contact/islands.hpp"

namespace flotsam {

class IslandSleep {
 public:
  /// sleep_time T_s [s] (<= 0: no island ever sleeps), sleep_speed v_s [m/s].
  IslandSleep(double sleep_time, double sleep_speed) : time_(sleep_time), speed_(sleep_speed) {}

  bool enabled() const { return time_ > 0.0; }
  bool asleep(int i) const { return i < static_cast<int>(asleep_.size()) && asleep_[i]; }

  /// Before detection, for the bodies of the step (`in_step`), just moved by the body step with
  /// velocities that went from `start` to the present ones over lengths[i]: wakes the islands
  /// whose forces changed (Z-2); puts the others' bodies back to their sleeping poses, at rest.
  void check_forces(BodySet& bodies, const BodyVelocities& start,
                    const std::vector<double>& lengths, const std::vector<char>& in_step);

  /// After detection: wakes the sleeping islands that a contact joins to an awake body or to
  /// another sleeping island, their bodies moved again as the body step left them. True when
  /// some were: the caller detects again.
  bool wake_touched(const std::vector<ContactConstraint>& contacts, BodySet& bodies);

  /// With `contacts` grouped by `islands`: moves the contacts of the islands whose bodies are all
  /// asleep to `resting` (not solved). A sleeping body in an island with awake ones (touched in a
  /// second detection) is woken at rest. Returns the islands moved.
  int set_aside(std::vector<ContactConstraint>& contacts, const Islands& islands,
                std::vector<ContactConstraint>& resting, BodySet& bodies);

  /// After the solve of the awake `contacts` (grouped by `islands`): the bodies' time still
  /// (Z-1), and the islands still for sleep_time fall asleep. Notes every step body's pose.
  void update(std::vector<ContactConstraint>& contacts, const Islands& islands, BodySet& bodies,
              const std::vector<double>& lengths, const std::vector<char>& in_step);

  /// Body i is awake from now on, and its last pose unknown (it leaves the contacts, or the
  /// world was restored).
  void wake(int i);
  void wake_all();

 private:
  void resize(int n);
  void wake_marked(BodySet* bodies);

  double time_, speed_;  // T_s [s], v_s [m/s]
  std::vector<char> asleep_;
  std::vector<int> group_;  // the island a sleeping body fell asleep in (one of its bodies)
  std::vector<Vec2> rest_position_, rest_acceleration_;  // [m], a_z [m/s^2]
  std::vector<double> rest_angle_, rest_angular_;        // [rad], alpha_z [rad/s^2]
  std::vector<double> still_time_;                       // [s] (Z-1) held so long
  std::vector<Vec2> acceleration_;                       // this step's a [m/s^2]
  std::vector<double> angular_acceleration_;             // [rad/s^2]
  std::vector<Vec2> last_position_;                      // [m] at the end of the last step
  std::vector<double> last_angle_;                       // [rad]
  std::vector<char> last_known_;
  // Where the body step left a sleeping body (to wake it there).
  std::vector<Vec2> moved_position_, moved_velocity_;
  std::vector<double> moved_angle_, moved_spin_;
  std::vector<char> stashed_;             // 1 where moved_* hold this step's
  std::vector<char> woken_, in_contact_;  // per group, per body (scratch)
  int sleeping_ = 0;                      // bodies asleep
};

}  // namespace flotsam
