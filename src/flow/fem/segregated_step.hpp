#pragma once
// The segregated (projection) time step of the FEM engine, `flow.scheme: segregated`
// (docs/model.md "The segregated step", (M-20)-(M-23)). Same unknowns and weak form as the
// coupled step (element_assembly.hpp), theta-scheme or BDF2, advection by characteristics; the
// coupled (u, eta) system is replaced by a sequence of small ones:
//
//   1. advection   u_d = (u^n + dt a^n)(X), a^n = M_L^-1 (-s g G eta^n) - f k x u^n       (M-20)
//   2. momentum    (M_L (1/dt + gamma^n) + K_nu) u~ = M_L u_d/dt - (1-s) g G eta^n
//                    - T_nu(u^n) + F                                          (M-21) per component
//   3. elevation   (M_1/dt + theta^2 g G^T D G - C) d_eta
//                    = S - B + G^T H (theta u~ + (1-theta) u^n)
//                    D_a = H_a P_a / A_a,  A_a = m_a (1/dt + gamma_a),  C x = G^T (theta u^n_a x_a)
//                    (M-22): SPD but for C, the depth's change carried by the current
//   4. correction  u^{n+1}_a = P_a (u~_a - theta g (G d_eta)_a / A_a)         (M-23)
//
// With BDF2 (time.scheme: bdf2) the stages are the same with theta = 1, s = 0, 1/dt replaced by
// BDF2's inv_dt, u_d by BDF2's u^n and u^{n-1} at their feet, eta^{n-1}'s part of the time term on
// the right of (M-22), and Coriolis at the node on u extrapolated to t^{n+1}.
//
// The slope at t^n is taken in part s = 3/4 - theta/2 at the feet, 1 - s at the node (s = 1/2
// would centre it along the path; s = 1 - theta, the coupled step's split, leaves a steady error
// O((theta - 1/2) dt); stability needs s < 1/2 for theta > 1/2: docs/model.md), its increment
// theta g G d_eta at the node. M_L is the lumped P2 mass (diagonal scaling,
// Hinton-Rock-Zienkiewicz: the consistent diagonal scaled to the element's area; row sums would
// give the P2 vertices zero mass), G the surface slope (3) and, transposed, the continuity flux
// (9), both integrated with M_L's own nodal quadrature: G_ai = sum over the elements e at node a of
// m_a^e / |e| integral_e grad M_i, so that M_L^-1 G eta is at every node the mean of its elements'
// slopes (the exact (N_a, grad M_i) is zero at P2 vertices: their shape functions integrate to
// zero), K_nu the scalar viscous stiffness (nu_e grad u, grad w) of (4), wholly at t^{n+1}
// whatever theta (its transposed-gradient half T_nu explicit: bounded by K_nu, so that the pair
// is stable at any step, which theta K_nu implicit is not once nu_e dt / h^2 grows), P_a the
// velocity constraint at node a (identity; the tangent projector at slip nodes; zero at velocity
// nodes), M_1 the P1 mass, x_a a P1 field at P2 node a. The forcing (7) is integrated in M_L's
// quadrature too. The momentum predictor is solved by conjugate gradients preconditioned with the
// zero fill-in incomplete Cholesky factor of its matrix at an earlier step (made again when the
// iterations grow), on the P2 nodes renumbered by locality (reverse Cuthill-McKee), u and v in one
// sweep (pair_conjugate_gradients.hpp), the rows in two parts swept on the threads (row_parts.hpp:
// the factor block diagonal between them). C is assembled with S on S's pattern. The elevation
// system is solved by GMRES preconditioned with a CHOLMOD Cholesky factor of an earlier step's SPD
// part, refactorised when GMRES needs more than max_extra_iterations beyond what it needed after
// the last factorisation.
#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>
#include <array>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "core/vec.hpp"
#include "flow/fem/incomplete_cholesky.hpp"
#include "flow/fem/pair_conjugate_gradients.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

