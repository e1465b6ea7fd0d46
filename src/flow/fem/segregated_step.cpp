// Eigen's CHOLMOD view of a sparse matrix: GCC sees a null outer index where there is none.
#pragma GCC diagnostic ignored "-Wnull-dereference"
#include "flow/fem/segregated_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "core/parallel_for.hpp"
#include "flow/fem/node_ordering.hpp"
#include "flow/fem/pair_conjugate_gradients.hpp"
#include "flow/fem/serial_blas.hpp"
#include "flow/fem/shallow_water_solver.hpp"
#include "flow/fem/turbulence.hpp"

namespace flotsam {

namespace {

constexpr int max_extra_iterations = 3;    // GMRES iterations an aged factor may need beyond a
                                           // fresh one's before it is refactorised
constexpr int max_fresh_iterations = 40;   // GMRES iterations with a fresh factor
constexpr double gmres_tolerance = 1e-12;  // [-] |r| / |b| that ends an elevation solve
constexpr int max_cg_iterations = 200;     // [-] of the momentum predictor (incomplete Cholesky
                                           // preconditioned: a few to ten)
// |r| / |b| that ends the momentum predictor's solve, per component [-]: u~'s relative error is
// then 1e-8 times the matrix's condition (lumped mass over dt plus the viscous stiffness), far
// below the step's own error (the verification cases and the step-convergence test pass as
// with 1e-10, which took a third more iterations: docs/model.md "The segregated step").
constexpr double predictor_tolerance = 1e-8;
// s, the part of the surface slope at t^n, g G eta^n, taken at the paths' feet (M-20); the
// rest, and the implicit increment theta g G d_eta, at the arriving node (M-21), (M-23). With
// s = 1/2 the slope's time integral along the path is centred in space, as the advection by
// characteristics is, and a steady flow has no error O(dt); the coupled step's s = 1 - theta
// (the time off-centring taken in space too) leaves a steady error O((theta - 1/2) dt u . grad)
// that made the shortened paper channel's discharge 1.9 % lower at dt = 1 s than at 0.1 s. But
// with theta > 1/2 the gravity waves moving with the current are damped only while s < 1/2 (at
// 1/2 the bump of subcritical_bump.cpp does not settle; at 0.48 it settles 1.2 % from Bernoulli,
// against 0.8 % at 0.4). Halfway, s = 3/4 - theta/2 (0.45 at theta = 0.6, 1/2 at theta = 1/2),
// halves that error and keeps the damping (docs/model.md "The segregated step"). BDF2 takes every
// term at t^{n+1} at the node (its time derivative along the path is second order by itself):
// none at the feet. [-]
double slope_at_feet(TimeScheme scheme, double theta) {
  return scheme == TimeScheme::bdf2 ? 0.0 : 0.75 - 0.5 * theta;
}

using Vector = Eigen::VectorXd;

// GMRES for A x = b, right-preconditioned (A P^-1 y = b, x = P^-1 y), from x, without restart:
// apply(p, Ap) computes A p, precondition(r, z) z = P^-1 r. Returns the iterations, or
// max_iterations + 1 when |b - A x| > tolerance |b| after them (x then holds the last iterate).
template <class Apply, class Precondition>
int gmres(const Apply& apply, const Precondition& precondition, const Vector& b, Vector& x,
          double tolerance, int max_iterations, Eigen::MatrixXd& V, Eigen::MatrixXd& Z) {
  const Eigen::Index n = x.size();
  const int m = max_iterations;
  Vector r(n), w(n);
  apply(x, w);
  r = b - w;
  const double beta = r.norm(), stop = tolerance * std::max(b.norm(), 1e-300);
  if (beta <= stop) return 0;
  if (V.rows() != n || V.cols() < m + 1) V.resize(n, m + 1);  // kept by the caller
  if (Z.rows() != n || Z.cols() < m) Z.resize(n, m);
  Eigen::MatrixXd Hess = Eigen::MatrixXd::Zero(m + 1, m);
  Vector cs = Vector::Zero(m), sn = Vector::Zero(m), g = Vector::Zero(m + 1);
  V.col(0) = r / beta;
  g[0] = beta;
  int k = 0;
  bool converged = false;
  while (k < m && !converged) {
    Vector z(n);
    precondition(V.col(k), z);
    Z.col(k) = z;
    apply(z, w);
    for (int i = 0; i <= k; ++i) {  // modified Gram-Schmidt
      Hess(i, k) = V.col(i).dot(w);
      w -= Hess(i, k) * V.col(i);
    }
    Hess(k + 1, k) = w.norm();
    if (Hess(k + 1, k) > 0.0) V.col(k + 1) = w / Hess(k + 1, k);
    for (int i = 0; i < k; ++i) {  // the earlier Givens rotations
      const double t = cs[i] * Hess(i, k) + sn[i] * Hess(i + 1, k);
      Hess(i + 1, k) = -sn[i] * Hess(i, k) + cs[i] * Hess(i + 1, k);
      Hess(i, k) = t;
    }
    const double d = std::hypot(Hess(k, k), Hess(k + 1, k));
    cs[k] = Hess(k, k) / d;
    sn[k] = Hess(k + 1, k) / d;
    Hess(k, k) = d;
    Hess(k + 1, k) = 0.0;
    g[k + 1] = -sn[k] * g[k];
    g[k] *= cs[k];
    ++k;
    converged = std::abs(g[k]) <= stop;
  }
  const Vector y = Hess.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
  x += Z.leftCols(k) * y;
  return converged ? k : max_iterations + 1;
}

// A compressed column-major matrix of `rows` rows whose column j sums, over the elements listed
// for it (list[start[j]] .. list[start[j + 1]], in that order), what entries(e, j, add) adds with
// add(row, value): rows sorted, each entry's terms summed in the list's order.
template <class Entries>
Eigen::SparseMatrix<double, Eigen::ColMajor, int> column_assembled(int columns, int rows,
                                                                   const std::vector<int>& start,
                                                                   const std::vector<int>& list,
                                                                   const Entries& entries) {
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> A(rows, columns);
  std::vector<int> slot(rows, -1), touched;
  std::vector<int> outer(columns + 1, 0), inner;
  std::vector<double> values, sums;
  for (int j = 0; j < columns; ++j) {
    touched.clear();
    sums.clear();
    for (int k = start[j]; k < start[j + 1]; ++k)
      entries(list[k], j, [&](int row, double value) {
        if (slot[row] < 0) {
          slot[row] = static_cast<int>(touched.size());
          touched.push_back(row);
          sums.push_back(0.0);
        }
        sums[slot[row]] += value;
      });
    std::vector<int> order(touched.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return touched[a] < touched[b]; });
    for (int k : order) {
      inner.push_back(touched[k]);
      values.push_back(sums[k]);
    }
    for (int row : touched) slot[row] = -1;
    outer[j + 1] = static_cast<int>(inner.size());
  }
  A.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), A.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), A.innerIndexPtr());
  std::copy(values.begin(), values.end(), A.valuePtr());
  return A;
}

}  // namespace

