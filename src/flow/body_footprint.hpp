#pragma once
// The cells under a body's footprint (spec 5, two-way coupling), for both engines: the FEM's
// elements and the finite-volume engine's cells. Cells near the body are found by a walk over
// neighbours from the cell holding its centre, among those whose centroid lies within the
// footprint's circumcircle widened by twice the cell's size; the footprint holds those whose
// centroid lies inside the body's rectangle and that the engine lets carry a share.
#include <cmath>
#include <vector>

#include "core/vec.hpp"
#include "flow/flow_field.hpp"

namespace flotsam {

class FootprintWalk {
 public:
  explicit FootprintWalk(int cells) : stamp_(cells, -1) {}

  /// The cells under footprint r (its index `body` among this walk's calls), from `start`.
  /// `Cells` gives centroid(i) [m], area(i) [m^2], neighbours(i) (indices; < 0: none) and
  /// counts(i) (whether cell i may carry a share).
  template <class Cells>
  const std::vector<int>& covered(const BodyFootprint& r, int start, int body, const Cells& cells) {
    const Vec2 axis(std::cos(r.angle), std::sin(r.angle));
    const double reach = r.half_extents.norm();  // [m]
    covered_.clear();
    queue_.assign(1, start);
    stamp_[start] = body;
    for (std::size_t q = 0; q < queue_.size(); ++q) {
      const int i = queue_[q];
      const Vec2 d = cells.centroid(i) - r.centre;
      if (d.norm() > reach + 2.0 * std::sqrt(cells.area(i))) continue;
      if (std::abs(d.dot(axis)) <= r.half_extents.x() &&
          std::abs(cross(axis, d)) <= r.half_extents.y() && cells.counts(i))
        covered_.push_back(i);
      for (int j : cells.neighbours(i))
        if (j >= 0 && stamp_[j] != body) {
          stamp_[j] = body;
          queue_.push_back(j);
        }
    }
    return covered_;
  }

 private:
  std::vector<int> stamp_;  // per cell: the last body whose walk reached it
  std::vector<int> queue_, covered_;
};

/// Per body, the cells it was spread over and each one's share of it (sum 1), in
/// [start[k], start[k + 1]): what an engine needs to say, after a step, what each body exchanged.
struct FootprintShares {
  std::vector<int> start{0}, cell;
  std::vector<double> share;  // [-]

  void clear() { start.assign(1, 0), cell.clear(), share.clear(); }
  void add(int i, double w) { cell.push_back(i), share.push_back(w); }
  void close_body() { start.push_back(static_cast<int>(cell.size())); }
  bool empty(int k) const { return start[k] == start[k + 1]; }
};

}  // namespace flotsam
