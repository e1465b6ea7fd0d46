#pragma once
// The FEM shallow-water engine (spec 1, paper section 2): P2 velocity / P1 elevation
// (Taylor-Hood) Galerkin finite elements, advection by characteristics (or Eulerian with SUPG),
// a theta-scheme or BDF2 in time (the case's time.scheme) linearised by Newton's method at each
// step, and one coupled sparse system in (u, v, eta) per iteration,
// solved by a sparse direct LU whose symbolic analysis is reused, and whose numeric factors are
// kept across steps for an iterative refinement (linear_solver.hpp). docs/model.md "Flow
// (spec 1)" gives the weak form (element_assembly.hpp), the choices and the departures.
//
// Outline (as a deal.II tutorial): setup_system -> [assemble_system -> apply_boundary_conditions
// -> solve] per iteration -> check_state; step() and solve_steady() call them in order.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "flow/bed.hpp"
#include "flow/fem/boundary_conditions.hpp"
#include "flow/fem/characteristics.hpp"
#include "flow/fem/element_assembly.hpp"
#include "flow/fem/element_blocks.hpp"
#include "flow/fem/linear_solver.hpp"
#include "flow/fem/linear_system.hpp"
#include "flow/fem/mass_matrix.hpp"
#include "flow/fem/segregated_step.hpp"
#include "flow/flow_state.hpp"
#include "flow/water_balance.hpp"
#include "io/case.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

/// How the advection term of (M-1a) is discretised.
enum class Advection {
  characteristics,  // fractional step: characteristics, then one implicit (u, eta) system
  supg,             // Eulerian, SUPG-stabilised, inside the Newton iterations
};

/// Numerical choices of the engine (not physics: those are in FlowConfig).
struct FlowSolverOptions {
  Advection advection = Advection::characteristics;
  // Newton iterations per step. With characteristics one is the semi-implicit scheme: the
  // (u, eta) system linearised about t^n (friction, depth in the flux); SUPG needs about three.
  int max_iterations = 1;
  double iteration_tolerance = 1e-6;  // [-] relative change of the state that ends them
  bool supg = true;                   // SUPG stabilisation of advection (Advection::supg)
  LinearSolverKind linear_solver = LinearSolverKind::umfpack;
  // Keep the LU across solves for an iterative refinement, refactorising when the refinement
  // stalls or takes many iterations (linear_solver.hpp).
  bool reuse_factorisation = true;
  // [s] largest pseudo time step of the steady solve's Newton iterations (a small time term
  // keeps the linearised steady problem regular: closed basins, u = 0); 0: 1e5 h_min / sqrt(g H).
  double steady_pseudo_dt = 0.0;
  // [elements] colours smaller than this are assembled serially: starting threads costs more
  // than it saves on a few hundred elements.
  int parallel_min_colour = 512;
  BedFunction bed;        // overrides the case's bed when set (tests)
  SourceFunction source;  // manufactured source terms when set (tests)
};

struct StepReport {
  int iterations = 0;        // Newton iterations taken
  double last_change = 0.0;  // [-] relative change at the last iteration
};

struct SteadyReport {
  bool converged = false;
  int iterations = 0;               // Newton iterations, all continuation stages together
  std::vector<double> residuals;    // [-] relative residual before each iteration and at the end
  std::vector<double> viscosities;  // [m^2/s] the viscosity each residual was computed with
  double viscosity = 0.0;           // [m^2/s] the lowest viscosity whose steady state was found
};

class ShallowWaterSolver {
 public:
  /// Keeps references to `mesh` and `flow_case`, which must outlive the solver. Checks the
  /// boundary conditions against the mesh (InputError).
  ShallowWaterSolver(const Mesh& mesh, const Case& flow_case, FlowSolverOptions options = {});

  /// Bed, initial state (still water, eta linear in x between FlowConfig's initial values),
  /// sparsity pattern. Throws InputError when a node starts with a depth below the dry depth.
  void initialize();
  /// Replaces the state (eta per vertex, u and v per P2 node), e.g. an initial condition, and
  /// the state one step before it that BDF2 needs (a restart; none: the flow was steady). The
  /// next linear solve factorises afresh.
  void set_state(const FlowState& state, const FlowState* before = nullptr);
  /// The next linear solve factorises afresh instead of reusing the last LU
  /// (FlowSolverOptions::reuse_factorisation). At a checkpoint: a run restarted from it starts
  /// with a fresh LU, so the run that goes on must too for both to stay the same bit for bit.
  void start_fresh_factorisation() {
    solver_.refactorise();
    if (segregated_) segregated_->refactorise();
  }

