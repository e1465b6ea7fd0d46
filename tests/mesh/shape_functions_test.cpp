#include "mesh/shape_functions.hpp"

#include <gtest/gtest.h>

namespace flotsam {
namespace {

const std::array<Vec2, 6> reference_nodes = {Vec2(0, 0),   Vec2(1, 0),     Vec2(0, 1),
                                             Vec2(0.5, 0), Vec2(0.5, 0.5), Vec2(0, 0.5)};

TEST(ShapeFunctions, P2IsKroneckerAtNodesAndSumsToOne) {
  for (int i = 0; i < 6; ++i) {
    const auto N = p2_values(reference_nodes[i].x(), reference_nodes[i].y());
    for (int j = 0; j < 6; ++j) EXPECT_NEAR(N[j], i == j ? 1.0 : 0.0, 1e-15);
  }
  const auto N = p2_values(0.21, 0.37);
  double sum = 0;
  for (double v : N) sum += v;
  EXPECT_NEAR(sum, 1.0, 1e-15);
}

TEST(ShapeFunctions, P2GradientsMatchFiniteDifferences) {
  const double r = 0.23, s = 0.41, h = 1e-6;
  const auto G = p2_reference_gradients(r, s);
  const auto Nr1 = p2_values(r + h, s), Nr0 = p2_values(r - h, s);
  const auto Ns1 = p2_values(r, s + h), Ns0 = p2_values(r, s - h);
  for (int j = 0; j < 6; ++j) {
    EXPECT_NEAR(G[j].x(), (Nr1[j] - Nr0[j]) / (2 * h), 1e-8);
    EXPECT_NEAR(G[j].y(), (Ns1[j] - Ns0[j]) / (2 * h), 1e-8);
  }
}

TEST(ShapeFunctions, P1IsKroneckerAtVertices) {
  for (int i = 0; i < 3; ++i) {
    const auto N = p1_values(reference_nodes[i].x(), reference_nodes[i].y());
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(N[j], i == j ? 1.0 : 0.0, 1e-15);
  }
}

}  // namespace
}  // namespace flotsam
