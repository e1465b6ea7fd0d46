// FemFlowField::sample for a batch of points (flow_field.hpp's sample_batch): the points located
// together (PointLocator::locate_batch: most are still in the element of their hint), the nodal
// values of their elements gathered into flat arrays, one lane per point, and the interpolation
// of fem_flow_field.cpp in loops over the lanes that compile to vector code, in sample's order of
// operations, so that every lane has sample's bits. A point in a curved element (isoparametric
// J, found by Newton) is sampled by sample itself.
#include "core/vector_clones.hpp"
#include "flow/fem/fem_flow_field.hpp"
#include "flow/flow_batch.hpp"
#include "mesh/shape_functions.hpp"

namespace flotsam {
namespace {

constexpr int W = batch_width;

/// The lanes' data gathered from their elements, and the flow interpolated from them.
struct FemLanes {
  alignas(64) double N[6][W], gr[6][W], gs[6][W];  // P2 values and d/dr, d/ds
  alignas(64) double U0[6][W], V0[6][W], U1[6][W], V1[6][W], Z[6][W], E0[3][W], E1[3][W];
  alignas(64) double J00[W], J01[W], J10[W], J11[W], r[W], s[W], t[W];
  alignas(64) double H[W], u[W], v[W], g00[W], g01[W], g10[W], g11[W], du[W], dv[W], zx[W], zy[W];
};

/// fem_flow_field.cpp's sums, lane by lane (a virtual function has no clones: this one has).
FLOTSAM_VECTOR_CLONES
void interpolate(FemLanes& L, double t0, double span) {
#pragma omp simd
  for (int k = 0; k < W; ++k) {
    const double a = time_weight(L.t[k], t0, span);
    double u0x = 0.0, u0y = 0.0, u1x = 0.0, u1y = 0.0, z_b = 0.0, z_x = 0.0, z_y = 0.0;
    double a00 = 0.0, a01 = 0.0, a10 = 0.0, a11 = 0.0;  // G0
    double b00 = 0.0, b01 = 0.0, b10 = 0.0, b11 = 0.0;  // G1
    for (int j = 0; j < 6; ++j) {
      const double dx = L.J00[k] * L.gr[j][k] + L.J01[k] * L.gs[j][k];  // d = J^-T grad N_j
      const double dy = L.J10[k] * L.gr[j][k] + L.J11[k] * L.gs[j][k];
      const double ax = L.U0[j][k], ay = L.V0[j][k], bx = L.U1[j][k], by = L.V1[j][k];
      const double N = L.N[j][k], Z = L.Z[j][k];
      u0x += N * ax, u0y += N * ay;
      u1x += N * bx, u1y += N * by;
      a00 += ax * dx, a01 += ax * dy, a10 += ay * dx, a11 += ay * dy;
      b00 += bx * dx, b01 += bx * dy, b10 += by * dx, b11 += by * dy;
      z_b += N * Z;
      z_x += Z * dx, z_y += Z * dy;
    }
    const double M0 = 1.0 - L.r[k] - L.s[k], M1 = L.r[k], M2 = L.s[k];  // p1_values
    double eta0 = 0.0, eta1 = 0.0;
    eta0 += M0 * L.E0[0][k], eta1 += M0 * L.E1[0][k];
    eta0 += M1 * L.E0[1][k], eta1 += M1 * L.E1[1][k];
    eta0 += M2 * L.E0[2][k], eta1 += M2 * L.E1[2][k];
    const double b = 1 - a;
    const double eta = b * eta0 + a * eta1;
    L.H[k] = eta - z_b;
    L.u[k] = b * u0x + a * u1x, L.v[k] = b * u0y + a * u1y;
    L.g00[k] = b * a00 + a * b00, L.g01[k] = b * a01 + a * b01;
    L.g10[k] = b * a10 + a * b10, L.g11[k] = b * a11 + a * b11;
    L.du[k] = span > 0.0 ? (u1x - u0x) / span : 0.0;
    L.dv[k] = span > 0.0 ? (u1y - u0y) / span : 0.0;
    L.zx[k] = z_x, L.zy[k] = z_y;
  }
}

}  // namespace

void FemFlowField::sample_batch(const double* x, const double* y, const double* t,
                                const bool* active, int* hints, BatchFlow& out) const {
  Location where[W];
  locator_.locate_batch(W, x, y, active, hints, where);
  const Mesh& mesh = solver_.mesh();
  const FlowState& s0 = solver_.previous_state();
  const FlowState& s1 = solver_.state();
  const std::vector<double>& bed = solver_.bed();
  const double span = s1.time - s0.time;  // [s]

  // The lanes interpolated here (inside, straight element), with their element's data.
  bool lane[W];
  FemLanes L;
  for (int k = 0; k < W; ++k) {
    const Location& w = where[k];
    lane[k] = active[k] && w.inside && !w.curved;
    if (active[k] && w.inside && w.curved) {
      out.set(k, sample({x[k], y[k]}, t[k], hints[k]));  // the same location from the same hint
      continue;
    }
    if (active[k] && w.element >= 0) hints[k] = w.element;
    if (!lane[k]) {
      out.set(k, FlowSample{.inside = false});
      L.r[k] = L.s[k] = L.t[k] = 0.0;  // numbers for the idle lane's loop below
      L.J00[k] = L.J01[k] = L.J10[k] = L.J11[k] = 0.0;
      for (int j = 0; j < 6; ++j)
        L.U0[j][k] = L.V0[j][k] = L.U1[j][k] = L.V1[j][k] = L.Z[j][k] = 0.0;
      for (int j = 0; j < 3; ++j) L.E0[j][k] = L.E1[j][k] = 0.0;
      for (int j = 0; j < 6; ++j) L.N[j][k] = L.gr[j][k] = L.gs[j][k] = 0.0;
      continue;
    }
    const auto& el = mesh.elements[w.element];
    const P2Values Nk = p2_values(w.r, w.s);
    const P2Gradients g2 = p2_reference_gradients(w.r, w.s);
    for (int j = 0; j < 6; ++j) {
      const int n = el[j];
      L.N[j][k] = Nk[j], L.gr[j][k] = g2[j].x(), L.gs[j][k] = g2[j].y();
      L.U0[j][k] = s0.u[n], L.V0[j][k] = s0.v[n], L.U1[j][k] = s1.u[n], L.V1[j][k] = s1.v[n];
      L.Z[j][k] = bed[n];
    }
    for (int j = 0; j < 3; ++j) L.E0[j][k] = s0.eta[el[j]], L.E1[j][k] = s1.eta[el[j]];
    const Mat2& J = straight_inverse_[w.element];
    L.J00[k] = J(0, 0), L.J01[k] = J(0, 1), L.J10[k] = J(1, 0), L.J11[k] = J(1, 1);
    L.r[k] = w.r, L.s[k] = w.s;
    L.t[k] = t[k];
  }

  interpolate(L, s0.time, span);
  for (int k = 0; k < W; ++k) {
    if (!lane[k]) continue;
    out.inside[k] = 1.0;
    out.H[k] = L.H[k], out.u[k] = L.u[k], out.v[k] = L.v[k];
    out.g00[k] = L.g00[k], out.g01[k] = L.g01[k], out.g10[k] = L.g10[k], out.g11[k] = L.g11[k];
    out.du_dt[k] = L.du[k], out.dv_dt[k] = L.dv[k];
    out.zb_x[k] = L.zx[k], out.zb_y[k] = L.zy[k];
  }
}

}  // namespace flotsam
