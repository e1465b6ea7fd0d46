#include "core/time_series.hpp"

#include <algorithm>

namespace flotsam {

double TimeSeries::operator()(double t) const {
  if (t <= points_.front().first) return points_.front().second;
  if (t >= points_.back().first) return points_.back().second;
  auto after = std::upper_bound(points_.begin(), points_.end(), t,
                                [](double value, const auto& p) { return value < p.first; });
  auto before = after - 1;
  const double w = (t - before->first) / (after->first - before->first);
  return (1.0 - w) * before->second + w * after->second;
}

// Split [t0, t1] at the table's abscissae: on each piece the series is linear, and the trapezoid
// of its two end values is its exact integral.
double TimeSeries::integral(double t0, double t1) const {
  if (is_constant()) return points_.front().second * (t1 - t0);
  double sum = 0.0, a = t0, value_a = (*this)(t0);
  for (const auto& [t, value] : points_) {
    if (t <= a) continue;
    if (t >= t1) break;
    sum += 0.5 * (t - a) * (value_a + value);
    a = t;
    value_a = value;
  }
  return sum + 0.5 * (t1 - a) * (value_a + (*this)(t1));
}

}  // namespace flotsam