SegregatedStep::SegregatedStep(const ShallowWaterSolver& solver) : mesh_(solver.mesh()) {
  const int N2 = mesh_.node_count(), N1 = mesh_.vertex_count, E = mesh_.element_count();
  m_.assign(N2, 0.0);
  k_geometry_.assign(21 * static_cast<size_t>(E), 0.0);
  // Per element, each node's share of it (M_L's weight) and the integrals of grad M_i: G's
  // entries, assembled by columns below (a list of all entries would triple the peak memory).
  std::vector<std::array<double, 6>> weight(E);  // [-]
  std::vector<std::array<Vec2, 3>> slope(E);     // [m]
  std::vector<Eigen::Triplet<double>> m1;
  m1.reserve(9 * static_cast<size_t>(E));
  ElementValues ev;
  for (int e = 0; e < E; ++e) {
    compute_element_values(mesh_, e, ev, false);
    const auto& el = mesh_.elements[e];
    std::array<double, 6> diagonal{};  // (N_a, N_a) [m^2]
    slope[e].fill(Vec2::Zero());       // integral of grad M_i over the element [m]
    double area = 0.0;
    for (int q = 0; q < triangle_point_count; ++q) {
      area += ev.JxW[q];
      for (int a = 0; a < 6; ++a) diagonal[a] += ev.N2[q][a] * ev.N2[q][a] * ev.JxW[q];
      for (int a = 0, ab = 21 * e; a < 6; ++a)  // (grad N_a, grad N_b), b >= a
        for (int b = a; b < 6; ++b, ++ab)
          k_geometry_[ab] += ev.dN2[q][a].dot(ev.dN2[q][b]) * ev.JxW[q];
      for (int i = 0; i < 3; ++i) {
        slope[e][i] += ev.dN1[q][i] * ev.JxW[q];
        for (int j = 0; j < 3; ++j)
          m1.emplace_back(el[i], el[j], ev.N1[q][i] * ev.N1[q][j] * ev.JxW[q]);  // (8)
      }
    }
    double sum = 0.0;
    for (double d : diagonal) sum += d;
    for (int a = 0; a < 6; ++a) {
      weight[e][a] = diagonal[a] / sum;  // [-] node a's share of the element (M_L)
      m_[el[a]] += area * weight[e][a];  // M_L, diagonal scaling
    }
  }
  mid_ends_.assign(N2 - N1, {0, 0});
  for (int e = 0; e < E; ++e)
    for (int side = 0; side < 3; ++side)
      mid_ends_[mesh_.elements[e][3 + side] - N1] = {mesh_.elements[e][side],
                                                     mesh_.elements[e][(side + 1) % 3]};
  // The elements at each node, in increasing order.
  std::vector<int> at_start(N2 + 1, 0), at_node(6 * static_cast<size_t>(E));
  for (const auto& el : mesh_.elements)
    for (int a : el) ++at_start[a + 1];
  for (int a = 0; a < N2; ++a) at_start[a + 1] += at_start[a];
  {
    std::vector<int> fill(at_start.begin(), at_start.end() - 1);
    for (int e = 0; e < E; ++e)
      for (int a : mesh_.elements[e]) at_node[fill[a]++] = e;
  }
  // (3) (9) in M_L's nodal quadrature, by columns: G_(2a+c),i = sum over the elements e at
  // vertex i of m_a^e (d M_i / d x_c)_e, in increasing e (the sums as a list of entries made them).
  G_ = column_assembled(N1, 2 * N2, at_start, at_node, [&](int e, int i, auto add) {
    const auto& el = mesh_.elements[e];
    const int local = el[0] == i ? 0 : el[1] == i ? 1 : 2;
    for (int a = 0; a < 6; ++a)
      for (int c = 0; c < 2; ++c) add(2 * el[a] + c, weight[e][a] * slope[e][local][c]);
  });
  weight = {};
  slope = {};
  M1_.resize(N1, N1);
  M1_.setFromTriplets(m1.begin(), m1.end());
  m1 = {};
  plan_schur_matrix(M1_);
  // K_nu's pattern, its unknowns renumbered by locality (reverse Cuthill-McKee) for the
  // predictor's sweeps and its incomplete factor.
  const SparseMatrix pattern =
      column_assembled(N2, N2, at_start, at_node, [&](int e, int, auto add) {
        for (int b : mesh_.elements[e]) add(b, 0.0);
      });
  node_order_ = reverse_cuthill_mckee(pattern);
  std::vector<int> old_of(N2), at_new(at_node.size()), at_new_start(N2 + 1, 0);
  for (int a = 0; a < N2; ++a) old_of[node_order_[a]] = a;
  for (int k = 0; k < N2; ++k) {
    at_new_start[k + 1] = at_new_start[k] + at_start[old_of[k] + 1] - at_start[old_of[k]];
    std::copy(at_node.begin() + at_start[old_of[k]], at_node.begin() + at_start[old_of[k] + 1],
              at_new.begin() + at_new_start[k]);
  }
  K_ = column_assembled(N2, N2, at_new_start, at_new, [&](int e, int, auto add) {
    for (int b : mesh_.elements[e]) add(node_order_[b], 0.0);
  });
  // K_nu is assembled by the elements in the order of their first node in K_'s order, so that
  // its additions stay within a band of K_'s values rather than jump across all of them.
  k_elements_.resize(E);
  {
    std::vector<int> first(E);
    for (int e = 0; e < E; ++e) {
      first[e] = N2;
      for (int a : mesh_.elements[e]) first[e] = std::min(first[e], node_order_[a]);
      k_elements_[e] = e;
    }
    std::stable_sort(k_elements_.begin(), k_elements_.end(),
                     [&](int d, int e) { return first[d] < first[e]; });
  }
  {
    std::vector<double> by_element(21 * static_cast<size_t>(E));
    for (int i = 0; i < E; ++i)
      std::copy_n(k_geometry_.begin() + 21 * static_cast<ptrdiff_t>(k_elements_[i]), 21,
                  by_element.begin() + 21 * static_cast<ptrdiff_t>(i));
    k_geometry_.swap(by_element);
  }
  k_position_.resize(36 * static_cast<size_t>(E));
  for (int i = 0; i < E; ++i) {
    const auto& el = mesh_.elements[k_elements_[i]];
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b) {
        const int column = node_order_[el[b]];
        const int* begin = K_.innerIndexPtr() + K_.outerIndexPtr()[column];
        const int* end = K_.innerIndexPtr() + K_.outerIndexPtr()[column + 1];
        k_position_[36 * i + 6 * a + b] =
            static_cast<int>(std::lower_bound(begin, end, node_order_[el[a]]) - K_.innerIndexPtr());
      }
  }
  predictor_factor_.analyse(K_);
}

