#pragma once
// A quantity given as a constant or as a table [[t, value], ...] linearly interpolated in t
// (hydrographs, boundary elevations, bed profiles given as tables). Outside the table the end
// values hold.
#include <utility>
#include <vector>

namespace flotsam {

class TimeSeries {
 public:
  TimeSeries() = default;
  explicit TimeSeries(double constant) : points_{{0.0, constant}} {}
  /// points must be non-empty with strictly increasing abscissae (checked by the caller, which
  /// knows the file and the key to name in the message).
  explicit TimeSeries(std::vector<std::pair<double, double>> points) : points_(std::move(points)) {}

  double operator()(double t) const;
  /// The integral over [t0, t1] (t0 <= t1) [value x t]: exact for the piecewise-linear series and
  /// its end values held outside the table (a hyetograph's rain depth over a step).
  double integral(double t0, double t1) const;
  bool is_constant() const { return points_.size() == 1; }
  const std::vector<std::pair<double, double>>& points() const { return points_; }

 private:
  std::vector<std::pair<double, double>> points_{{0.0, 0.0}};
};

}  // namespace flotsam
