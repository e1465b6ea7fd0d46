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

/// The nodal fields the lanes read, as flat arrays indexed by mesh node.
struct FemNodes {
  const double *u0, *v0, *u1, *v1, *eta0, *eta1, *bed;  // the step's two states, the bed
};

/// Per lane: its element's six nodes, J^-T, the point's (r, s) and time; then the flow.
struct FemLanes {
  alignas(64) int node[6][W];
  alignas(64) double J00[W], J01[W], J10[W], J11[W], r[W], s[W], t[W];
  alignas(64) double N[6][W], gr[6][W], gs[6][W];  // P2 values and d/dr, d/ds
  // fem_flow_field.cpp's sums: u0, u1, G0, G1, z_b, grad z_b, eta0, eta1
  alignas(64) double u0x[W], u0y[W], u1x[W], u1y[W], a00[W], a01[W], a10[W], a11[W];
  alignas(64) double b00[W], b01[W], b10[W], b11[W], z_b[W], z_x[W], z_y[W], eta0[W], eta1[W];
  alignas(64) double H[W], u[W], v[W], g00[W], g01[W], g10[W], g11[W], du[W], dv[W];
};

/// fem_flow_field.cpp's sums, lane by lane in loops over the lanes, node after node, reading
/// the nodes' values where they are (a virtual function has no clones: this one has).
FLOTSAM_VECTOR_CLONES
void interpolate(FemLanes& L, const FemNodes& f, double t0, double span) {
#pragma omp simd
  for (int k = 0; k < W; ++k) {
    p2_basis(L.r[k], L.s[k], &L.N[0][k], &L.gr[0][k], &L.gs[0][k], W);
    L.u0x[k] = L.u0y[k] = L.u1x[k] = L.u1y[k] = 0.0;
    L.a00[k] = L.a01[k] = L.a10[k] = L.a11[k] = 0.0;
    L.b00[k] = L.b01[k] = L.b10[k] = L.b11[k] = 0.0;
    L.z_b[k] = L.z_x[k] = L.z_y[k] = L.eta0[k] = L.eta1[k] = 0.0;
  }
  for (int j = 0; j < 6; ++j) {
#pragma omp simd
    for (int k = 0; k < W; ++k) {
      const int n = L.node[j][k];
      const double dx = L.J00[k] * L.gr[j][k] + L.J01[k] * L.gs[j][k];  // d = J^-T grad N_j
      const double dy = L.J10[k] * L.gr[j][k] + L.J11[k] * L.gs[j][k];
      const double ax = f.u0[n], ay = f.v0[n], bx = f.u1[n], by = f.v1[n], Z = f.bed[n];
      const double N = L.N[j][k];
      L.u0x[k] += N * ax, L.u0y[k] += N * ay;
      L.u1x[k] += N * bx, L.u1y[k] += N * by;
      L.a00[k] += ax * dx, L.a01[k] += ax * dy, L.a10[k] += ay * dx, L.a11[k] += ay * dy;
      L.b00[k] += bx * dx, L.b01[k] += bx * dy, L.b10[k] += by * dx, L.b11[k] += by * dy;
      L.z_b[k] += N * Z;
      L.z_x[k] += Z * dx, L.z_y[k] += Z * dy;
    }
  }
  for (int j = 0; j < 3; ++j) {
#pragma omp simd
    for (int k = 0; k < W; ++k) {
      const double M = j == 0 ? 1.0 - L.r[k] - L.s[k] : j == 1 ? L.r[k] : L.s[k];  // p1_values
      L.eta0[k] += M * f.eta0[L.node[j][k]];
      L.eta1[k] += M * f.eta1[L.node[j][k]];
    }
  }
#pragma omp simd
  for (int k = 0; k < W; ++k) {
    const double a = time_weight(L.t[k], t0, span), b = 1 - a;
    const double eta = b * L.eta0[k] + a * L.eta1[k];
    L.H[k] = eta - L.z_b[k];
    L.u[k] = b * L.u0x[k] + a * L.u1x[k], L.v[k] = b * L.u0y[k] + a * L.u1y[k];
    L.g00[k] = b * L.a00[k] + a * L.b00[k], L.g01[k] = b * L.a01[k] + a * L.b01[k];
    L.g10[k] = b * L.a10[k] + a * L.b10[k], L.g11[k] = b * L.a11[k] + a * L.b11[k];
    L.du[k] = span > 0.0 ? (L.u1x[k] - L.u0x[k]) / span : 0.0;
    L.dv[k] = span > 0.0 ? (L.u1y[k] - L.u0y[k]) / span : 0.0;
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
  const double span = s1.time - s0.time;  // [s]

  // The lanes interpolated here (inside, straight element); an idle lane reads element 0.
  bool lane[W];
  FemLanes L;
  for (int k = 0; k < W; ++k) {
    const Location& w = where[k];
    lane[k] = active[k] && w.inside && !w.curved;
    if (active[k] && w.inside && w.curved)  // the same location from the same hint
      out.set(k, sample({x[k], y[k]}, t[k], hints[k]));
    else if (active[k] && w.element >= 0)
      hints[k] = w.element;
    const int e = lane[k] ? w.element : 0;
    const auto& el = mesh.elements[e];
    for (int j = 0; j < 6; ++j) L.node[j][k] = el[j];
    const Mat2& J = straight_inverse_[e];
    L.J00[k] = J(0, 0), L.J01[k] = J(0, 1), L.J10[k] = J(1, 0), L.J11[k] = J(1, 1);
    L.r[k] = lane[k] ? w.r : 0.0, L.s[k] = lane[k] ? w.s : 0.0, L.t[k] = t[k];
  }

  interpolate(L,
              {s0.u.data(), s0.v.data(), s1.u.data(), s1.v.data(), s0.eta.data(), s1.eta.data(),
               solver_.bed().data()},
              s0.time, span);
  for (int k = 0; k < W; ++k) {
    if (!lane[k]) {
      if (!(active[k] && where[k].inside)) out.set(k, FlowSample{.inside = false});
      continue;
    }
    out.inside[k] = 1.0;
    out.H[k] = L.H[k], out.u[k] = L.u[k], out.v[k] = L.v[k];
    out.g00[k] = L.g00[k], out.g01[k] = L.g01[k], out.g10[k] = L.g10[k], out.g11[k] = L.g11[k];
    out.du_dt[k] = L.du[k], out.dv_dt[k] = L.dv[k];
    out.zb_x[k] = L.z_x[k], out.zb_y[k] = L.z_y[k];
  }
}

}  // namespace flotsam