// The pattern of S = M_1 + G^T D G (D: 2x2 blocks per P2 node) and, per node a, where each
// product of its rows of G (2a and 2a + 1 share their columns) lands in S's values, so that
// (M-22) is assembled in place each step.
void SegregatedStep::plan_schur_matrix(const SparseMatrix& M1) {
  const int N2 = mesh_.node_count();
  S_ = SparseMatrix(G_.transpose() * G_) + M1;
  S_.makeCompressed();
  std::fill(S_.valuePtr(), S_.valuePtr() + S_.nonZeros(), 0.0);
  const auto position = [&](int i, int j) {
    const int* begin = S_.innerIndexPtr() + S_.outerIndexPtr()[j];
    const int* end = S_.innerIndexPtr() + S_.outerIndexPtr()[j + 1];
    return static_cast<int>(std::lower_bound(begin, end, i) - S_.innerIndexPtr());
  };
  const int* vertex = G_.innerIndexPtr();
  size_t pairs = 0;
  for (int a = 0; a < N2; ++a) {
    const size_t count = G_.outerIndexPtr()[2 * a + 1] - G_.outerIndexPtr()[2 * a];
    pairs += count * count;
  }
  schur_position_.clear();
  schur_position_.reserve(pairs);
  carried_local_.assign(N2, {-1, -1});
  for (int a = 0; a < N2; ++a) {
    const int begin = G_.outerIndexPtr()[2 * a], end = G_.outerIndexPtr()[2 * a + 1];
    for (int p = begin; p < end; ++p)
      for (int q = begin; q < end; ++q) schur_position_.push_back(position(vertex[p], vertex[q]));
    // The vertices that x_a interpolates from, among the row's (C's columns).
    const int N1 = mesh_.vertex_count;
    const std::array<int, 2> ends =
        a < N1 ? std::array<int, 2>{a, -1}
               : std::array<int, 2>{mid_ends_[a - N1][0], mid_ends_[a - N1][1]};
    for (int m = 0; m < 2 && ends[m] >= 0; ++m) {
      const int* found = std::find(vertex + begin, vertex + end, ends[m]);
      if (found == vertex + end)
        throw std::logic_error("SegregatedStep: a node's vertex is not in its row of G");
      carried_local_[a][m] = static_cast<int>(found - (vertex + begin));
    }
  }
  m1_position_.clear();
  for (int k = 0; k < M1.outerSize(); ++k)
    for (SparseMatrix::InnerIterator entry(M1, k); entry; ++entry)
      m1_position_.push_back(position(static_cast<int>(entry.row()), k));
}

SegregatedStep::~SegregatedStep() = default;

void SegregatedStep::NodeMatrices::clear(int node_count) {
  if (static_cast<int>(at.size()) != node_count) at.assign(node_count, -1);
  for (int node : nodes) at[node] = -1;
  nodes.clear();
  matrix.clear();
}

void SegregatedStep::NodeMatrices::set(int node, const Mat2& m) {
  if (at[node] < 0) {
    at[node] = static_cast<int>(matrix.size());
    nodes.push_back(node);
    matrix.push_back(m);
  } else {
    matrix[at[node]] = m;
  }
}

