#pragma once
// The progress of a long run: simulated time, step, wall time per step and the estimated time
// left. On a terminal one line is redrawn in place (a bar); in a log (not a terminal) a plain
// line is printed every `log_interval` seconds of wall time.
#include <chrono>
#include <cstdio>
#include <string>

namespace flotsam {

class Progress {
 public:
  Progress(double t_start, double t_end, std::FILE* stream = stderr, double log_interval = 10.0);

  /// Reports that step `step` reached simulated time t [s]; `extra` is appended (e.g. bodies).
  void update(double t, long step, const std::string& extra = "");
  /// Ends the line on a terminal.
  void finish();

  /// "1:02:03" from seconds.
  static std::string format_duration(double seconds);

 private:
  double t_start_, t_end_;
  std::FILE* stream_;
  bool terminal_;
  double log_interval_;  // [s] of wall time between plain lines
  std::chrono::steady_clock::time_point start_, last_print_;
  bool printed_ = false;
};

}  // namespace flotsam