class ShallowWaterSolver;
struct StepReport;

class SegregatedStep {
 public:
  /// The constant operators of the mesh: M_L, M_1, G, the pattern of K_nu.
  explicit SegregatedStep(const ShallowWaterSolver& solver);
  ~SegregatedStep();

  /// Advances `solver` by dt [s] (its state, previous state, water balance). Throws RunError
  /// (state left at the start of the step) as ShallowWaterSolver::step does.
  StepReport step(ShallowWaterSolver& solver, double dt);
  /// The next step factorises afresh (a restart must continue bit for bit).
  void refactorise() {
    factor_age_ = -1;
    predictor_stale_ = true;
    predictor_.rate.clear();
    eta_rate_.resize(0);
  }

  /// Conjugate-gradient iterations of the elevation solves so far, and factorisations.
  long elevation_iterations() const { return elevation_iterations_; }
  long factorisations() const { return factorisations_; }
  /// Conjugate-gradient iterations of the momentum predictor (M-21) so far, both components.
  long momentum_iterations() const { return momentum_iterations_; }
  /// Incomplete Cholesky factorisations of the momentum predictor's matrix so far.
  long predictor_factorisations() const { return predictor_factorisations_; }

 private:
  using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
  using Vector = Eigen::VectorXd;
  // Per-node momentum loads of one step [m^3 s^-2], the lumped friction [m^2/s], and the P1
  // continuity source [m^3/s].
  struct Loads {
    std::vector<Vec2> force;      // (7) forcing, minus the explicit transposed viscous part of (4)
    std::vector<double> gamma_m;  // sum over elements of m_a^e gamma_a: friction (5), lumped
    Vector source;                // (11) (q_i, S)
    std::vector<double> depth;    // H^n per node [m]
    std::vector<double> speed, node_rate;  // |u^n| [m/s], the friction rate (5) [1/s] per node
  };
  // 2x2 matrices per node that are the identity at all but a few nodes (the constraints P_a).
  struct NodeMatrices {
    std::vector<int> at;  // per node: its entry of `matrix`, or -1 (the identity)
    std::vector<int> nodes;
    std::vector<Mat2> matrix;
    void clear(int node_count);
    void set(int node, const Mat2& m);
    const Mat2* of(int node) const { return at[node] < 0 ? nullptr : &matrix[at[node]]; }
  };
  // The step's vectors, kept from one step to the next (no allocation per step).
  struct Work {
    Vector G_eta, A, flux, b, b_free, d_eta, G_d_eta, guess;
    std::vector<double> carried_values;  // C in S_'s pattern [m^2/s]
    std::vector<double> system_values;   // S - C in S_'s pattern, eliminated [m^2/s]
    std::vector<double> q_x, q_y;
    NodeMatrices P, P_after;      // P_a, and the tangent applied after the correction (M-23)
    std::vector<char> dirichlet;  // per vertex: on an elevation boundary
    // S_'s rows of the elevation boundaries' vertices before their elimination, by vertex
    std::vector<int> row_start, row_column;
    std::vector<double> row_value;
    Eigen::MatrixXd V, Z;  // GMRES's Krylov basis and its preconditioned vectors
  };
  struct Prediction {                 // what the momentum predictor (M-21) takes
    double slope_at_feet, g, inv_dt;  // [-], [m s^-2], [1/s]
    const Eigen::VectorXd* G_eta;     // G eta^n [m^2], rows 2a + c
    const Eigen::VectorXd* A;         // m_a/dt + gamma_a m_a [m^2/s]
    const Loads* loads;
  };
  void assemble_momentum(ShallowWaterSolver& s, double t_source, Loads& loads);
  void predict_velocity(const ShallowWaterSolver& s, const Prediction& in, std::vector<double>& u,
                        std::vector<double>& v);
  using Operator = std::function<void(const Eigen::VectorXd&, Eigen::VectorXd&)>;
  /// (M-22): x with apply(x) = b, preconditioned by the Cholesky factor of the SPD part S.
  void plan_schur_matrix(const SparseMatrix& M1);
  Eigen::VectorXd solve_elevation(const SparseMatrix& S, const Eigen::VectorXd& b,
                                  const Operator& apply, const Eigen::VectorXd& guess);
  void eliminate_elevation_boundaries(Work& w);