// One pass over the elements: the viscous stiffness K_nu with this step's nu_e (M-3) (without
// an eddy viscosity nu_e is the constant nu and K_nu is assembled at the first step only), the
// explicit transposed-gradient viscous part, the forcing (7), the friction rate (5) lumped at
// the nodes, the continuity source (11).
void SegregatedStep::assemble_momentum(ShallowWaterSolver& s, double t_source, Loads& loads) {
  const FlowConfig& flow = s.case_.flow;
  const FlowState& n = s.previous_;
  const int N2 = mesh_.node_count();
  loads.force.assign(N2, Vec2::Zero());
  loads.gamma_m.assign(N2, 0.0);
  loads.source.setZero(mesh_.vertex_count);
  const bool constant_k = flow.turbulence == TurbulenceModel::none;
  const bool assemble_k = !(constant_k && k_viscosity_ == flow.viscosity);
  element_viscosity_.resize(mesh_.element_count());
  AssemblyParameters p;
  p.friction = FrictionModel::from(flow);
  const Vec2 wind_stress = air_density / flow.water_density * wind_drag_coefficient *
                           flow.wind.norm() * flow.wind;  // (M-2) wind, times H [m^2 s^-2]
  const SourceFunction* source = s.options_.source ? &s.options_.source : nullptr;
  // Per node: H^n, |u^n| and, with one friction coefficient, the rate (5) itself, so that the
  // elements at a node do not each compute it again.
  const bool by_element = !s.friction_coefficient_.empty();
  loads.depth.resize(N2);
  std::vector<double>& speed = loads.speed;          // [m/s]
  std::vector<double>& node_rate = loads.node_rate;  // [1/s]
  speed.resize(N2);
  node_rate.resize(by_element ? 0 : N2);
  for (int a = 0; a < N2; ++a) {
    loads.depth[a] = s.node_depth_of(n, a);
    speed[a] = std::hypot(n.u[a], n.v[a]);
    if (!by_element) node_rate[a] = p.friction.rate(speed[a], loads.depth[a]);
  }
  s.for_each_element([&](int e) {
    FrictionModel friction = p.friction;
    if (!s.friction_coefficient_.empty()) friction.coefficient = s.friction_coefficient_[e];
    ElementValues ev;
    compute_element_values(mesh_, e, ev, false);
    const auto& el = mesh_.elements[e];
    std::array<double, 6> u_e, v_e, z_e, diagonal{};
    std::array<double, 3> eta_e;
    for (int b = 0; b < 6; ++b) {
      u_e[b] = n.u[el[b]];
      v_e[b] = n.v[el[b]];
      z_e[b] = s.z_b_[el[b]];
      for (int q = 0; q < triangle_point_count; ++q)
        diagonal[b] += ev.N2[q][b] * ev.N2[q][b] * ev.JxW[q];
    }
    for (int j = 0; j < 3; ++j) eta_e[j] = n.eta[el[j]];
    double A = 0.0;  // [m^2]
    for (int q = 0; q < triangle_point_count; ++q) A += ev.JxW[q];
    const double nu_t =
        constant_k ? 0.0
                   : eddy_viscosity(flow.turbulence, flow.smagorinsky_constant, friction,
                                    element_flow_average(ev, u_e, v_e, z_e, eta_e));  // (M-3)
    const double nu_e = flow.viscosity + nu_t;  // (M-3) [m^2/s]
    double diagonal_sum = 0.0;
    for (double d : diagonal) diagonal_sum += d;
    for (int a = 0; a < 6; ++a) {  // (5) friction, lumped: m_a^e gamma(|u^n_a|, H^n_a)
      const double gamma =
          by_element ? friction.rate(speed[el[a]], loads.depth[el[a]]) : node_rate[el[a]];
      loads.gamma_m[el[a]] += A * diagonal[a] / diagonal_sum * gamma;
    }
    if (!s.element_drag_rates_.empty())  // the bodies' drag, implicit and lumped as (5)
      for (int a = 0; a < 6; ++a)
        loads.gamma_m[el[a]] += A * diagonal[a] / diagonal_sum * s.element_drag_rates_[e];
    Vec2 total_force = Vec2::Zero();  // integral of (7) over the element [m^3 s^-2]
    for (int q = 0; q < triangle_point_count; ++q) {
      const auto& N = ev.N2[q];
      Mat2 G_n = Mat2::Zero();  // d u_i / d x_j at t^n
      Vec2 force = s.element_forces_.empty() ? Vec2::Zero() : s.element_forces_[e];
      double z_b = 0.0, eta = 0.0;
      for (int b = 0; b < 6; ++b) {
        G_n += Vec2(n.u[el[b]], n.v[el[b]]) * ev.dN2[q][b].transpose();
        z_b += N[b] * s.z_b_[el[b]];
        if (!s.node_forces_.empty()) force += N[b] * s.node_forces_[el[b]];
      }
      for (int j = 0; j < 3; ++j) eta += ev.N1[q][j] * n.eta[el[j]];
      force += wind_stress / std::max(eta - z_b, p.friction.min_depth);  // (7) wind
      double S = 0.0;
      if (source) {
        const SourceTerms src = (*source)(ev.x[q], t_source);
        force += src.momentum;  // (7)
        S = src.continuity;
      }
      const double JxW = ev.JxW[q];
      total_force += force * JxW;
      for (int a = 0; a < 6; ++a) {
        const Vec2& dN_a = ev.dN2[q][a];
        // (4), transposed half (nu_e grad u^T, grad w) at t^n
        loads.force[el[a]] -= nu_e * G_n.transpose() * dN_a * JxW;
      }
      for (int i = 0; i < 3; ++i) loads.source[el[i]] += ev.N1[q][i] * S * JxW;  // (11)
    }
    element_viscosity_[e] = nu_e;
    // (7) in M_L's nodal quadrature, as the slope (3) is (G): each node takes its share of the
    // element's force, so that a forced state at rest (wind set-up) balances node by node.
    for (int a = 0; a < 6; ++a) loads.force[el[a]] += diagonal[a] / diagonal_sum * total_force;
  });
  if (assemble_k) {  // (4), (nu_e grad u, grad w), by the elements in k_elements_'s order
    double* K = K_.valuePtr();
    std::fill(K, K + K_.nonZeros(), 0.0);
    const double* geometry = k_geometry_.data();
    const int* position = k_position_.data();
    for (int e : k_elements_) {
      const double nu_e = element_viscosity_[e];
      for (int a = 0; a < 6; ++a)
        for (int b = a; b < 6; ++b, ++geometry) {
          const double k = nu_e * *geometry;
          K[position[6 * a + b]] += k;
          if (b != a) K[position[6 * b + a]] += k;
        }
      position += 36;
    }
  }
  k_viscosity_ = constant_k ? flow.viscosity : std::numeric_limits<double>::quiet_NaN();
}

