#pragma once
// Islands (Box2D's b2Island): the bodies joined by contacts, directly or through other bodies.
// A wall joins nothing: it does not move, so two logs resting against the same pier are two
// islands. Islands share no body, so each is solved on its own (its own sweeps, stopping when it
// has converged, so a resting island costs one sweep while a jam still loading takes many) and
// in parallel, with the same result on any number of threads: within an island the contacts keep
// their order, and no island reads another's bodies.
#include <span>
#include <vector>

#include "contact/impulse_solver.hpp"
#include "contact/sweep_and_prune.hpp"

namespace flotsam {

class Islands {
 public:
  /// Reorders `contacts` so that each island's contacts are contiguous: islands in the order of
  /// their first contact, and within an island the contacts in their old relative order.
  void group(std::vector<ContactConstraint>& contacts, int body_count);
  /// The same islands for contacts given by their bodies alone, ends[m] = (a, b), b = -1 for a
  /// wall, without moving them: returns each contact's index once grouped (island() then holds
  /// for a vector in that order).
  const std::vector<int>& number(std::span<const BodyPair> ends, int body_count);

  int count() const { return static_cast<int>(start_.size()) - 1; }
  /// Island k's contacts, after group() on the same vector.
  std::span<ContactConstraint> island(std::vector<ContactConstraint>& contacts, int k) const {
    return {contacts.data() + start_[k], static_cast<std::size_t>(start_[k + 1] - start_[k])};
  }
  /// The islands from the largest (most contacts) down: the order to hand them to threads in.
  const std::vector<int>& largest_first() const { return largest_first_; }
  int largest() const { return largest_first_.empty() ? 0 : size(largest_first_.front()); }

 private:
  int size(int k) const { return start_[k + 1] - start_[k]; }
  int root(int body);
  void join(int a, int b);
  void number_in_team(std::span<const BodyPair> ends);

  std::vector<int> parent_;  // union-find over bodies
  std::vector<int> first_of_root_, island_of_root_, root_of_contact_, island_of_contact_;
  std::vector<int> start_, largest_first_;
  std::vector<int> run_start_, thread_counts_;  // number_in_team(): per thread, per island
  std::vector<int> destination_;                // of each contact, once grouped
  std::vector<BodyPair> ends_;
  std::vector<ContactConstraint> sorted_;
};

}  // namespace flotsam
