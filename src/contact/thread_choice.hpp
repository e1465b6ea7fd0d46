#pragma once
// Whether a solve that gives the same bits on one thread and on several should use the threads:
// the one the measured time per unit of work says is faster. A step of the soft step meets the
// threads about a hundred times (contact_colours.hpp); on a machine with more runnable threads
// than cores each meeting may wait for a time slice, and the threads then cost many times what
// they save. The choice changes only the time, never the result. Each way's cost is a running
// mean of seconds per unit of work; the slower way is tried again after 16 runs, then after twice
// as many each time the trial confirms it slower (at most 1,024), as the load changes.
#include <algorithm>
#include <array>

namespace flotsam {

class ThreadChoice {
 public:
  /// True when the next run should use the threads.
  bool threads() {
    if (cost_[1] < 0.0) return true;
    if (cost_[0] < 0.0) return false;
    const bool faster = cost_[1] < cost_[0];
    if (faster != best_) best_ = faster, wait_ = first_wait;  // the other way won a trial
    if (++runs_ < wait_) return faster;
    runs_ = 0;
    wait_ = std::min(2 * wait_, last_wait);
    return !faster;
  }
  /// A run with (threads) or without took `seconds` [s] for `work` units (> 0).
  void record(bool threads, double seconds, double work) {
    double& cost = cost_[threads ? 1 : 0];
    const double sample = seconds / work;  // [s] per unit
    cost = cost < 0.0 ? sample : (1.0 - weight) * cost + weight * sample;
  }

 private:
  static constexpr int first_wait = 16, last_wait = 1024;  // runs between trials
  static constexpr double weight = 0.25;                   // [-] of a new sample in the mean
  std::array<double, 2> cost_{-1.0, -1.0};                 // [s] per unit, -1: not yet run
  bool best_ = true;
  int runs_ = 0, wait_ = first_wait;
};

}  // namespace flotsam