// (M-21) for u and v: (diag(A) + K_nu) u~ = m u_d/dt - (1 - s) g G eta^n + F, A_a = m_a/dt +
// gamma_a m_a, velocity nodes fixed at their boundary values (set in u, v on entry), by
// conjugate gradients from u_d, preconditioned with the zero fill-in incomplete Cholesky factor
// of the matrix of an earlier step (friction and the eddy viscosity change it little from step
// to step; made again once it ages: predictor_factor_), on the nodes in K_'s order
// (node_order_), both components in one sweep.
void SegregatedStep::predict_velocity(const ShallowWaterSolver& s, const Prediction& in,
                                      std::vector<double>& u, std::vector<double>& v) {
  const int N2 = mesh_.node_count();
  Predictor& w = predictor_;
  w.fixed.assign(N2, 0);
  for (const auto& node : s.bc_.velocity_nodes) w.fixed[node_order_[node.node]] = 1;
  w.A.resize(N2);  // [m^2/s] in K_'s order
  for (int a = 0; a < N2; ++a) w.A[node_order_[a]] = (*in.A)[a];
  const bool fresh = predictor_stale_ || w.fixed != factor_fixed_;
  if (fresh) {
    predictor_factor_.factorise(K_, 1.0, w.A, w.fixed);
    factor_fixed_ = w.fixed;
    predictor_stale_ = false;
    ++predictor_factorisations_;
  }
  w.x.resize(2 * static_cast<size_t>(N2));  // u~, interleaved (entry 2 k + c)
  w.b.resize(2 * static_cast<size_t>(N2));
  const double s_node = (1.0 - in.slope_at_feet) * in.g;
  // The first iterate: the boundary values at fixed nodes, elsewhere u_d, the flow arriving
  // along the paths, plus the last step's (u~ - u_d) inv_dt over inv_dt: the slope, the viscous
  // and the friction terms change little from one step to the next (a fifth fewer iterations
  // over the paper's channel's hour than from u_d alone; none at the first step and after
  // refactorise(), so that a restart continues bit for bit).
  const bool last = w.rate.size() == w.x.size();
  parallel_for(N2, RowParts::parallel_rows, [&](int a) {
    const int k = node_order_[a];
    const Vec2& force = in.loads->force[a];
    for (int c = 0; c < 2; ++c) {
      const double u_d = (c == 0 ? s.u_departure_ : s.v_departure_)[a];  // [m/s]
      w.b[2 * k + c] = m_[a] * u_d * in.inv_dt                           // (1)
                       - s_node * (*in.G_eta)[2 * a + c]                 // (3) node, t^n
                       + force[c];                                       // (4) T_nu, (7)
      w.x[2 * k + c] =
          w.fixed[k] ? (c == 0 ? u : v)[a] : u_d + (last ? w.rate[2 * k + c] / in.inv_dt : 0.0);
    }
  });
  const auto apply = [&](const std::vector<double>& p, std::vector<double>& y) {
    return pair_product(K_, 1.0, w.A.data(), &w.fixed, p, y);  // (4) (1) (5)
  };
  const auto precondition = [&](const std::vector<double>& r, std::vector<double>& z) {
    return predictor_factor_.solve_pair(r, z);
  };
  const std::array<int, 2> iterations = pair_conjugate_gradients(
      apply, precondition, w.fixed, w.b, w.x, predictor_tolerance, max_cg_iterations, w.work);
  for (int c = 0; c < 2; ++c) {
    if (iterations[c] > max_cg_iterations)
      throw_run_error("flow: the momentum predictor (M-21) did not converge in {} iterations",
                      max_cg_iterations);
    momentum_iterations_ += iterations[c];
  }
  const int most = std::max(iterations[0], iterations[1]);
  if (fresh)
    predictor_fresh_iterations_ = most;
  else if (most > predictor_fresh_iterations_ + max_extra_iterations)
    predictor_stale_ = true;  // aged too far: the next step makes a fresh factor
  w.rate_new.resize(w.x.size());
  parallel_for(N2, RowParts::parallel_rows, [&](int a) {
    const int k = node_order_[a];
    u[a] = w.x[2 * k];
    v[a] = w.x[2 * k + 1];
    w.rate_new[2 * k] = (u[a] - s.u_departure_[a]) * in.inv_dt;
    w.rate_new[2 * k + 1] = (v[a] - s.v_departure_[a]) * in.inv_dt;
  });
}

