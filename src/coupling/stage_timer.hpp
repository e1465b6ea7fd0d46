#pragma once
// Wall time spent in each stage of the simulation step (docs/architecture.md), summed over the
// run: the profile printed at the end of a run.
#include <array>
#include <chrono>
#include <string_view>

namespace flotsam {

enum class Stage { flow, bodies, contacts, reaction, diagnostics, output, count };

constexpr std::array<std::string_view, static_cast<int>(Stage::count)> stage_names = {
    "flow", "bodies", "contacts", "reaction", "diagnostics", "output"};

class StageTimer {
 public:
  /// Times the enclosing scope into stage s.
  class Scope {
   public:
    Scope(StageTimer& timer, Stage s)
        : timer_(timer), stage_(s), start_(std::chrono::steady_clock::now()) {}
    ~Scope() {
      timer_.seconds_[static_cast<int>(stage_)] +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    StageTimer& timer_;
    Stage stage_;
    std::chrono::steady_clock::time_point start_;
  };

  Scope time(Stage s) { return Scope(*this, s); }
  double seconds(Stage s) const { return seconds_[static_cast<int>(s)]; }  // [s]

 private:
  std::array<double, static_cast<int>(Stage::count)> seconds_{};
};

}  // namespace flotsam
