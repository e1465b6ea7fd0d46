#include "flow/fem/quadrature.hpp"

#include <cmath>

namespace flotsam {

const std::array<TrianglePoint, triangle_point_count>& triangle_rule() {
  static const std::array<TrianglePoint, triangle_point_count> rule = [] {
    const double s15 = std::sqrt(15.0);
    const double a1 = (6.0 - s15) / 21.0, b1 = (9.0 + 2.0 * s15) / 21.0;
    const double a2 = (6.0 + s15) / 21.0, b2 = (9.0 - 2.0 * s15) / 21.0;
    const double w0 = 9.0 / 80.0;
    const double w1 = (155.0 - s15) / 2400.0, w2 = (155.0 + s15) / 2400.0;
    return std::array<TrianglePoint, triangle_point_count>{{{1.0 / 3.0, 1.0 / 3.0, w0},
                                                            {a1, a1, w1},
                                                            {b1, a1, w1},
                                                            {a1, b1, w1},
                                                            {a2, a2, w2},
                                                            {b2, a2, w2},
                                                            {a2, b2, w2}}};
  }();
  return rule;
}

const std::array<EdgePoint, edge_point_count>& edge_rule() {
  static const std::array<EdgePoint, edge_point_count> rule = [] {
    const double d = 0.5 * std::sqrt(0.6);
    return std::array<EdgePoint, edge_point_count>{
        {{0.5 - d, 5.0 / 18.0}, {0.5, 8.0 / 18.0}, {0.5 + d, 5.0 / 18.0}}};
  }();
  return rule;
}

}  // namespace flotsam