  /// Advances the flow by dt [s] with the case's flow.scheme: the coupled step (one (u, eta)
  /// system) or the segregated one (segregated_step.hpp). Throws RunError when a node dries or the
  /// solution is not finite; the state is then left at the start of the step.
  StepReport step(double dt);
  /// Drives the flow at the current time to steady state: Newton's method for the steady
  /// (Eulerian, SUPG) equations with a pseudo time term, whose step shrinks when a node dries or
  /// the residual jumps, until the residual relative to the starting state's is below
  /// TimeConfig::steady_tolerance. When Newton fails from the current state and from the initial
  /// one, continuation in the viscosity: the steady state of a more viscous flow, then step by
  /// step down to the case's (steady_state.cpp). Not converged: the state is the steady state at
  /// SteadyReport::viscosity.
  SteadyReport solve_steady();
  /// The other road to a steady state, when solve_steady cannot take it (a long channel whose
  /// pseudo steps follow its slow transient): steps of dt [s] until the largest change of the
  /// velocity in one step is at most `settled` times the largest velocity, or until time
  /// t_max [s]. Returns that relative change of the last step [-].
  double march_to_steady(double dt, double settled, double t_max);
  /// How much the last step changed the flow: max |u^{n+1} - u^n| / max |u^{n+1}| [-] (0 for
  /// water at rest). A flow with steady boundaries that has settled shows 1e-6 or less.
  double last_step_change() const;

  /// Body forces per unit mass [m s^-2] applied from the next step on (two-way coupling):
  /// per element (constant on it) and per P2 node (interpolated). Empty: none.
  void set_element_forces(std::vector<Vec2> forces) { element_forces_ = std::move(forces); }
  const std::vector<Vec2>& element_forces() const { return element_forces_; }
  /// The bodies' drag per element, c_e [1/s] in -c_e u, implicit; empty: none.
  void set_element_drag_rates(std::vector<double> rates) { element_drag_rates_ = std::move(rates); }
  const std::vector<double>& element_drag_rates() const { return element_drag_rates_; }
  void set_node_forces(std::vector<Vec2> forces) { node_forces_ = std::move(forces); }

  // ---- fields ----
  double time() const { return state_.time; }
  const FlowState& state() const { return state_; }
  const FlowState& previous_state() const { return previous_; }
  const std::vector<double>& eta() const { return state_.eta; }  // [m] P1
  const std::vector<double>& u() const { return state_.u; }      // [m/s] P2
  const std::vector<double>& v() const { return state_.v; }      // [m/s] P2
  const std::vector<double>& bed() const { return z_b_; }        // [m] P2
  std::vector<double> depth() const;                             // H [m] P2
  std::vector<double> vorticity() const;                         // dv/dx - du/dy [1/s] P2
  /// nu_t [m^2/s] per element (M-3) of the present state, as a step from it would take it.
  std::vector<double> eddy_viscosity() const;
  /// The friction law's coefficient (n, C or K) per element, at the centroid of its corners: the
  /// case's default, its raster, its zones (flow/friction_map.hpp); empty without friction.
  const std::vector<double>& friction_coefficients() const { return friction_coefficient_; }
  const WaterBalance& water_balance() const { return balance_; }
  /// Puts back the balance of a checkpoint (a restarted run continues its sums).
  void restore_water_balance(const WaterBalance& balance) { balance_ = balance; }
  double volume() const;  // [m^3]
  const Mesh& mesh() const { return mesh_; }
  const Case& flow_case() const { return case_; }
  const BoundaryConditions& boundary_conditions() const { return bc_; }
  /// Solves, factorisations and Krylov iterations of the linear solver so far.
  const LinearSolverCounts& linear_solver_counts() const { return solver_.counts(); }
  /// The segregated step (flow.scheme: segregated), null with the coupled one.
  const SegregatedStep* segregated_step() const { return segregated_.get(); }

