#include "flow/fv/reconstruction.hpp"

#include <algorithm>

namespace flotsam {

void CellField::resize(int cells) {
  for (auto* a : {&h, &eta, &u, &v}) a->assign(cells, 0.0);
  for (auto* a : {&grad_h, &grad_eta, &grad_u, &grad_v}) a->assign(cells, Vec2::Zero());
}

namespace {

// Barth-Jespersen: the limited gradient of phi in cell i from the neighbour differences d[k].
Vec2 limited_gradient(const CellMesh& c, int i, const double d[3]) {
  const auto& w = c.gradient_weight[i];
  const Vec2 g = d[0] * w[0] + d[1] * w[1] + d[2] * w[2];
  const double d_max = std::max({0.0, d[0], d[1], d[2]});
  const double d_min = std::min({0.0, d[0], d[1], d[2]});
  double alpha = 1.0;
  for (int k = 0; k < 3; ++k) {
    const double delta = g.dot(c.to_edge[i][k]);  // edge value - cell value
    if (delta > d_max)
      alpha = std::min(alpha, d_max / delta);
    else if (delta < d_min)
      alpha = std::min(alpha, d_min / delta);
  }
  return alpha * g;
}

}  // namespace

void reconstruct(const CellMesh& c, int order, double dry_depth, CellField& f) {
  const int n = c.cell_count;
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    if (order < 2 || f.h[i] <= dry_depth) {
      f.grad_h[i] = f.grad_eta[i] = f.grad_u[i] = f.grad_v[i] = Vec2::Zero();
      continue;
    }
    double dh[3], deta[3], du[3], dv[3];
    for (int k = 0; k < 3; ++k) {
      const int j = c.neighbour[i][k];
      const bool wet = j >= 0 && f.h[j] > dry_depth;
      dh[k] = j >= 0 ? f.h[j] - f.h[i] : 0.0;
      deta[k] = wet ? f.eta[j] - f.eta[i] : 0.0;
      du[k] = wet ? f.u[j] - f.u[i] : 0.0;
      dv[k] = wet ? f.v[j] - f.v[i] : 0.0;
    }
    f.grad_h[i] = limited_gradient(c, i, dh);
    f.grad_eta[i] = limited_gradient(c, i, deta);
    f.grad_u[i] = limited_gradient(c, i, du);
    f.grad_v[i] = limited_gradient(c, i, dv);
  }
}

}  // namespace flotsam