Eigen::VectorXd SegregatedStep::solve_elevation(const SparseMatrix& S, const Vector& b,
                                                const Operator& apply, const Vector& guess) {
  const auto factorise = [&] {
    const SerialBlas serial;
    if (!factor_) {
      factor_ = std::make_unique<Eigen::CholmodSupernodalLLT<SparseMatrix>>();
      // The fill-reducing ordering: AMD's and METIS's nested dissection both tried, the one with
      // the smaller factor kept. CHOLMOD's default tries METIS only for a factor denser than the
      // 495k channel's, where AMD's factor has 3.8e7 entries and METIS's 3.0e7 (and 42 % fewer
      // flops): the solves inside GMRES read the whole factor.
      cholmod_common& c = factor_->cholmod();
      c.nmethods = 2;
      c.method[0].ordering = CHOLMOD_AMD;
      c.method[1].ordering = CHOLMOD_METIS;
    }
    if (analysed_nonzeros_ != S.nonZeros()) {
      factor_->analyzePattern(S);
      analysed_nonzeros_ = S.nonZeros();
    }
    factor_->factorize(S);
    if (factor_->info() != Eigen::Success)
      throw_run_error("flow: the elevation system (M-22) is not positive definite (mesh {})",
                      mesh_.source);
    factor_age_ = 0;
    ++factorisations_;
  };
  const bool fresh = factor_age_ < 0;
  if (fresh) factorise();
  const auto precondition = [&](const Vector& r, Vector& z) {
    const SerialBlas serial;
    z = factor_->solve(r);
  };
  // Refactorised when the aged factor needs more iterations than a fresh one did, plus a margin
  // (the part C that the factor leaves out sets how many a fresh one needs).
  const int allowed = fresh ? max_fresh_iterations : fresh_iterations_ + max_extra_iterations;
  Vector x = guess;
  int iterations = gmres(apply, precondition, b, x, gmres_tolerance, allowed, work_.V, work_.Z);
  if (iterations > allowed && !fresh) {  // the factor aged too far: a fresh one
    elevation_iterations_ += allowed;
    factorise();
    x = guess;
    iterations =
        gmres(apply, precondition, b, x, gmres_tolerance, max_fresh_iterations, work_.V, work_.Z);
    fresh_iterations_ = iterations;
  } else if (fresh) {
    fresh_iterations_ = iterations;
  } else {
    ++factor_age_;
  }
  if (iterations > max_fresh_iterations)
    throw_run_error("flow: the elevation system (M-22) did not converge in {} GMRES iterations",
                    max_fresh_iterations);
  elevation_iterations_ += iterations;
  return x;
}

