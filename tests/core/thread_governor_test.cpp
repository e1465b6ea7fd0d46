// Verifies the thread governor's choice on machines modelled by the wall time of a step on n
// threads: idle (two threads 1.7x faster: it stays on two, trials under 1 % of the steps),
// loaded (two threads 2.6x slower, as measured with one core busy: it comes down to one within
// the first interval and a trial, and the run takes at most 1.1x its time on one thread), load
// that comes and goes, and a step whose cost falls fast over the run (the bracketed trial keeps
// it from a wrong switch).
#include "core/thread_governor.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace flotsam {
namespace {

struct Timed {
  double seconds = 0.0;  // [s] wall time of all the steps
  long steps = 0;
};

/// Steps until `run` has taken `wall` seconds in all, each taking cost(threads, its time so far).
void run_until(ThreadGovernor& governor, Timed& run, double wall,
               const std::function<double(int, double)>& cost) {
  while (run.seconds < wall) {
    const double s = cost(governor.threads(), run.seconds);
    governor.record(s);
    run.seconds += s;
    ++run.steps;
  }
}

/// A run of `wall` seconds.
Timed run_for(ThreadGovernor& governor, double wall,
              const std::function<double(int, double)>& cost) {
  Timed run;
  run_until(governor, run, wall, cost);
  return run;
}

double idle(int threads, double) {
  return threads == 2 ? 0.006 : 0.0102;  // [s] 1.7x
}

double loaded(int threads, double) {
  return threads == 2 ? 0.026 : 0.010;  // [s] two threads 2.6x slower
}

TEST(ThreadGovernor, StaysOnAllThreadsOnAnIdleMachineWithTrialsUnderOnePercent) {
  ThreadGovernor governor(2);
  const Timed run = run_for(governor, 600.0, idle);
  EXPECT_EQ(governor.threads(), 2);
  EXPECT_LT(static_cast<double>(governor.reduced_steps()) / static_cast<double>(run.steps), 0.01);
  // The run's time against all of it on two threads: the trials' cost.
  const double all_on_two = static_cast<double>(run.steps) * idle(2, 0.0);
  EXPECT_LT(run.seconds / all_on_two, 1.005);
}

TEST(ThreadGovernor, ComesDownToOneThreadWhenTwoAreSlower) {
  ThreadGovernor governor(2);
  const ThreadGovernor::Settings settings;
  run_for(governor, settings.first_interval + 3 * 3 * 0.026, loaded);  // the interval, a trial
  EXPECT_EQ(governor.threads(), 1);
  const Timed run = run_for(governor, 120.0, loaded);
  const double all_on_one = static_cast<double>(run.steps) * loaded(1, 0.0);
  EXPECT_LT(run.seconds / all_on_one, 1.02);
}

TEST(ThreadGovernor, WholeLoadedRunTakesAtMostTenPercentMoreThanOneThread) {
  ThreadGovernor governor(2);
  const Timed run = run_for(governor, 10.0, loaded);  // a short run: the first interval counts
  const double all_on_one = static_cast<double>(run.steps) * loaded(1, 0.0);
  EXPECT_LT(run.seconds / all_on_one, 1.1);
}

TEST(ThreadGovernor, FollowsLoadThatComesAndGoes) {
  ThreadGovernor governor(2);
  const ThreadGovernor::Settings settings;
  const auto busy_between = [](double from, double to) {
    return [=](int threads, double t) {
      return t >= from && t < to ? loaded(threads, t) : idle(threads, t);
    };
  };
  // Idle for 200 s, loaded from then to 400 s, idle again.
  const auto machine = busy_between(200.0, 400.0);
  Timed run;
  const auto until = [&](double wall) { run_until(governor, run, wall, machine); };
  until(200.0);
  EXPECT_EQ(governor.threads(), 2);
  // Within the longest interval and a trial of the load's start: one thread.
  until(200.0 + settings.last_interval + 1.0);
  EXPECT_EQ(governor.threads(), 1);
  until(400.0);
  EXPECT_EQ(governor.threads(), 1);
  until(400.0 + settings.last_interval + 1.0);
  EXPECT_EQ(governor.threads(), 2);
}

TEST(ThreadGovernor, CostFallingOverTheRunDoesNotMakeItSwitch) {
  // The step's cost halves in every window (0.05 s of wall time): a trial on one
  // thread, measured after the steps on two, would look cheaper than they were.
  ThreadGovernor governor(2);
  const auto falling = [](int threads, double t) {
    return idle(threads, t) * std::exp2(-t / 0.05);
  };
  run_for(governor, 0.8, falling);  // the first trials, at 0.1 s and 0.5 s
  EXPECT_EQ(governor.changes(), 0);
}

TEST(ThreadGovernor, OneThreadNeverTries) {
  ThreadGovernor governor(1);
  run_for(governor, 100.0, idle);
  EXPECT_EQ(governor.threads(), 1);
  EXPECT_EQ(governor.reduced_steps(), 0);
}

TEST(ThreadGovernor, FourThreadsComeDownByHalvesAndBackByDoubling) {
  // Four threads with two of four cores held by others: two is best; one is slower again; from
  // two it tries four and one in turn and keeps two.
  const auto shared = [](int threads, double) {
    return threads == 4 ? 0.030 : threads == 2 ? 0.010 : 0.016;
  };
  ThreadGovernor governor(4);
  run_for(governor, 30.0, shared);
  EXPECT_EQ(governor.threads(), 2);
  const Timed run = run_for(governor, 300.0, shared);
  EXPECT_EQ(governor.threads(), 2);
  EXPECT_LT(run.seconds / (static_cast<double>(run.steps) * shared(2, 0.0)), 1.02);
}

}  // namespace
}  // namespace flotsam
