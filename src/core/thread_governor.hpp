#pragma once
// How many OpenMP threads the next step of a run takes (docs/performance.md "Shared machines").
//
// A run gives the same bits on any number of threads, so the count may change between any two
// steps. On a machine of its own every thread pays; on a shared one (another program holding a
// core, a second run beside this one) a team waits at each of a step's many barriers for the
// thread the system has put aside, and two threads take longer than one. The governor measures
// rather than guesses: the run starts on all its threads; now and then it tries a few steps on
// half as many (or, once it has come down, twice as many and half as many in turn) and keeps
// whichever took less wall time per step. A trial is bracketed by two measurements on the current
// count, so that a flow that grows costlier over the run does not decide:
//
//   settled for `interval` --> current count for a window --> the other count for a window -->
//   current count for a window --> the other kept if its time per step is below `gain` times
//   the mean of the two windows around it.
//
// A window is at least `window_steps` steps and `window_seconds` of wall time. A change starts
// the interval again from `first_interval`; no change multiplies it by `growth`, up to
// `last_interval`: a run of a few seconds makes three or four trials, and on a steady machine
// the trials cost well under 1 % of a long run.
#include <algorithm>

namespace flotsam {

class ThreadGovernor {
 public:
  struct Settings {
    double first_interval = 0.1;   // [s] of wall time before the first trial
    double growth = 4.0;           // [-] the interval's factor after a trial that changed nothing
    double last_interval = 64.0;   // [s] longest time between trials
    double window_seconds = 0.05;  // [s] shortest window
    int window_steps = 3;          // [-] fewest steps in a window
    double gain = 0.9;             // [-] the other count kept below this share of the time
  };

  /// A run on at most `threads` threads (omp_get_max_threads() at the start of the run).
  explicit ThreadGovernor(int threads, Settings settings);
  explicit ThreadGovernor(int threads) : ThreadGovernor(threads, Settings{}) {}

  /// The count the next step takes.
  int threads() const { return phase_ == Phase::trial ? other_ : current_; }
  /// The wall time of the step just taken on threads() threads.
  void record(double seconds);

  int most() const { return most_; }
  /// Steps taken on fewer than most() threads, trials included.
  long reduced_steps() const { return reduced_steps_; }
  long steps() const { return steps_; }
  /// Times a trial's count was kept.
  int changes() const { return changes_; }

 private:
  enum class Phase { settled, before, trial, after };
  struct Window {
    double seconds = 0.0;  // [s]
    int steps = 0;
    double per_step() const { return seconds / std::max(steps, 1); }
  };
  void next_phase();
  int other_count();

  int most_;
  Settings settings_;
  int current_, other_ = 1;
  bool up_next_ = true;  // below most(): the next trial doubles (else halves)
  Phase phase_ = Phase::settled;
  double interval_;        // [s] settled time before the next trial
  Window window_;          // the phase's time and steps so far
  Window before_, trial_;  // the trial's measurements
  long steps_ = 0, reduced_steps_ = 0;
  int changes_ = 0;
};

/// Sets the OpenMP thread count for its scope and puts the one before back.
class ThreadCountScope {
 public:
  explicit ThreadCountScope(int threads);
  ~ThreadCountScope();
  ThreadCountScope(const ThreadCountScope&) = delete;
  ThreadCountScope& operator=(const ThreadCountScope&) = delete;

 private:
  int before_;
};

}  // namespace flotsam
