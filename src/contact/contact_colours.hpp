#pragma once
// Graph colouring of the contacts (Box2D v3's constraint graph colours): contacts of one colour
// share no movable body, so they can be solved at the same time on any number of threads, and
// solving the colours one after another is one Gauss-Seidel sweep in colour order, the same bit
// for bit whatever the threads. A wall and an anchored body do not move: they join nothing.
// Greedy, in the contacts' order: each takes the lowest colour that none of the contacts of its
// bodies has; a contact that finds none of the 64 goes to the overflow, solved by one thread.
#include <cstdint>
#include <vector>

#include "contact/impulse_solver.hpp"
#include "contact/sweep_and_prune.hpp"

namespace flotsam {

class ContactColours {
 public:
  static constexpr int max_colours = 64;

  /// movable[i] = 0 for a body that the contacts cannot move (1/m = 1/I = 0).
  void assign(std::span<const ContactConstraint> contacts, const std::vector<char>& movable);
  /// The same for contacts given by their bodies alone, ends[m] = (a, b), b = -1 for a wall.
  void assign(std::span<const BodyPair> ends, const std::vector<char>& movable);

  /// Colours in use, then the overflow as the last group (possibly empty).
  int groups() const { return static_cast<int>(start_.size()) - 1; }
  /// The contacts in colour order: group k is order()[start(k)] to order()[start(k + 1) - 1].
  const std::vector<int>& order() const { return order_; }
  int start(int k) const { return start_[k]; }
  bool is_overflow(int k) const { return k == groups() - 1; }

 private:
  std::vector<std::uint64_t> used_;  // per body: the colours its contacts have
  std::vector<int> colour_of_, order_, start_;
  std::vector<BodyPair> ends_;
};

}  // namespace flotsam
