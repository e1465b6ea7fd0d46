// FemFlowField::sample for a batch of points (flow_field.hpp's sample_batch): the points located
// together (PointLocator::locate_batch: most are still in the element of their hint), each
// lane's six nodes' values read from their packs (NodePack, one cache line a node, copied once
// per flow step by pack_states), and the interpolation of fem_flow_field.cpp in loops over the
// lanes that compile to vector code, in sample's order of operations, so that every lane has
// sample's bits. A point in a curved element (isoparametric J, found by Newton) is sampled by
// sample itself.
#include <cstdint>
#include <stdexcept>

#include "core/vector_clones.hpp"
#include "flow/fem/fem_flow_field.hpp"
#include "flow/flow_batch.hpp"
#include "mesh/shape_functions.hpp"

namespace flotsam {
namespace {

constexpr int W = batch_width;

/// Per lane: where its element's six nodes' packs start, J^-T, the point's (r, s) and time;
/// then the flow.
struct FemLanes {
  alignas(64) int pack[6][W];
  alignas(64) double J00[W], J01[W], J10[W], J11[W], r[W], s[W], t[W];
  alignas(64) double N[6][W], gr[6][W], gs[6][W];  // P2 values and d/dr, d/ds
  // fem_flow_field.cpp's sums: u0, u1, G0, G1, z_b, grad z_b, eta0, eta1
  alignas(64) double u0x[W], u0y[W], u1x[W], u1y[W], a00[W], a01[W], a10[W], a11[W];
  alignas(64) double b00[W], b01[W], b10[W], b11[W], z_b[W], z_x[W], z_y[W], eta0[W], eta1[W];
  alignas(64) double H[W], u[W], v[W], g00[W], g01[W], g10[W], g11[W], du[W], dv[W];
};

/// fem_flow_field.cpp's sums, lane by lane in loops over the lanes, node after node, reading
/// the nodes' values from their packs (a virtual function has no clones: this one has).
FLOTSAM_VECTOR_CLONES
void interpolate(FemLanes& L, const double* packs, double t0, double span) {
  using P = NodePack;
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
      const int n = L.pack[j][k];
      const double dx = L.J00[k] * L.gr[j][k] + L.J01[k] * L.gs[j][k];  // d = J^-T grad N_j
      const double dy = L.J10[k] * L.gr[j][k] + L.J11[k] * L.gs[j][k];
      const double ax = packs[n + P::u0], ay = packs[n + P::v0], bx = packs[n + P::u1];
      const double by = packs[n + P::v1], Z = packs[n + P::bed];
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
      L.eta0[k] += M * packs[L.pack[j][k] + P::eta0];
      L.eta1[k] += M * packs[L.pack[j][k] + P::eta1];
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

void FemFlowField::pack_states() {
  using P = NodePack;
  const Mesh& mesh = solver_.mesh();
  const FlowState& s0 = solver_.previous_state();
  const FlowState& s1 = solver_.state();
  const std::vector<double>& z = solver_.bed();
  const int node_count = mesh.node_count(), vertex_count = mesh.vertex_count;
  if (pack_storage_.empty()) {  // 8 doubles more, to start the packs on a 64-byte boundary
    pack_storage_.resize(static_cast<std::size_t>(P::size) * node_count + 8);
    const auto address = reinterpret_cast<std::uintptr_t>(pack_storage_.data());
    pack_ = static_cast<int>((64 - address % 64) % 64 / sizeof(double));
  }
  // One thread: 11 us for 10,535 nodes, 91 us for 101,101 (bench_bodies_forces BM_PackStates);
  // a parallel loop's two threads cost more than that to start on a shared machine.
  double* packs = pack_storage_.data() + pack_;
  for (int n = 0; n < node_count; ++n) {
    double* f = packs + static_cast<std::size_t>(P::size) * n;
    f[P::u0] = s0.u[n], f[P::v0] = s0.v[n], f[P::u1] = s1.u[n], f[P::v1] = s1.v[n];
    f[P::bed] = z[n];
    f[P::eta0] = n < vertex_count ? s0.eta[n] : 0.0;
    f[P::eta1] = n < vertex_count ? s1.eta[n] : 0.0;
  }
  packed_begin_ = s0.time, packed_end_ = s1.time;
}

void FemFlowField::sample_batch(const double* x, const double* y, const double* t,
                                const bool* active, int* hints, BatchFlow& out) const {
  Location where[W];
  locator_.locate_batch(W, x, y, active, hints, where);
  const FlowState& s0 = solver_.previous_state();
  const FlowState& s1 = solver_.state();
  const double span = s1.time - s0.time;  // [s]
  if (packed_begin_ != s0.time || packed_end_ != s1.time)
    throw std::logic_error("FemFlowField: the states changed since pack_states");

  // The lanes interpolated here (inside, straight element); an idle lane reads element 0.
  const double* packs = pack_storage_.data() + pack_;
  bool lane[W];
  FemLanes L;
  for (int k = 0; k < W; ++k) {
    const Location& w = where[k];
    lane[k] = active[k] && w.inside && !w.curved;
    if (active[k] && w.inside && w.curved)  // the same location from the same hint
      out.set(k, sample({x[k], y[k]}, t[k], hints[k]));
    else if (active[k] && w.element >= 0)
      hints[k] = w.element;
    const ElementRecord& element = elements_[lane[k] ? w.element : 0];
    for (int j = 0; j < 6; ++j) L.pack[j][k] = element.pack[j];
    const double* J = element.J;
    L.J00[k] = J[0], L.J01[k] = J[1], L.J10[k] = J[2], L.J11[k] = J[3];
    L.r[k] = lane[k] ? w.r : 0.0, L.s[k] = lane[k] ? w.s : 0.0, L.t[k] = t[k];
  }

  interpolate(L, packs, s0.time, span);
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
