#pragma once
// The finite-volume engine's solver (spec 7; docs/model.md "Finite-volume engine"): the
// conservative form of (M-1) in (h, hu, hv) on the cells of cell_mesh.hpp, integrated over a
// coupling step in as many explicit sub-steps as the Courant limit asks. One sub-step:
//
//   U1      = U^n + dt L(U^n) + R                  SSP Runge-Kutta 2 (Heun), (M-13)
//   U2      = (U^n + U1 + dt L(U1) + R) / 2
//   U^{n+1} = drag(friction(infiltration(U2, dt), dt), dt)
//                                   implicit, never reverse the flow: friction (M-14), then the
//                                   piers' drag (M-25, pier_drag.hpp) and the bodies'
//                                   (body_drag.hpp)
//
// where L is the finite-volume operator:  reconstruct (reconstruction.hpp) -> edge fluxes
// (hydrostatic reconstruction of Audusse et al. 2004 + HLLC, hllc_flux.hpp; boundaries by ghost
// states, fv_boundary.hpp; the edges under bridge decks, deck_flux.hpp) -> sum per cell with the
// bed-slope, Coriolis, wind and body sources; R = (w_i int r dt, 0, 0) the rain of the sub-step and
// infiltration its loss (rain_source.hpp, (M-17)), plus the sub-step's depth of the sources
// (flow_sources.hpp, (M-24)).
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "core/vec.hpp"
#include "flow/friction.hpp"
#include "flow/fv/body_drag.hpp"
#include "flow/fv/cell_mesh.hpp"
#include "flow/fv/deck_flux.hpp"
#include "flow/fv/flow_sources.hpp"
#include "flow/fv/fv_boundary.hpp"
#include "flow/fv/pier_drag.hpp"
#include "flow/fv/rain_source.hpp"
#include "flow/fv/rank_split.hpp"
#include "flow/fv/reconstruction.hpp"
#include "flow/fv/time_levels.hpp"
#include "flow/water_balance.hpp"
#include "io/case.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

/// The conserved state: depth and unit discharges per cell.
struct ConservedState {
  double time = 0.0;           // [s]
  std::vector<double> h;       // [m]
  std::vector<double> hu, hv;  // [m^2/s]
};

/// The numerical flux through a line of edges (a cross-section), times the edges' lengths.
struct SectionFlux {
  double discharge = 0.0;        // [m^3/s]
  Vec2 momentum = Vec2::Zero();  // [m^4/s^2] h u (u.n) + the pressure g h^2 / 2 (times rho: [N])
};

/// What the sub-steps of the run so far did (the end-of-run summary).
struct SubStepStats {
  long count = 0;             // sub-steps taken
  long rejected = 0;          // sub-steps retried at half the step (a negative depth)
  double smallest = 0.0;      // [s] smallest Courant step (0: none yet)
  double total = 0.0;         // [s] time covered by Courant-limited sub-steps
  double cell_updates = 0.0;  // cells advanced one step, summed (retried steps too)
};

class FiniteVolumeSolver {
 public:
  /// Keeps references to `mesh` and `flow_case`. Builds the cells (or takes `cells`, built by
  /// build_cell_mesh on the same mesh with the case's flow.fv.cells, shared by several runs)
  /// and resolves the boundary conditions (InputError naming a group the engine cannot take).
  FiniteVolumeSolver(const Mesh& mesh, const Case& flow_case,
                     std::shared_ptr<const CellMesh> cells = nullptr);

  /// Bed per cell and the case's initial state at t = 0; starts the water balance.
  void initialize();
  /// Advances to time() + dt [s] in Courant-limited sub-steps. RunError naming the time, the
  /// cell's position and the quantity when the state stops being finite or a depth negative
  /// even at 1/64 of the Courant step.
  void advance(double dt);

  /// Replaces the state (restart, frozen mode); the balance is left as it is.
  void set_state(const ConservedState& state);
  const ConservedState& state() const { return U_; }
  double time() const { return U_.time; }

