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

}  // namespace flotsam
