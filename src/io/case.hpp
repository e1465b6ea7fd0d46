#pragma once
// A case: everything a run needs, as read from a YAML case file (docs/case-format.md) or built in
// code by tests and benchmarks. Every field has its unit and its default here; the parser
// (io/case_file.hpp) fills these structures and rejects what is out of range.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bodies/body_set.hpp"
#include "bridges/bridge_config.hpp"
#include "core/calendar_time.hpp"
#include "core/expression.hpp"
#include "core/time_series.hpp"
#include "core/vec.hpp"
#include "geo/raster.hpp"
#include "mesh/geometry.hpp"

namespace flotsam {

// ---- bed ----------------------------------------------------------------------------------

struct BedConfig {
  enum class Kind { flat, slope, table, expression, raster } kind = Kind::flat;
  double level = 0.0;         // z_b at the origin [m]
  Vec2 slope = Vec2::Zero();  // (-dz_b/dx, -dz_b/dy) [-]: positive = bed falls along +x / +y
  TimeSeries profile_x;       // kind == table: z_b as a function of x [m] (piecewise linear)
  Expression expression;      // kind == expression: z_b(x, y) [m]; kind == raster: an optional
                              // edit z_b(x, y, z) of the raster's elevation z [m]
  std::shared_ptr<const Raster> raster;  // kind == raster: the terrain (sampled bilinearly)
  std::string origin;                    // "case.yaml:12: bed.raster", for messages
};

// ---- flow ---------------------------------------------------------------------------------

/// Which engine advances the flow (docs/model.md): the paper's P2-P1 finite elements, or the
/// finite-volume engine for floods with wet/dry fronts and shocks (spec 7).
enum class FlowEngineKind { fem, fv };

enum class FrictionLaw { none, manning, chezy, strickler };
enum class TurbulenceModel { none, smagorinsky, mixing_length };

struct BoundaryCondition {
  // free: transmissive, what reaches the boundary leaves (finite-volume engine only)
  enum class Kind { elevation, discharge, velocity, wall, noslip, free } kind = Kind::wall;
  std::string group;   // mesh physical group
  TimeSeries value;    // eta_b [m] or Q [m^3/s]
  TimeSeries value_y;  // velocity: u_b = (value, value_y) [m/s]
  int line = 0;        // line of the group's key in the case file, for messages (0: built in code)
};

/// The finite-volume engine's cells (docs/model.md "Finite-volume engine"): the mesh's
/// triangles, or each six-node triangle split into its four sub-triangles (the paper's Fig. 3).
enum class FvCells { elements, split };

/// Numerical choices of the finite-volume engine (src/flow/fv, docs/model.md).
struct FiniteVolumeConfig {
  FvCells cells = FvCells::elements;
  int order = 2;         // 1: piecewise constant; 2: MUSCL reconstruction with a limiter
  double courant = 0.9;  // [-] in (0, 1]: dt = courant * min(2 A / (3 l_max) / s), s the
                         // largest wave speed at the cell's edges; up to 0.5 depths stay
                         // positive by construction, above a sub-step that makes one negative is
                         // retried at half the step (model.md (M-16))
  double velocity_depth = 1e-5;  // H_eps [m]: below it velocities are desingularised (model.md)
  int time_levels = 0;     // [-] local time stepping: steps dt0 .. 2^(levels-1) dt0 (1: one step);
                           // 0: `auto` (flow/fv/time_levels.hpp choose_time_levels)
  double pier_drag = 1.2;  // C_d [-] of the piers' form drag (model.md (M-25)); 0: none
};

/// Rain on the domain with a constant infiltration loss (flow.rain; finite-volume engine only,
/// docs/model.md (M-17)). The engine multiplies the intensity by a weight per cell: the value of
/// the raster's pixel under the cell's centroid when a raster is given, else 1.
struct RainConfig {
  bool enabled = false;       // flow.rain given
  TimeSeries intensity;       // i(t) [mm/h]: a constant or a hyetograph, >= 0
  double infiltration = 0.0;  // f [mm/h] >= 0: lost where there is water, never more than it
  std::shared_ptr<const Raster> raster;  // w [-] per pixel, >= 0, covering every cell; or none
  std::string raster_origin;             // "case.yaml:7: flow.rain.raster", for messages
  int line = 0;  // line of the key flow.rain in the case file, for messages (0: built in code)
};

/// Water let in inside the domain (flow.sources; docs/model.md "Sources", (M-24)): a discharge
/// Q(t) >= 0 into the cell holding `point`, or spread over the cells whose centroids lie in
/// `polygon` in proportion to their areas. It brings no momentum.
struct FlowSource {
  std::string name;           // the entry's `name`, or "flow.sources[k]"
  std::vector<Vec2> polygon;  // [m] a simple polygon; empty: a point source
  Vec2 point = Vec2::Zero();  // [m] of a point source
  TimeSeries discharge;       // Q(t) [m^3/s] >= 0, a constant or a hydrograph
  std::string origin;         // "case.yaml:12: flow.sources[0] (culvert)", for messages
};

/// A polygon with its own friction coefficient (flow.friction.zones): its outer ring and its
/// holes, corners in order. `origin` names it in messages: "case.yaml:9: flow.friction.zones[0]",
/// or "case.yaml:9: flow.friction.zones: landuse.gpkg, layer 'landuse', feature 3".
struct FrictionZone {
  std::vector<Vec2> ring;                // [m] a simple polygon
  std::vector<std::vector<Vec2>> holes;  // [m] not in the zone
  double coefficient = 0.0;              // n, C or K as flow.friction.law says, > 0
  std::string origin;
};

/// Friction varying over the domain (docs/model.md "Friction over the domain"): at each cell
/// centroid (FV) or element centroid (FEM), the default coefficient, replaced by the raster's
/// pixel there when it holds a value, replaced by each zone holding the point in turn (the last
/// one listed wins).
struct FrictionMapConfig {
  std::shared_ptr<const Raster> raster;  // the coefficient per pixel (nearest); or none
  std::string raster_origin;             // "case.yaml:8: flow.friction.raster", for messages
  std::vector<FrictionZone> zones;       // in the order listed
  bool empty() const { return !raster && zones.empty(); }
};

/// How the FEM engine advances a step (docs/model.md "FEM engine"): one coupled (u, eta) system
/// per step, or the segregated (projection) step: momentum with a lumped P2 mass, then one P1
/// system for the elevation, its SPD Schur complement plus the depth carried by the current,
/// preconditioned by the former's Cholesky factor (src/flow/fem/segregated_step.hpp).
enum class FlowScheme { coupled, segregated };

struct FlowConfig {
  FlowEngineKind engine = FlowEngineKind::fem;
  FlowScheme scheme = FlowScheme::coupled;  // FEM engine only
  FiniteVolumeConfig fv;
  double gravity = 9.81;          // g [m s^-2]
  double water_density = 1000.0;  // rho [kg m^-3]
  double viscosity = 1e-6;        // nu [m^2/s] (M-3)
  FrictionLaw friction = FrictionLaw::none;
  double friction_coefficient = 0.0;  // n [s m^-1/3] (manning), C [m^1/2/s] (chezy), K (strickler)
  FrictionMapConfig friction_map;     // where the coefficient differs from the one above
  TurbulenceModel turbulence = TurbulenceModel::none;
  double smagorinsky_constant = 0.2;  // C_s [-]
  double latitude_deg = 0.0;          // phi [deg]; Coriolis on when coriolis == true
  bool coriolis = false;
  Vec2 wind = Vec2::Zero();  // W at 10 m [m/s]
  RainConfig rain;
  std::vector<FlowSource> sources;
  double min_depth = 1e-3;  // H_min [m], friction denominator bound (spec 1.1)
  // H_dry [m] (spec 1.5): unset, the engine's default (dry_depth_or_default).
  std::optional<double> dry_depth;
  std::vector<BoundaryCondition> boundaries;