  /// Body forces [N] per cell, acting on the water during the next steps (two-way coupling).
  void set_cell_forces(std::vector<Vec2> forces) { cell_force_ = std::move(forces); }
  /// The bodies' drag per cell, point-implicit after friction (body_drag.hpp); empty: none.
  void set_body_drag(BodyDrag drag) { body_drag_ = std::move(drag); }
  const BodyDrag& body_drag() const { return body_drag_; }
  /// The piers' form drag (pier_drag.hpp), with the impulse the water has given them since this
  /// solver started (a restart starts it again: it is not in checkpoints).
  const PierDrag& pier_drag() const { return pier_drag_; }
  /// Advance only this rank's cells (rank_split.hpp); the state is whole again after advance().
  /// nullptr: every cell (one rank).
  void set_rank_split(std::shared_ptr<const RankSplit> split);
  const RankSplit* rank_split() const { return split_.get(); }
  /// Called after every sub-step with the state's new time and the sub-step's length [s].
  void set_sub_step_observer(std::function<void(double t, double dt)> f) {
    sub_step_observer_ = std::move(f);
  }
  const std::vector<Vec2>& cell_forces() const { return cell_force_; }
  /// The weight w_i [-] of each cell by which the case's rain intensity is multiplied there
  /// (M-17): one per cell, finite and >= 0; 1 everywhere unless set (rain varying over the domain).
  void set_rain_weights(std::vector<double> weights) { rain_.set_weights(std::move(weights)); }
  const RainSource& rain() const { return rain_; }
  const FlowSources& sources() const { return sources_; }
  /// Per edge of cells().boundary_edges: 1 where water may cross it (a condition other than a
  /// wall), the edges whose values the ranks gather (rank_split.hpp).
  std::vector<char> open_boundary() const;

  /// The state's cell values and limited gradients (what the bodies sample).
  void fill_field(CellField& field) const;

  const CellMesh& cells() const { return cells_; }
  /// The time levels the run uses: flow.fv.time_levels, `auto` chosen (time_levels.hpp).
  int time_levels() const { return time_levels_; }
  /// The friction law's coefficient (n, C or K) per cell, at its centroid: the case's default,
  /// its raster, its zones (flow/friction_map.hpp); empty without friction.
  const std::vector<double>& friction_coefficients() const { return friction_coefficient_; }
  const std::vector<double>& bed() const { return z_; }              // [m] per cell
  const std::vector<double>& node_bed() const { return node_bed_; }  // [m] per mesh node
  double volume() const;                                             // [m^3]
  const WaterBalance& water_balance() const { return balance_; }
  void restore_water_balance(const WaterBalance& b) { balance_ = b; }
  /// V(0) = V now, nothing through the boundaries yet.
  void restart_water_balance();
  const SubStepStats& sub_steps() const { return stats_; }
  void restore_sub_steps(const SubStepStats& s) { stats_ = s; }
  /// The Courant step [s] of the current state (M-16) (infinite when all is dry and still).
  double courant_step() const;
  double wet_fraction() const;  // [-] of the cells' area deeper than output.wet_depth
  /// The scheme's own fluxes through `edges` at the current state (L evaluated as a sub-step's
  /// first stage does), each counted from its cell whose centroid lies behind along `direction`
  /// to the other (a boundary edge: along its normal's side): the discharge and the momentum flux
  /// as the receiving cell takes it (with its hydrostatic correction, (M-12)). A section's
  /// momentum balance checked with these is the scheme's, whatever side a sampled value takes;
  /// a section may be a staircase of edges (those between the cells on either side of a line).
  SectionFlux section_flux(std::span<const int> edges, Vec2 direction) const;
  double dry_depth() const { return dry_depth_; }                    // [m]
  double water_density() const { return case_.flow.water_density; }  // [kg/m^3]

