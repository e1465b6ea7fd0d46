// FvFlowField::sample for a batch of points (flow_field.hpp's sample_batch): the points located
// together (PointLocator::locate_batch: most are still in the element of their hint), the data
// of their cells gathered into flat arrays, one lane per point, and the reconstruction of
// fv_flow_field.cpp in a loop over the lanes that compiles to vector code, in sample's order of
// operations, so that every lane has sample's bits.
#include "core/vector_clones.hpp"
#include "flow/flow_batch.hpp"
#include "flow/fv/fv_flow_field.hpp"

namespace flotsam {
namespace {

constexpr int W = batch_width;

/// Per lane: d = p - centroid, the cell's bed, and per state (0: begin, 1: end) its cell's
/// values; then the flow reconstructed from them.
struct FvLanes {
  alignas(64) double dx[W], dy[W], z0[W], sx[W], sy[W], t[W];
  alignas(64) double wet[2][W], eta[2][W], ex[2][W], ey[2][W];  // h > 0, eta, grad eta
  alignas(64) double u[2][W], ux[2][W], uy[2][W], v[2][W], vx[2][W], vy[2][W];
  alignas(64) double H[W], uo[W], vo[W], g00[W], g01[W], g10[W], g11[W], du[W], dv[W];
};

/// fv_flow_field.cpp's reconstruction, lane by lane (std::max(a, b) = a < b ? b : a; a virtual
/// function has no clones: this one has).
FLOTSAM_VECTOR_CLONES
void reconstruct(FvLanes& L, double t0, double span) {
#pragma omp simd
  for (int k = 0; k < W; ++k) {
    const double z_b = L.z0[k] + (L.sx[k] * L.dx[k] + L.sy[k] * L.dy[k]);  // the cell's mean z_i
    const double a = time_weight(L.t[k], t0, span);
    double h = 0.0, G00 = 0.0, G01 = 0.0, G10 = 0.0, G11 = 0.0;
    double u_at[2], v_at[2];
    for (int s = 0; s < 2; ++s) {
      const double w = s == 0 ? 1.0 - a : a;
      const double eta_s =
          L.wet[s][k] != 0.0 ? L.eta[s][k] + (L.ex[s][k] * L.dx[k] + L.ey[s][k] * L.dy[k]) : z_b;
      const double depth = eta_s - z_b;
      h += w * (0.0 < depth ? depth : 0.0);
      u_at[s] = L.u[s][k] + (L.ux[s][k] * L.dx[k] + L.uy[s][k] * L.dy[k]);
      v_at[s] = L.v[s][k] + (L.vx[s][k] * L.dx[k] + L.vy[s][k] * L.dy[k]);
      G00 += w * L.ux[s][k], G01 += w * L.uy[s][k];
      G10 += w * L.vx[s][k], G11 += w * L.vy[s][k];
    }
    L.H[k] = h;
    L.uo[k] = (1.0 - a) * u_at[0] + a * u_at[1], L.vo[k] = (1.0 - a) * v_at[0] + a * v_at[1];
    L.g00[k] = G00, L.g01[k] = G01, L.g10[k] = G10, L.g11[k] = G11;
    L.du[k] = span > 0.0 ? (u_at[1] - u_at[0]) / span : 0.0;
    L.dv[k] = span > 0.0 ? (v_at[1] - v_at[0]) / span : 0.0;
  }
}

}  // namespace

void FvFlowField::sample_batch(const double* x, const double* y, const double* t,
                               const bool* active, int* hints, BatchFlow& out) const {
  Location where[W];
  locator_->locate_batch(W, x, y, active, hints, where);
  const CellMesh& c = solver_.cells();
  const std::vector<double>& cell_bed = solver_.bed();
  const double span = t1_ - t0_;  // [s]

  bool lane[W], any = false;
  for (int k = 0; k < W; ++k) {
    lane[k] = active[k] && where[k].inside;
    any = any || lane[k];
    if (active[k] && where[k].element >= 0) hints[k] = where[k].element;
  }
  if (!any) {  // nothing to read (the states need not exist yet)
    for (int k = 0; k < W; ++k) out.set(k, FlowSample{.inside = false});
    return;
  }
  FvLanes L;
  for (int k = 0; k < W; ++k) {
    const Location& w = where[k];
    const int i = lane[k] ? c.cell_of(w.element, w.r, w.s) : 0;  // cell 0: numbers for idle lanes
    L.dx[k] = x[k] - c.centroid[i].x(), L.dy[k] = y[k] - c.centroid[i].y();
    L.z0[k] = cell_bed[i], L.sx[k] = bed_slope_[i].x(), L.sy[k] = bed_slope_[i].y();
    L.t[k] = t[k];
    for (int s = 0; s < 2; ++s) {
      const CellField& f = s == 0 ? begin_ : end_;
      L.wet[s][k] = f.h[i] > 0.0 ? 1.0 : 0.0;
      L.eta[s][k] = f.eta[i], L.ex[s][k] = f.grad_eta[i].x(), L.ey[s][k] = f.grad_eta[i].y();
      L.u[s][k] = f.u[i], L.ux[s][k] = f.grad_u[i].x(), L.uy[s][k] = f.grad_u[i].y();
      L.v[s][k] = f.v[i], L.vx[s][k] = f.grad_v[i].x(), L.vy[s][k] = f.grad_v[i].y();
    }
  }

  reconstruct(L, t0_, span);
  for (int k = 0; k < W; ++k) {
    if (!lane[k]) {
      out.set(k, FlowSample{.inside = false});
      continue;
    }
    const int i = c.cell_of(where[k].element, where[k].r, where[k].s);
    out.inside[k] = 1.0;
    out.H[k] = L.H[k], out.u[k] = L.uo[k], out.v[k] = L.vo[k];
    out.g00[k] = L.g00[k], out.g01[k] = L.g01[k], out.g10[k] = L.g10[k], out.g11[k] = L.g11[k];
    out.du_dt[k] = L.du[k], out.dv_dt[k] = L.dv[k];
    out.zb_x[k] = bed_slope_[i].x(), out.zb_y[k] = bed_slope_[i].y();
  }
}

}  // namespace flotsam