  /// H_dry [m]: the case's, else 1e-3 m for the FEM (spec 1.5) and 1e-5 m for the finite
  /// volumes, whose cells are first order below it (docs/model.md "Thin films").
  double dry_depth_or_default() const {
    return dry_depth.value_or(engine == FlowEngineKind::fv ? 1e-5 : 1e-3);
  }

  // Initial state: still water with eta linear in x between the two values (spec 8.2), or flat.
  double initial_eta_start = 0.0;  // eta at x = x_min [m]
  double initial_eta_end = 0.0;    // eta at x = x_max [m]
  // Or formulas in x, y (flow.initial.eta / u / v); empty: the above, at rest. Where eta is
  // below the bed the cell (or node) starts dry.
  // The case file's eta goes to initial_eta only when it is a formula (a number sets
  // initial_eta_start = initial_eta_end, and initial_eta stays empty); its u and v, numbers or
  // formulas, are kept as formulas (a number is a formula of its text), empty when not given.
  Expression initial_eta;  // [m]
  Expression initial_u;    // [m/s]
  Expression initial_v;    // [m/s]
};

// ---- time ---------------------------------------------------------------------------------

enum class CouplingMode { frozen, one_way, two_way };

/// How frozen mode finds its steady flow.
enum class SteadyMethod {
  solve,  // Newton on the steady equations (Eulerian form), marching when it does not converge
  march,  // marching in time with the case's time scheme until the flow stops changing
};

/// How the time derivative of (M-1) is discretised (docs/model.md "Time scheme").
enum class TimeScheme {
  theta,  // the theta-scheme (first order unless theta = 1/2)
  bdf2,   // second-order backward differences, all terms at t^{n+1}; the first step after the
          // initial state or a state set without its history takes u^{n-1} = u^n
};

struct TimeConfig {
  double end = 3600.0;  // [s] simulated time
  double step = 0.1;    // flow step dt [s]
  CouplingMode mode = CouplingMode::two_way;
  SteadyMethod steady_method = SteadyMethod::solve;  // frozen mode
  double steady_tolerance = 1e-8;   // steady/frozen mode: relative residual to stop at [-]
  int steady_max_iterations = 100;  // then frozen mode marches in time to the steady state
  double spin_up_step = 20.0;       // [s] flow step of that march
  double spin_up_end = 14400.0;     // [s] longest march before the run stops
  TimeScheme scheme = TimeScheme::theta;
  double theta = 0.6;     // [-] of TimeScheme::theta: 0.5 Crank-Nicolson, 1 backward Euler
  CalendarTime origin{};  // the calendar time (UTC) of t = 0, for the time axes of the results
};

// ---- bodies -------------------------------------------------------------------------------

enum class DragLaw { ganser, constant };

struct BodyPhysics {
  DragLaw drag_law = DragLaw::ganser;
  double drag_coefficient = 1.2;        // C_d when drag_law == constant [-]
  double added_mass_coefficient = 0.5;  // C_a [-] (M-5)
  bool center_of_pressure = true;       // (M-7)
  int drag_points = 1;                  // slices along the body (spec 3.2)
  double rotation_coefficient = 1.0;    // C_r [-] (M-8)
  double bed_friction = 0.6;            // mu_bed [-] (spec 3.4)
  double rk_tolerance = 1e-6;           // RKF45 tolerance on the weighted error norm [-]
};

/// The contact solver (docs/model.md "Contacts"): Box2D v2.4's sequential impulses with a
/// position stage, or Box2D v3's soft step (sub-steps with soft contacts).
enum class ContactSolverKind { sequential_impulses, soft_step };

struct ContactConfig {
  ContactSolverKind solver = ContactSolverKind::sequential_impulses;
  double restitution = 1.0;  // e [-] (M-9); the paper's case uses 1
  double friction = 0.5;     // mu_c [-]
  bool added_mass_in_contact = false;
  int iterations = 20;  // impulse sweeps per contact solve
  // Contact solver settings (src/contact, docs/model.md "Contacts").
  double restitution_threshold = 0.01;  // [m/s] slower approaches do not bounce (resting contact)
  double velocity_tolerance = 1e-6;     // [m/s] sweeps stop when no point's velocity changes more
  int position_iterations = 10;         // position-correction sweeps (at most)
  double allowed_overlap = 0.005;  // [-] overlap left uncorrected, fraction of the thinner width
  // Soft step only (src/contact/soft_step.hpp).
  int substeps = 4;             // sub-steps per contact interval
  double contact_hertz = 30.0;  // [Hz] stiffness of a soft contact, as a natural frequency
  double damping_ratio = 10.0;  // zeta [-] of a soft contact
  // Sleeping islands (src/contact/island_sleep.hpp): an island still for sleep_time is not solved
  // until touched or its forces change. 0: never (the case file's default with soft_step is
  // soft_step_sleep_time).
  double sleep_time = 0.0;    // T_s [s]
  double sleep_speed = 1e-3;  // v_s [m/s]
};

constexpr double soft_step_sleep_time = 0.5;  // [s] Box2D's b2_timeToSleep

/// Bodies released from a line or a zone (spec 5), at a rate over [start_time, end_time] or
/// `count` of them at once at start_time, with sizes drawn uniformly in ranges.
struct Release {
  Vec2 line_start = Vec2::Zero(), line_end = Vec2::Zero();  // [m] release line (no zone)
  std::vector<Vec2> zone;                   // [m] corners of a release zone; empty: the line
  double start_time = 0.0, end_time = 0.0;  // [s]; end_time unused with a count
  double rate = 0.0;                        // bodies per minute [1/min]; unused with a count
  long count = 0;                           // > 0: this many bodies at once at start_time
  Shape shape = Shape::log;
  double length_min = 20.0, length_max = 20.0;      // L [m]
  double width_min = 1.0, width_max = 1.0;          // l [m]
  double height = 1.0;                              // b for boxes [m]
  double density_min = 600.0, density_max = 600.0;  // [kg m^-3]
  double angle_min_deg = 0.0, angle_max_deg = 360.0;
  unsigned long seed = 1;
  int source_line = 0;  // line of the release in the case file, for messages (0: built in code)
};

/// How far down a jam at a bridge reaches (docs/model.md "Vertical extent of a jam").
enum class JamExtent {
  layer,         // each body acts on the water over its own draft (the paper's floating layer)
  accumulation,  // a jam at a bridge is a porous accumulation of thickness (M-J1)
};

struct JamConfig {
  JamExtent vertical_extent = JamExtent::layer;
  double porosity = 0.5;  // P [-], voids over the accumulation's bulk volume (accumulation only)
};

struct BodiesConfig {
  std::vector<BodySpec> bodies;  // given explicitly
  std::vector<Release> releases;
  BodyPhysics physics;
  ContactConfig contact;
  JamConfig jams;
};

// ---- output -------------------------------------------------------------------------------

/// A gauge (output.probes): eta, H, u, v sampled at a point at every coupling step.
struct Probe {
  std::string name;
  Vec2 position = Vec2::Zero();  // [m]
  int line = 0;                  // line in the case file, for messages (0: built in code)
};

/// The result files besides the tables (docs/output-format.md): ParaView's .vtu/.vtp/.pvd, the
/// UGRID NetCDF file of the flow and the debris' GeoPackage layers (QGIS, xarray).
struct OutputFormats {
  bool vtk = true;
  bool ugrid = false;
  bool gpkg = false;
};

struct OutputConfig {
  std::string directory = "out";  // relative to the working directory
  double interval = 60.0;         // [s] between field outputs
  bool overwrite = false;         // replace an existing output folder (else: error)
  bool backwater = false;     // run a reference flow without bodies alongside (two-way), for the
                              // water-surface rise upstream of each bridge (spec 6.3); doubles the
                              // flow's cost
  std::vector<Probe> probes;  // gauges, written to <name>_probes.csv
  double probe_interval = 0.0;     // [s] between probe rows; 0: every coupling step
  double wet_depth = 0.01;         // [m] deeper counts as wet for the flood envelopes' arrival time
                                   // and wet duration (finite-volume engine)
  double raster_resolution = 0.0;  // [m] pixel size of the envelopes' GeoTIFF rasters; 0: none
  OutputFormats formats{};         // output.formats; by default vtk, and ugrid and gpkg as well
                                   // when the case has a coordinate system (geodata)
};

/// One setting of a case as its file gives it (io/case_digest.hpp): the key path
/// ("flow.friction.coefficient", "bodies.list[2].x") and the value in a canonical text; for a
/// file the case reads, "<key> (file contents)" and the checksum of its bytes.
struct CaseSetting {
  std::string key;
  std::string value;
  bool operator==(const CaseSetting&) const = default;
};

/// A file the case reads (the mesh, rasters, vector files): the key naming it and its path.
struct InputFile {
  std::string key;
  std::string path;
};

struct Case {
  std::string file;  // the case file, for messages ("" when built in code)
  std::string name;  // defaults to the file's stem
  MeshSource mesh;
  std::vector<BridgeConfig> bridges;  // bridges: (a mesh.channel makes its own from its piers)
  BedConfig bed;
  FlowConfig flow;
  TimeConfig time;
  BodiesConfig bodies;
  OutputConfig output;
  std::vector<CaseSetting> settings;   // every value of the case file, for restarts; empty when
                                       // built in code
  std::vector<InputFile> input_files;  // read by the run: never deleted by --overwrite
  std::string crs_wkt;  // the coordinate system of the case's coordinates (WKT): the key crs, else
                        // the terrain raster's, else mesh.region's files'; empty: none
};

}  // namespace flotsam