 private:
  /// The time levels of L's part being evaluated (local time stepping): all by default.
  struct LevelRange {
    int lo = 0, hi = 1 << 30;
    bool holds(const TimeLevels* t, int edge) const {
      return !t || (t->edge_level[edge] >= lo && t->edge_level[edge] <= hi);
    }
  };
  /// What edge k of cell i adds to the cell's d(A U)/dt [m^3/s, m^4/s^2] (sum_cell_rates).
  struct EdgeRate {
    double h, hu, hv;
  };

  /// dU/dt = L(U) at time t into rate_; boundary outflow [m^3/s] per group into outflow_rate_.
  /// `courant`: also the Courant step of U's wave speeds into stage_courant_step_.
  void evaluate(const ConservedState& U, double t, bool courant = true) const;
  /// Its edge fluxes only (every edge, at U): what local time stepping starts a cycle with.
  void evaluate_fluxes(const ConservedState& U, double t) const;
  void compute_edge_fluxes(std::span<const int> edges, std::span<const int> boundary_edges,
                           double t, LevelRange levels) const;
  void deck_fluxes(LevelRange levels) const;  // the edges under bridge decks (deck_flux.hpp)
  EdgeRate edge_rate(int i, int k) const;
  void add_local_rate(int i, double h, double hu, double hv, double& ru, double& rv) const;
  void load_cell(int i, double h, double hu, double hv) const;
  double speed(const ConservedState& U, int i) const;
  void apply_friction(ConservedState& U, int i, double dt) const;
  void sum_cell_rates(const ConservedState& U, bool courant = true) const;
  bool add_stage(const ConservedState& U, const ConservedState& y, ConservedState& out, double a,
                 double b, double dt);
  void apply_friction(ConservedState& U, double dt) const;
  void apply_drag(ConservedState& U, double dt);
  void apply_pier_drag(ConservedState& U, int i, double dt);
  // One flood over ranks (rank_split.hpp): this rank's part of L and of the stages.
  int discharge_condition(int edge) const;
  bool open_edge(int edge) const;
  void gather_discharge_weights(std::span<const int> boundary_edges) const;
  /// This rank's split while advance() runs (each rank its own cells), else nullptr (all cells).
  const RankSplit* part() const { return advancing_ ? split_.get() : nullptr; }
  /// The cells this rank advances: its own over ranks, else all.
  std::span<const int> my_cells() const {
    const RankSplit* split = part();
    return split ? split->own() : std::span<const int>(all_cells_);
  }
  void exchange(ConservedState& U) const;
  void gather(ConservedState& U) const;
  // Local time stepping (local_time_steps.cpp).
  void advance_local(double dt);
  std::vector<std::vector<int>> tied_cells() const;
  void choose_levels(double dt0, int cap);
  int local_cycle(double t0, double dt0);
  /// The cycle's levels as this rank advances them: *levels_, or its share over ranks.
  const TimeLevels& my_levels();
  void exchange_steps(bool with_state);
  void evaluate_part(const EdgeSet& part, std::span<const int> boundary_edges, double t,
                     LevelRange levels, bool first_stage);
  void take_shares(std::span<const int> edges, std::span<const int> boundary_edges,
                   bool first_stage);
  void start_steps(const std::vector<int>& all, const std::vector<int>& mine, double t);
  int finish_steps(const std::vector<int>& all, const std::vector<int>& mine, double t_end);
  void gather_step();
  void apply_infiltration(ConservedState& U, double dt);
  void load_cells(const ConservedState& U) const;  // desingularised velocities into field_
  int clamp_round_off(ConservedState& U, double weight, std::span<const int> cells);
  [[noreturn]] void fail_at(const ConservedState& U, int cell, double t) const;
  void check(const ConservedState& U) const;