 private:
  friend class SegregatedStep;
  StepReport step_coupled(double dt);
  void setup_coupled_system();
  struct Iteration {  // the linearised problem of one iteration
    double theta, inv_dt, t_new, t_source;
    bool characteristics;          // advection done by characteristics, else Eulerian
    double added_viscosity = 0.0;  // [m^2/s] on top of the case's (steady continuation)
    // The time term (u - u_d) inv_dt starts from u_d = now u^n + before u^{n-1} (BDF2), taken
    // at the paths' feet with characteristics; the same weights give eta_d.
    double now = 1.0, before = 0.0;  // [-]
    double dt_before = 0.0;          // [s] t^n - t^{n-1}
  };
  Iteration time_step(double dt) const;
  void setup_system();
  AssemblyParameters assembly_parameters(const Iteration& it) const;
  // The nodal values of element e (all but nu_e, which assemble_system sets).
  ElementState element_state(int e, const Iteration& it) const;
  void for_each_element(const std::function<void(int)>& visit) const;
  void departure_values(const Iteration& it, double dt);
  void assemble_system(const Iteration& it);
  void assemble_inflow_stabilisation();
  void apply_boundary_conditions(const Iteration& it);
  double elevation_boundary_level(int k, const Iteration& it) const;
  void set_boundary_velocities(const Iteration& it);
  double boundary_flux_weight(int c, const Iteration& it) const;
  Eigen::VectorXd solve();
  void unpack(const Eigen::VectorXd& x);
  Eigen::VectorXd pack(const FlowState& s) const;
  void record_fluxes(const Eigen::VectorXd& x);
  void update_balance(const Iteration& it, double dt, const Eigen::VectorXd& x);
  // The step's group rates (set before) into the sums, the volume, the source, BDF2's lag.
  void accumulate_balance(const Iteration& it, double dt);
  // H = eta - z_b [m] at P2 node `node` of state s (mid nodes: eta the mean of the edge's ends).
  double node_depth_of(const FlowState& s, int node) const;
  void restart_water_balance();  // V(0) = V now, nothing through the boundaries yet
  void check_state(const FlowState& s, double t) const;
  double volume_of(const FlowState& s) const;  // [m^3]
  double residual_norm(const Eigen::VectorXd& x) const;
  double steady_residual(const Iteration& it);
  bool newton_to_steady(Iteration it, double dt, double dt_max, double r_ref, double tolerance,
                        int max_iterations, SteadyReport& report);

  const Mesh& mesh_;
  const Case& case_;
  FlowSolverOptions options_;
  BoundaryConditions bc_;
  LinearSystem system_;
  LinearSolver solver_;
  ElementBlocks blocks_;  // the order of for_each_element
  std::optional<Characteristics> characteristics_;
  std::optional<P2MassMatrix> mass_;            // with characteristics and the theta-scheme
  bool coupled_system_ready_ = false;           // system_ set up (coupled step, steady solve)
  std::unique_ptr<SegregatedStep> segregated_;  // flow.scheme: segregated
  // [m/s] per P2 node: the time term's start u_d with characteristics (departure_values)
  std::vector<double> u_departure_, v_departure_;

  std::vector<double> z_b_;                   // [m] per P2 node
  std::vector<double> friction_coefficient_;  // n, C or K per element (the law's unit)
  std::vector<double> lumped_p1_;             // [m^2] integral of each P1 basis function
  std::vector<Vec2> element_forces_, node_forces_;
  std::vector<double> element_drag_rates_;  // [1/s]
  std::vector<double> open_flux_;           // [m^3/s] term (10) per mesh group, last assembly
  std::vector<int> elevation_group_;        // per elevation node: its mesh group
  std::vector<int> elevation_edges_;        // boundary edges of groups with an elevation alone
  std::vector<std::array<int, 2>> mid_vertices_;  // per P2 node >= vertex_count: edge ends
  double bed_volume_ = 0.0;                       // integral of z_b [m^3]
  double H_mean_ = 1.0;                           // [m] initial mean depth (residual scaling)

  FlowState state_;          // at t^{n+1} (the current iterate during a step)
  FlowState previous_;       // at t^n
  FlowState before_;         // at t^{n-1} (BDF2)
  bool history_ = false;     // previous_ is a step before state_ (false: set_state)
  FlowState linearisation_;  // x^k of the current iteration
  WaterBalance balance_;
};

}  // namespace flotsam