StepReport SegregatedStep::step(ShallowWaterSolver& s, double dt) {
  if (s.history_) std::swap(s.before_, s.previous_);  // t^{n-1}
  s.previous_ = s.state_;
  // The time term (u - u_d) inv_dt (ShallowWaterSolver::time_step): the theta-scheme's inv_dt =
  // 1/dt, u_d from u^n; BDF2's theta = 1, u_d = now u^n + before u^{n-1} at their feet, and
  // eta^n's part in the continuity equation likewise.
  const ShallowWaterSolver::Iteration it = s.time_step(dt);
  const bool bdf2 = s.case_.time.scheme == TimeScheme::bdf2;
  const double th = it.theta, g = s.case_.flow.gravity;
  const double feet = slope_at_feet(s.case_.time.scheme, th);
  const FlowState& n = s.previous_;
  FlowState& next = s.state_;
  const int N2 = mesh_.node_count(), N1 = mesh_.vertex_count;
  Work& w = work_;
  try {
    s.set_boundary_velocities(it);  // velocity and discharge nodes at t^{n+1}, in state_
    Loads& loads = loads_;
    assemble_momentum(s, it.t_source, loads);

    // 1. Advection (M-20): part of the slope at t^n and the explicit Coriolis carried to the feet.
    // G annihilates constants; taken on eta^n - eta^n_0 it does so exactly, so a lake at rest
    // stays at rest to the last bit rather than gaining round-off at every step.
    const Eigen::Map<const Vector> eta_n(n.eta.data(), N1);
    w.G_eta.noalias() = G_ * (eta_n.array() - eta_n[0]).matrix();  // [m^2]
    const Vector& G_eta = w.G_eta;
    const FlowConfig& flow = s.case_.flow;
    const double f = flow.coriolis
                         ? 2.0 * earth_rotation_rate * std::sin(flow.latitude_deg * pi / 180.0)
                         : 0.0;  // [1/s]
    if (bdf2) {
      // u^n and u^{n-1} at their feet; Coriolis (6) at the node, on u extrapolated to t^{n+1}
      // (second order, and explicit: implicit it would make (M-22) unsymmetric). Without a
      // history (the first step) there is no u^{n-1}: u^n itself.
      s.departure_values(it, dt);
      const bool history = it.before != 0.0;
      const double w_n = history ? dt / it.dt_before : 0.0;  // [-]
      for (int a = 0; a < N2 && f != 0.0; ++a) {
        const Vec2 u_a(n.u[a], n.v[a]);
        const Vec2 u_new =
            history ? Vec2(u_a + w_n * (u_a - Vec2(s.before_.u[a], s.before_.v[a]))) : u_a;
        const Vec2 coriolis = -f * Vec2(-u_new.y(), u_new.x()) / it.inv_dt;  // (6) [m/s]
        s.u_departure_[a] += coriolis.x();
        s.v_departure_[a] += coriolis.y();
      }
    } else {
      w.q_x.resize(N2);
      w.q_y.resize(N2);
      parallel_for(N2, RowParts::parallel_rows, [&](int a) {
        const Vec2 u_a(n.u[a], n.v[a]);
        const Vec2 acceleration = -feet * g * Vec2(G_eta[2 * a], G_eta[2 * a + 1]) / m_[a] -
                                  f * Vec2(-u_a.y(), u_a.x());  // (3) (6), the parts at the feet
        w.q_x[a] = u_a.x() + dt * acceleration.x();
        w.q_y[a] = u_a.y() + dt * acceleration.y();
      });
      s.characteristics_->advect(n.u, n.v, dt, w.q_x, w.q_y, s.u_departure_, s.v_departure_);
    }

    // 2. Momentum predictor (M-21), viscosity and friction implicit.
    w.A.resize(N2);  // [m^2/s] m_a/dt + gamma_a m_a
    for (int a = 0; a < N2; ++a) w.A[a] = m_[a] * it.inv_dt + loads.gamma_m[a];
    const Vector& A = w.A;
    predict_velocity(s, {feet, g, it.inv_dt, &G_eta, &A, &loads}, next.u, next.v);

    // The constraint P_a of each node: free (the identity, the nodes not listed), fixed
    // (velocity nodes: zero), or u . normal = 0 (walls, and the tangent of elevation boundaries
    // where water enters, from u^n). The tangent held at an elevation boundary (where water
    // enters, which changes from step to step where eddies leave) is applied after the
    // correction only, so that the matrix of (M-22) changes with H and gamma alone and its
    // factor stays a good preconditioner.
    w.P.clear(N2);
    w.P_after.clear(N2);
    for (const auto& node : s.bc_.velocity_nodes) w.P.set(node.node, Mat2::Zero());
    for (const SlipNode& slip : s.bc_.slip_nodes) {
      const Mat2 tangent = Mat2::Identity() - slip.normal * slip.normal.transpose();
      if (slip.outward.isZero())
        w.P.set(slip.node, tangent);  // wall
      else if (slip.outward.dot(Vec2(n.u[slip.node], n.v[slip.node])) <= 0.0)
        w.P_after.set(slip.node, tangent);
    }
    const std::vector<double>& H = loads.depth;  // [m] H^n
    w.flux.resize(2 * N2);  // [m^2/s] H (theta P u~ + (1 - theta) u^n), by node
    parallel_for(N2, RowParts::parallel_rows, [&](int a) {
      const Mat2* P_a = w.P.of(a);
      const Vec2 u_tilde = !P_a || P_a->isZero() ? Vec2(next.u[a], next.v[a])
                                                 : Vec2(*P_a * Vec2(next.u[a], next.v[a]));
      next.u[a] = u_tilde.x();
      next.v[a] = u_tilde.y();
      const Vec2 q = H[a] * (th * u_tilde + (1.0 - th) * Vec2(n.u[a], n.v[a]));  // (9)
      w.flux[2 * a] = q.x();
      w.flux[2 * a + 1] = q.y();
    });

    // 3. Elevation (M-22): the Schur complement M_1/dt + theta^2 g G^T D G, SPD, assembled in
    // place: node a adds (G_a,i)^T D_a (G_a,j) for each pair of vertices i, j in its rows of G.
    double* S_values = S_.valuePtr();
    std::fill(S_values, S_values + S_.nonZeros(), 0.0);
    for (size_t k = 0; k < m1_position_.size(); ++k)
      S_values[m1_position_[k]] = M1_.valuePtr()[k] * it.inv_dt;  // (8)
    // The depth's change carried by u^n, theta (d_eta u^n) in (9) as in the coupled step (with
    // it explicit the step is unstable at a Froude number of 0.5 and Courant 4.4: the bump):
    // C x = G^T (theta u^n_a x_a), x_a at P2 node a interpolated from the vertices, assembled
    // on S's pattern. It makes the system S - C unsymmetric; the SPD S factorised preconditions
    // it.
    w.carried_values.assign(S_.nonZeros(), 0.0);
    double* C_values = w.carried_values.data();
    const int* position = schur_position_.data();
    const double* slope = G_.valuePtr();  // rows 2a, 2a + 1: G_(2a+c),i at begin + k, end + k
    for (int a = 0; a < N2; ++a) {
      const double D = th * th * g * H[a] / A[a];  // [1/s] D_a = D P_a
      const Mat2* P_a = w.P.of(a);
      const int begin = G_.outerIndexPtr()[2 * a], end = G_.outerIndexPtr()[2 * a + 1];
      const std::array<int, 2>& ends = carried_local_[a];
      const double weight = ends[1] < 0 ? th : 0.5 * th;  // [-] theta times x_a's weights
      const Vec2 u_n(n.u[a], n.v[a]);
      for (int p = 0; p < end - begin; ++p, position += end - begin) {
        const Vec2 slope_p(slope[begin + p], slope[end + p]);
        const Vec2 w_p = P_a ? Vec2(D * *P_a * slope_p) : Vec2(D * slope_p);
        for (int q = 0; q < end - begin; ++q)
          S_values[position[q]] += w_p.dot(Vec2(slope[begin + q], slope[end + q]));
        const double c = weight * slope_p.dot(u_n);  // [m^2/s]
        for (int m = 0; m < 2 && ends[m] >= 0; ++m) C_values[position[ends[m]]] += c;
      }
    }
    w.b.noalias() = G_.transpose() * w.flux;  // (9)
    w.b += loads.source;                      // (11)
    if (it.before != 0.0) {  // (8) BDF2: eta_d - eta^n = before (eta^{n-1} - eta^n)
      const Eigen::Map<const Vector> eta_before(s.before_.eta.data(), N1);
      w.b.noalias() += (it.before * it.inv_dt) * (M1_ * (eta_before - eta_n));
    }
    Vector& b = w.b;
    std::vector<double> open_flux(mesh_.group_names.size(), 0.0);
    EdgeValues ev;
    for (const auto& open : s.bc_.open_edges) {  // (10), the outflow, known
      const auto& edge = mesh_.boundary[open.boundary_edge];
      compute_edge_values(mesh_, edge, ev);
      EdgeState es;
      for (int m = 0; m < 3; ++m) {
        const int node = ev.nodes[m];
        es.z_b[m] = s.z_b_[node];
        es.u_new[m] = Vec2(next.u[node], next.v[node]);
        es.u_n[m] = Vec2(n.u[node], n.v[node]);
        if (m < 2) es.eta_k[m] = es.eta_n[m] = n.eta[node];
      }
      const auto outflow = open_boundary_flux(s.boundary_flux_weight(open.condition, it), ev, es);
      for (int m = 0; m < 2; ++m) {
        open_flux[edge.group] += outflow[m];
        b[ev.nodes[m]] -= outflow[m];  // (10)
      }
    }
    // Elevation boundaries: d_eta known there, eliminated symmetrically in S_ itself, after
    // their rows are kept for the water balance.
    w.dirichlet.assign(N1, 0);
    Vector& d_eta = w.d_eta;
    d_eta.setZero(N1);
    for (int k = 0; k < static_cast<int>(s.bc_.elevation_nodes.size()); ++k) {
      const int i = s.bc_.elevation_nodes[k].vertex;
      w.dirichlet[i] = 1;
      d_eta[i] = s.elevation_boundary_level(k, it) - n.eta[i];
    }
    eliminate_elevation_boundaries(w);
    const Eigen::Map<const SparseMatrix> system(N1, N1, S_.nonZeros(), S_.outerIndexPtr(),
                                                S_.innerIndexPtr(), w.system_values.data());
    // The first iterate: the surface's last rate of change times dt (it changes smoothly from
    // step to step; zero at the first step and after refactorise(), so that a restart continues
    // bit for bit), with the elevation boundaries' known values.
    if (eta_rate_.size() == N1)
      w.guess.noalias() = eta_rate_ * dt;
    else
      w.guess.setZero(N1);
    for (const auto& node : s.bc_.elevation_nodes) w.guess[node.vertex] = d_eta[node.vertex];
    d_eta = solve_elevation(
        S_, w.b_free, [&](const Vector& x, Vector& y) { y.noalias() = system * x; }, w.guess);

    // 4. Correction (M-23).
    w.G_d_eta.noalias() = G_ * d_eta;
    parallel_for(N2, RowParts::parallel_rows, [&](int a) {
      const Vec2 G_d_eta_a(w.G_d_eta[2 * a], w.G_d_eta[2 * a + 1]);
      const Mat2* P_a = w.P.of(a);
      const Vec2 correction = th * g / A[a] * (P_a ? Vec2(*P_a * G_d_eta_a) : G_d_eta_a);  // [m/s]
      const Vec2 u_new(next.u[a] - correction.x(), next.v[a] - correction.y());
      const Mat2* P_after = w.P_after.of(a);
      next.u[a] = P_after ? (*P_after * u_new).x() : u_new.x();
      next.v[a] = P_after ? (*P_after * u_new).y() : u_new.y();
    });
    for (int j = 0; j < N1; ++j) next.eta[j] = n.eta[j] + d_eta[j];
    next.time = it.t_new;
    s.check_state(next, it.t_new);
    eta_rate_.noalias() = d_eta / dt;  // a step that failed leaves the last ones
    predictor_.rate.swap(predictor_.rate_new);

    // Water balance (water_balance.hpp): open boundaries (10), and the elevation boundaries'
    // rows of (M-22) as assembled, (S - C) d_eta - b, the outflow through each such vertex.
    WaterBalance& balance = s.balance_;
    balance.group_rate = open_flux;
    for (size_t k = 0; k < s.bc_.elevation_nodes.size(); ++k) {
      const int i = s.bc_.elevation_nodes[k].vertex;
      double flow_in = 0.0;  // [m^3/s] row i of S - C (kept before the elimination) times d_eta
      for (int p = w.row_start[i]; p < w.row_start[i + 1]; ++p)
        flow_in += w.row_value[p] * d_eta[w.row_column[p]];
      balance.group_rate[s.elevation_group_[k]] -= flow_in - b[i];
    }
  } catch (const RunError&) {
    s.state_ = s.previous_;
    if (s.history_) s.previous_ = s.before_;
    throw;
  }
  s.accumulate_balance(it, dt);
  s.history_ = true;
  StepReport report;
  report.iterations = 1;
  return report;
}