  const Mesh& mesh_;
  const Case& case_;
  std::shared_ptr<const RankSplit> split_;  // nullptr: one rank
  bool advancing_ = false;
  mutable std::vector<double> boundary_value_;    // per boundary edge (split_boundary_sums)
  std::shared_ptr<const CellMesh> shared_cells_;  // owns cells_
  const CellMesh& cells_;
  FvBoundaries boundaries_;
  std::vector<DeckEdge> deck_edges_;  // the edges under bridge decks
  FrictionModel friction_;
  std::vector<double> friction_coefficient_;  // n, C or K per cell (the law's unit)
  std::function<void(double, double)> sub_step_observer_;
  double g_;               // [m s^-2]
  double dry_depth_;       // [m]
  double velocity_depth_;  // H_eps [m]
  double coriolis_;        // f [1/s]
  Vec2 wind_stress_;       // tau_w / rho [m^2/s^2]

  std::vector<double> node_bed_;  // [m] bed at the mesh's nodes
  std::vector<double> z_;         // [m] bed per cell: the mean of its corners
  ConservedState U_, U1_;
  // Scratch of the operator L (mutable: evaluating L, as courant_step does, changes no state).
  mutable CellField field_;       // the stage's reconstruction
  std::vector<Vec2> cell_force_;  // [N] body reactions
  BodyDrag body_drag_;
  PierDrag pier_drag_;
  RainSource rain_;
  double rain_depth_ = 0.0;  // [m] int r dt over the current sub-step (times w_i per cell)
  FlowSources sources_;
  std::vector<double> source_depth_;  // [m] per cell, the sources' over the current sub-step
  // Per edge: flux through it along its normal (mass [m^2/s], momentum [m^3/s^2]), and the
  // hydrostatic corrections g/2 (h_e^2 - h*_e^2) of its two sides [m^3/s^2].
  mutable std::vector<double> flux_mass_, flux_x_, flux_y_, side_left_, side_right_;
  mutable std::vector<double>
      edge_speed_;  // [m/s] largest wave speed of the edge's Riemann problem
  mutable std::vector<double> edge_discharge_;  // [m^2/s] share q_e of a discharge condition
  mutable double stage_courant_step_ = 0.0;     // [s] of the last evaluation of L
  mutable std::vector<double> rate_h_, rate_hu_, rate_hv_;  // dU/dt per cell
  mutable std::vector<double> outflow_rate_;                // [m^3/s] per mesh group, this stage
  WaterBalance balance_;
  SubStepStats stats_;
  // Every cell and every edge (the whole mesh as one part). Local time stepping: the cells that
  // share a level, this cycle's levels; per cell its Courant step [s], its step's start [s] and
  // the rain and sources' rate [m/s] over it; per cell and local edge, what the edge gave the cell
  // at the cell's first stage (EdgeRate, side_*) and the sum of the edge's evaluations over the
  // cell's step times their weights (sum_*) [m^3, m^4/s].
  std::vector<int> all_cells_, all_edges_;
  int time_levels_ = 1;
  std::vector<std::vector<int>> level_ties_;
  TimeLevels full_levels_, capped_levels_;  // this cycle's, and those capped for a last one
  const TimeLevels* levels_ = nullptr;      // the cycle's: one of those
  std::vector<int> raw_levels_;             // what the Courant steps allowed, as last built
  std::vector<char> levels_dry_;            // dry_ as last built
  int full_version_ = 0, capped_from_ = -1;
  int levels_built_ = 0;    // counts the builds of full_ and capped_levels_
  TimeLevels rank_levels_;  // over ranks: this rank's share of *levels_
  const TimeLevels* rank_levels_for_ = nullptr;
  int rank_levels_built_ = -1;        // levels_built_ when rank_levels_ was taken
  std::vector<double> level_inputs_;  // over ranks: each cell's raw level and dryness
  std::vector<double> cell_step_, step_start_, feed_;
  std::vector<double> level_step_;   // [s] 2^m dt0 per level m, this cycle
  std::vector<double> infiltrated_;  // [m^3] per cell, infiltrated this cycle
  std::vector<char> dry_;            // per cell, at the cycle's start
  std::vector<double> side_h_, side_hu_, side_hv_;
  std::vector<double> sum_h_, sum_hu_, sum_hv_;
};

}  // namespace flotsam
