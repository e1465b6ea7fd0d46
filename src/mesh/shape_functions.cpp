#include "mesh/shape_functions.hpp"

namespace flotsam {

P1Values p1_values(double r, double s) {
  return {1.0 - r - s, r, s};
}

P1Gradients p1_reference_gradients() {
  return {Vec2(-1, -1), Vec2(1, 0), Vec2(0, 1)};
}

P2Values p2_values(double r, double s) {
  const double l0 = 1.0 - r - s, l1 = r, l2 = s;
  return {l0 * (2 * l0 - 1), l1 * (2 * l1 - 1), l2 * (2 * l2 - 1),
          4 * l0 * l1,       4 * l1 * l2,       4 * l2 * l0};
}

P2Gradients p2_reference_gradients(double r, double s) {
  const double l0 = 1.0 - r - s, l1 = r, l2 = s;
  // d lambda / d(r, s): lambda_0 -> (-1, -1), lambda_1 -> (1, 0), lambda_2 -> (0, 1).
  const Vec2 g0(-1, -1), g1(1, 0), g2(0, 1);
  return {(4 * l0 - 1) * g0,       (4 * l1 - 1) * g1,       (4 * l2 - 1) * g2,
          4 * (l0 * g1 + l1 * g0), 4 * (l1 * g2 + l2 * g1), 4 * (l2 * g0 + l0 * g2)};
}

}  // namespace flotsam
