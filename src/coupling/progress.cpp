#include "coupling/progress.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace flotsam {

Progress::Progress(double t_start, double t_end, std::FILE* stream, double log_interval)
    : t_start_(t_start),
      t_end_(t_end),
      stream_(stream),
      terminal_(isatty(fileno(stream)) != 0),
      log_interval_(log_interval),
      start_(std::chrono::steady_clock::now()),
      last_print_(start_) {}

std::string Progress::format_duration(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  return fmt::format("{}:{:02d}:{:02d}", s / 3600, (s / 60) % 60, s % 60);
}

void Progress::update(double t, long step, const std::string& extra) {
  const auto now = std::chrono::steady_clock::now();
  const double wall = std::chrono::duration<double>(now - start_).count();
  const double since = std::chrono::duration<double>(now - last_print_).count();
  const bool last = t >= t_end_;
  if (!last && since < (terminal_ ? 0.2 : log_interval_)) return;
  last_print_ = now;
  const double done = std::clamp((t - t_start_) / (t_end_ - t_start_), 0.0, 1.0);
  const double eta = done > 0 ? wall * (1 - done) / done : 0.0;
  const double per_step = step > 0 ? 1e3 * wall / static_cast<double>(step) : 0.0;
  const std::string text = fmt::format(
      "t = {:.1f} / {:.1f} s  step {}  {:.2f} ms/step  elapsed {}  left {}{}{}", t, t_end_, step,
      per_step, format_duration(wall), format_duration(eta), extra.empty() ? "" : "  ", extra);
  if (terminal_) {
    const int width = 24;
    const int filled = static_cast<int>(done * width);
    fmt::print(stream_, "\r[{}{}] {:3.0f}%  {}\x1b[K", std::string(filled, '#'),
               std::string(width - filled, '.'), 100 * done, text);
  } else {
    fmt::print(stream_, "{:3.0f}%  {}\n", 100 * done, text);
  }
  std::fflush(stream_);
  printed_ = true;
}

void Progress::finish() {
  if (terminal_ && printed_) fmt::print(stream_, "\n");
}

}  // namespace flotsam