// The system S - C with the rows and columns of the elevation boundaries' vertices
// (w.dirichlet) replaced by the identity's in S_ and w.system_values, their known d_eta moved to
// the right-hand side (w.b_free from w.b); C keeps its columns there (C x takes their d_eta as
// x). The rows of S - C there are kept first (w.row_*: the water balance's).
void SegregatedStep::eliminate_elevation_boundaries(Work& w) {
  const int N1 = mesh_.vertex_count;
  const int* outer = S_.outerIndexPtr();
  const int* index = S_.innerIndexPtr();
  double* S = S_.valuePtr();
  const double* C = w.carried_values.data();
  const auto at = [&](int i, int j) {  // S_'s position of (i, j), in the pattern
    return static_cast<int>(std::lower_bound(index + outer[j], index + outer[j + 1], i) - index);
  };
  w.b_free = w.b;
  w.row_start.assign(N1 + 1, 0);
  w.row_column.clear();
  w.row_value.clear();
  for (int i = 0; i < N1; ++i) {  // the rows, by the symmetric pattern's column i
    if (w.dirichlet[i])
      for (int p = outer[i]; p < outer[i + 1]; ++p) {
        const int k = at(i, index[p]);
        w.row_column.push_back(index[p]);
        w.row_value.push_back(S[k] - C[k]);
      }
    w.row_start[i + 1] = static_cast<int>(w.row_column.size());
  }
  w.system_values.resize(S_.nonZeros());
  for (int j = 0; j < N1; ++j) {
    if (w.dirichlet[j])
      for (int p = outer[j]; p < outer[j + 1]; ++p) {  // column j: S's to the right-hand side
        const int i = index[p];
        if (!w.dirichlet[i]) w.b_free[i] -= S[p] * w.d_eta[j];
        S[p] = i == j ? 1.0 : 0.0;
      }
    for (int p = outer[j]; p < outer[j + 1]; ++p)
      w.system_values[p] = w.dirichlet[index[p]] ? S[p] : S[p] - C[p];
  }
  for (int j = 0; j < N1; ++j) {
    if (!w.dirichlet[j]) continue;
    for (int p = outer[j]; p < outer[j + 1]; ++p) {  // row j
      const int k = at(j, index[p]);
      S[k] = w.system_values[k] = index[p] == j ? 1.0 : 0.0;
    }
    w.b_free[j] = w.d_eta[j];
  }
}

}  // namespace flotsam
