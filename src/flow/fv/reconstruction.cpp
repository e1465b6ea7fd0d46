#include "flow/fv/reconstruction.hpp"

#include <algorithm>
#include <cstddef>

namespace flotsam {

void CellField::resize(int cells) {
  for (auto* a : {&h, &eta, &u, &v}) a->assign(cells, 0.0);
  for (auto* a : {&grad_h, &grad_eta, &grad_u, &grad_v}) a->assign(cells, Vec2::Zero());
  for (auto* a : {&edge_h, &edge_eta, &edge_u, &edge_v}) a->assign(3 * cells, 0.0);
}

namespace {

// Barth-Jespersen: the limited gradient of phi in cell i from the neighbour differences d[k],
// and phi's values at the cell's three edges. The largest alpha keeping every edge value within
// [d_min, d_max] of the cell's is set by the largest and the smallest increment alone.
Vec2 limit(const CellMesh& c, int i, const double d[3], double phi, double* edge) {
  const auto& w = c.gradient_weight[i];
  const auto& r = c.to_edge[i];
  const Vec2 g = d[0] * w[0] + d[1] * w[1] + d[2] * w[2];
  const double d_max = std::max(std::max(0.0, d[0]), std::max(d[1], d[2]));
  const double d_min = std::min(std::min(0.0, d[0]), std::min(d[1], d[2]));
  const double delta[3] = {g.dot(r[0]), g.dot(r[1]), g.dot(r[2])};  // edge - cell value
  const double top = std::max(delta[0], std::max(delta[1], delta[2]));
  const double bottom = std::min(delta[0], std::min(delta[1], delta[2]));
  double alpha = 1.0;
  if (top > d_max) alpha = d_max / top;
  if (bottom < d_min) alpha = std::min(alpha, d_min / bottom);
  for (int k = 0; k < 3; ++k) edge[k] = phi + alpha * delta[k];
  return alpha * g;
}

// Cell i's limited gradients and edge values.
void reconstruct_cell(const CellMesh& c, int order, double dry_depth, CellField& f, int i) {
  if (order < 2 || f.h[i] <= dry_depth) {
    f.grad_h[i] = f.grad_eta[i] = f.grad_u[i] = f.grad_v[i] = Vec2::Zero();
    for (int k = 0; k < 3; ++k) {
      f.edge_h[3 * i + k] = f.h[i];
      f.edge_eta[3 * i + k] = f.eta[i];
      f.edge_u[3 * i + k] = f.u[i];
      f.edge_v[3 * i + k] = f.v[i];
    }
    return;
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
  double* edge_h = &f.edge_h[3 * i];
  f.grad_h[i] = limit(c, i, dh, f.h[i], edge_h);
  for (int k = 0; k < 3; ++k) edge_h[k] = std::max(0.0, edge_h[k]);  // round-off below 0
  f.grad_eta[i] = limit(c, i, deta, f.eta[i], &f.edge_eta[3 * i]);
  f.grad_u[i] = limit(c, i, du, f.u[i], &f.edge_u[3 * i]);
  f.grad_v[i] = limit(c, i, dv, f.v[i], &f.edge_v[3 * i]);
}

}  // namespace

void reconstruct(const CellMesh& c, int order, double dry_depth, CellField& f) {
  const int n = c.cell_count;
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) reconstruct_cell(c, order, dry_depth, f, i);
}

void reconstruct(const CellMesh& c, int order, double dry_depth, CellField& f,
                 std::span<const int> cells) {
  const auto n = static_cast<std::ptrdiff_t>(cells.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t k = 0; k < n; ++k) reconstruct_cell(c, order, dry_depth, f, cells[k]);
}

}  // namespace flotsam
