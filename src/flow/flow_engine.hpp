#pragma once
// A flow engine: what the simulation asks of whichever engine advances (M-1) (issue 15 item 5).
// Two implement it, each in its own folder: the paper's P2-P1 finite elements (flow/fem) and the
// finite-volume engine for floods (flow/fv). The simulation holds one, chosen once at setup by
// flow.engine (coupling/flow_engines.hpp), as Clawpack picks a Riemann solver, and never asks
// which it holds.
#include <cstdint>
#include <string>
#include <vector>

#include "flow/flood_envelope.hpp"
#include "flow/flow_field.hpp"
#include "flow/flow_state.hpp"
#include "flow/result_fields.hpp"
#include "flow/water_balance.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

class ArchiveWriter;
class ArchiveReader;
struct TimeConfig;

/// Frozen mode's march to a steady state: how far it must settle, the largest change of the
/// velocity in one step over the largest velocity [-].
constexpr double settled_change = 1e-5;

/// The end of such a march at time t [s] with that `change` [-]: logged when it settled, else a
/// RunError telling the user to march longer (time.spin_up_end).
void finish_march(double change, double t);

class FlowEngine {
 public:
  virtual ~FlowEngine() = default;

  /// The case's initial state (bed, surface, velocity) at t = 0, the balance started.
  virtual void initialize() = 0;
  /// Advances the flow by dt [s], the coupling step: engines that need smaller stable steps take
  /// them inside. Throws RunError naming the time, place and quantity when the flow goes wrong.
  virtual void step(double dt) = 0;
  /// Frozen mode: drives the flow to a steady state, which then becomes the state at t = 0 with
  /// its water balance started afresh.
  virtual void settle(const TimeConfig& time) = 0;

  virtual double time() const = 0;  // [s]
  /// What bodies sample (states of the current step interpolated in time) and where their
  /// reactions go (two-way).
  virtual FlowField& field() = 0;
  const FlowField& field() const { return const_cast<FlowEngine*>(this)->field(); }
  /// The flow on the mesh's nodes: eta per vertex, u and v per P2 node (the FEM's own unknowns;
  /// the finite-volume engine averages its cells around each node). For pictures, backwater
  /// sections and probes of the whole field.
  virtual const FlowState& nodal_state() const = 0;
  /// Per mesh node: 1 wet, 0 dry (pictures draw dry ground as land); empty: all wet (the FEM).
  virtual std::vector<std::uint8_t> wet_nodes() const { return {}; }
  virtual const WaterBalance& water_balance() const = 0;
  virtual double volume() const = 0;  // [m^3]
  virtual const Mesh& mesh() const = 0;

  /// Writes the engine's fields at the run's time t [s] as a ParaView .vtu file.
  virtual void write_fields(const std::string& path, double t) const = 0;
  /// The same for the UGRID NetCDF results: the engine's faces over the mesh's nodes, once, and
  /// its fields now (result_fields.hpp).
  virtual ResultMesh result_mesh() const = 0;
  virtual ResultFields result_fields() const = 0;
  /// Everything the engine needs to continue bit for bit (checkpoints), records named
  /// `prefix`.*; and the same read back (InputError naming the file when it does not fit).
  virtual void save(ArchiveWriter& w, const std::string& prefix) const = 0;
  virtual void restore(ArchiveReader& r, const std::string& prefix) = 0;
  /// A shared flow (coupling/shared_flow.hpp): the state after a step, as save() wrote it, read
  /// back in place of computing the step. The state before it stays the start of the interval
  /// the bodies sample, as after step().
  virtual void restore_step(ArchiveReader& r, const std::string& prefix) = 0;
  /// Called after each checkpoint: the engine drops what a restarted run would not have (so
  /// that the run that goes on and a restarted one stay the same bit for bit).
  virtual void after_checkpoint() {}
  /// A flood split over MPI ranks: gathers on every rank what only the output reads (the flood
  /// envelopes); every rank calls it at the same points, before rank 0 writes.
  virtual void synchronize() {}
  /// Where the bodies lie during the next step: the cells under them carry debris for the
  /// hazard rating of the flood envelopes (hazard.hpp (M-H2)). Engines without envelopes
  /// ignore them.
  virtual void mark_debris(const std::vector<BodyFootprint>& /*bodies*/) {}
  /// The engine's own lines of the end-of-run summary (each ending in a newline), or "".
  virtual std::string summary() const { return ""; }
  /// Writes the flood envelopes of the run so far as GeoTIFF rasters on `grid`, files
  /// `prefix`_<envelope>.tif (flood_envelope.hpp); returns them. Only an engine that keeps
  /// envelopes (the finite-volume engine) is given rasters to write: the case reader refuses
  /// output.rasters for the others.
  virtual std::vector<std::string> write_envelope_rasters(const std::string& /*prefix*/,
                                                          const RasterGrid& /*grid*/) const {
    return {};
  }

  // Shorthands for the nodal fields.
  const std::vector<double>& eta() const { return nodal_state().eta; }  // [m] per vertex
  const std::vector<double>& u() const { return nodal_state().u; }      // [m/s] per P2 node
  const std::vector<double>& v() const { return nodal_state().v; }      // [m/s] per P2 node
};

}  // namespace flotsam