  const Mesh& mesh_;
  std::vector<double> m_;  // [m^2] lumped P2 mass per node
  using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;
  RowMatrix G_;  // (2 N2) x N1, rows 2a + c: sum_e m_a^e (d M_i / d x_c)_e [m]
  std::vector<std::array<int, 2>> mid_ends_;  // the two vertices of each mid node (index - N1)
  SparseMatrix M1_;                           // P1 mass (8) [m^2]
  SparseMatrix S_;  // (M-22)'s SPD part, M_1/dt + theta^2 g G^T D G [m^2/s], fixed pattern
  std::vector<int> schur_position_;  // per node, per pair (i, j) of its vertices: S_'s value
  std::vector<int> m1_position_;     // M1_'s values' places in S_'s values
  // Per node a: where the vertices that a P1 field at a interpolates from (a itself, or a mid
  // node's two ends; -1: none) are among its row's of G (C's columns).
  std::vector<std::array<int, 2>> carried_local_;
  // The momentum predictor (M-21) works on the P2 nodes renumbered by locality: node a is
  // unknown node_order_[a] of K_, of the factor and of the predictor's vectors.
  std::vector<int> node_order_;
  SparseMatrix K_;  // scalar P2 viscous stiffness, nu_e (grad N_a, grad N_b) [m^2/s], reordered
  // Of (M-21)'s matrix at an earlier step (friction and the eddy viscosity change it little from
  // one step to the next), made again when a solve needs more than max_extra_iterations
  // beyond the solve that followed it, or when the fixed nodes change.
  IncompleteCholesky predictor_factor_;
  std::vector<char> factor_fixed_;  // the fixed nodes the factor was made with
  bool predictor_stale_ = true;     // none yet, or aged too far: make one at the next step
  int predictor_fresh_iterations_ = 0;
  struct Predictor {           // (M-21)'s vectors, in K_'s order, kept across steps
    std::vector<char> fixed;   // velocity nodes
    Eigen::VectorXd A;         // m_a/dt + gamma_a m_a [m^2/s]
    std::vector<double> x, b;  // u (then u~) [m/s], right-hand side; entry 2 k + c
    // (u~ - u_d) inv_dt of the last step, and of this one until it is accepted [m s^-2]
    std::vector<double> rate, rate_new;
    PairWorkspace work;
  } predictor_;
  std::vector<int> k_elements_;     // the elements in the order K_ is assembled by
  std::vector<int> k_position_;     // per element in that order, 36 positions in K_'s values
  std::vector<double> k_geometry_;  // per element in that order, (grad N_a, grad N_b), b >= a
  std::vector<double> element_viscosity_;  // nu_e of this step, per element [m^2/s]
  double k_viscosity_ = std::numeric_limits<double>::quiet_NaN();  // K_'s constant nu [m^2/s]
  std::unique_ptr<Eigen::CholmodSupernodalLLT<SparseMatrix>> factor_;
  Eigen::Index analysed_nonzeros_ = -1;
  int factor_age_ = -1;       // steps since the factorisation; -1: none
  Eigen::VectorXd eta_rate_;  // d_eta / dt of the last step [m/s]; empty: none
  int fresh_iterations_ = 0;  // GMRES iterations of the solve that followed the factorisation
  long elevation_iterations_ = 0, factorisations_ = 0, momentum_iterations_ = 0,
       predictor_factorisations_ = 0;
  Loads loads_;
  Work work_;
};

}  // namespace flotsam
