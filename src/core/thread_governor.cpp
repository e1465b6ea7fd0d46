#include "core/thread_governor.hpp"

#include <omp.h>

namespace flotsam {

ThreadGovernor::ThreadGovernor(int threads, Settings settings)
    : most_(std::max(threads, 1)),
      settings_(settings),
      current_(most_),
      interval_(settings.first_interval) {}

// Halving from all the threads; from fewer, doubling and halving in turn (doubling from one).
int ThreadGovernor::other_count() {
  const bool up = current_ < most_ && (up_next_ || current_ == 1);
  if (current_ < most_ && current_ > 1) up_next_ = !up_next_;
  return up ? std::min(most_, 2 * current_) : current_ / 2;
}

void ThreadGovernor::record(double seconds) {
  ++steps_;
  if (threads() < most_) ++reduced_steps_;
  if (most_ == 1) return;
  window_.seconds += seconds;
  ++window_.steps;
  const bool full = phase_ == Phase::settled ? window_.seconds >= interval_
                                             : window_.steps >= settings_.window_steps &&
                                                   window_.seconds >= settings_.window_seconds;
  if (full) next_phase();
}

void ThreadGovernor::next_phase() {
  switch (phase_) {
    case Phase::settled:
      other_ = other_count();
      phase_ = Phase::before;
      break;
    case Phase::before:
      before_ = window_;
      phase_ = Phase::trial;
      break;
    case Phase::trial:
      trial_ = window_;
      phase_ = Phase::after;
      break;
    case Phase::after: {
      const Window around{before_.seconds + window_.seconds, before_.steps + window_.steps};
      if (trial_.per_step() < settings_.gain * around.per_step()) {
        current_ = other_;
        ++changes_;
        interval_ = settings_.first_interval;
      } else {
        interval_ = std::min(settings_.growth * interval_, settings_.last_interval);
      }
      phase_ = Phase::settled;
      break;
    }
  }
  window_ = {};
}

ThreadCountScope::ThreadCountScope(int threads) : before_(omp_get_max_threads()) {
  omp_set_num_threads(threads);
}

ThreadCountScope::~ThreadCountScope() {
  omp_set_num_threads(before_);
}

}  // namespace flotsam
