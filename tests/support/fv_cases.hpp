#pragma once
// What the finite-volume verification cases (tests/verification/fv_*.cpp) share: a frictionless
// case for the finite-volume engine on a mesh given in memory, the engine run in coupling steps
// with its depth checked after each, and the measures they report: the L1 error of a cell field
// against an exact solution, the observed order between nested meshes, and wall-clock time.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/constants.hpp"
#include "flow/fv/fv_engine.hpp"
#include "io/case.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam::test {

/// A case for the finite-volume engine: flat bed at 0, no friction, no viscosity, the mesh given
/// in memory; `walls` lists groups to be walls (each test adds its other conditions).
inline Case fv_case(const std::vector<std::string>& walls) {
  Case c;
  c.mesh.kind = MeshSource::Kind::file;  // the mesh is given in memory, not generated
  c.flow.engine = FlowEngineKind::fv;
  c.flow.friction = FrictionLaw::none;
  c.flow.viscosity = 0.0;
  for (const std::string& group : walls)
    c.flow.boundaries.push_back(
        {BoundaryCondition::Kind::wall, group, TimeSeries(0.0), TimeSeries(0.0)});
  return c;
}

/// The dam-break channel of fv_dam_break_dry_bed.cpp and fv_dam_break_wet_bed.cpp: 20 m x 0.4 m,
/// walls all round (the waves stay inside until the end), flat bed, the dam at x = 10 m with
/// h_left upstream and h_right downstream [m], water at rest; `refinement` k gives 100 2^k x
/// 2^(k+1) square rectangles (two triangles each), nested as k grows.
struct DamBreakChannel {
  static constexpr double length = 20.0, width = 0.4, x_dam = 10.0;  // [m]
  static int nx(int refinement) { return 100 << refinement; }
  static int ny(int refinement) { return 2 << refinement; }
};

inline Mesh dam_break_mesh(int refinement) {
  using D = DamBreakChannel;
  return make_rectangle_mesh(
      {0.0, 0.0, D::length, D::width, D::nx(refinement), D::ny(refinement), true});
}

inline Case dam_break_case(double h_left, double h_right) {
  Case c = fv_case({"left", "right", "bottom", "top"});
  c.flow.initial_eta = Expression("x < " + std::to_string(DamBreakChannel::x_dam) + " ? " +
                                      std::to_string(h_left) + " : " + std::to_string(h_right),
                                  "dam break");
  return c;
}

/// The width of the cells [m] of a mesh of square rectangles cut into right isosceles triangles
/// (make_rectangle_mesh with dx = dy): their leg sqrt(2 A), dx for cells that are the mesh's
/// triangles (flow.fv.cells: elements), dx / 2 for their sub-triangles (split).
inline double cell_width(const CellMesh& cells) {
  double area = 0.0;
  for (double A : cells.area) area += A;
  return std::sqrt(2.0 * area / cells.cell_count);
}

/// The smallest depth of the engine's cells [m].
inline double smallest_depth(const FvEngine& engine) {
  const auto& h = engine.solver().state().h;
  return *std::min_element(h.begin(), h.end());
}

/// Runs the engine to `end` [s] in coupling steps of `step` [s], expecting no negative depth
/// after any of them.
inline void run_to(FvEngine& engine, double end, double step) {
  while (engine.time() < end - 1e-9 * step) {
    engine.step(std::min(step, end - engine.time()));
    ASSERT_GE(smallest_depth(engine), 0.0) << "negative depth at t = " << engine.time() << " s";
  }
}

/// Runs the engine `window` [s] further (coupling steps of `step` [s]) and returns the largest
/// change of a cell's depth over it [m]: a steady state's measure.
inline double depth_change_over(FvEngine& engine, double window, double step) {
  const std::vector<double> before = engine.solver().state().h;
  run_to(engine, engine.time() + window, step);
  double change = 0.0;
  for (std::size_t i = 0; i < before.size(); ++i)
    change = std::max(change, std::abs(engine.solver().state().h[i] - before[i]));
  return change;
}

/// The L1 error of a cell field against an exact solution taken at the cells' centroids,
/// per unit area of the domain: sum_i A_i |phi_i - phi(x_i)| / sum_i A_i [unit of phi].
inline double l1_error(const CellMesh& cells, const std::vector<double>& phi,
                       const std::function<double(const Vec2&)>& exact) {
  double error = 0.0, area = 0.0;
  for (int i = 0; i < cells.cell_count; ++i) {
    error += cells.area[i] * std::abs(phi[i] - exact(cells.centroid[i]));
    area += cells.area[i];
  }
  return error / area;
}

/// The observed order of an error that falls from `coarse` to `fine` when the cells halve [-].
inline double observed_order(double coarse, double fine) {
  return std::log2(coarse / fine);
}

/// Wall-clock seconds since construction.
class Stopwatch {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// Thacker's planar surface in a paraboloid (Thacker 1981, J. Fluid Mech. 107; SWASHES 4.2.2,
/// Delestre et al. 2013) of fv_thacker_paraboloid.cpp and its slow part: bed
/// z(r) = -h0 (1 - r^2 / a^2) in the box [0, L]^2 with walls, r measured from its centre; the
/// surface stays a plane that turns round the centre, the water moving as one at
///   eta(x, y, t) = (eta_p h0 / a^2) (2 (x - L/2) cos(omega t) + 2 (y - L/2) sin(omega t) - eta_p)
///   u = -eta_p omega sin(omega t),   v = eta_p omega cos(omega t),   omega = sqrt(2 g h0) / a,
/// h = eta - z where positive, dry elsewhere. SWASHES' parameters.
struct ThackerParaboloid {
  static constexpr double g = 9.81;                                    // [m s^-2]
  static constexpr double a = 1.0, h0 = 0.1, L = 4.0;                  // [m]
  static constexpr double eta_p = 0.5;                                 // [m] SWASHES' eta
  static double omega() { return std::sqrt(2.0 * g * h0) / a; }        // [1/s]
  static double period() { return 2.0 * std::numbers::pi / omega(); }  // [s]
  static double bed(double x, double y) {
    const double r2 = (x - 0.5 * L) * (x - 0.5 * L) + (y - 0.5 * L) * (y - 0.5 * L);
    return -h0 * (1.0 - r2 / (a * a));
  }
  static double eta(double x, double y, double t) {
    const double w = omega() * t;
    return eta_p * h0 / (a * a) *
           (2.0 * (x - 0.5 * L) * std::cos(w) + 2.0 * (y - 0.5 * L) * std::sin(w) - eta_p);
  }
  static double depth(double x, double y, double t) {
    return std::max(0.0, eta(x, y, t) - bed(x, y));
  }
  static double u(double t) { return -eta_p * omega() * std::sin(omega() * t); }  // [m/s]
  static double v(double t) { return eta_p * omega() * std::cos(omega() * t); }   // [m/s]
};

/// What one run of Thacker's paraboloid measures after `periods` periods on n x n rectangles.
struct ThackerRun {
  int n;
  double cell_width;     // [m] cell_width()
  double error_h;        // [m] L1 per unit area of the box
  double relative_h;     // [-] error_h over the exact depth's mean over the box
  double error_hu;       // [m^2/s] L1 per unit area of the box
  double volume_change;  // [-] (V(t) - V(0)) / V(0)
  double balance;        // [-] relative water balance error
  double seconds;
};

/// The engine at its defaults.
inline ThackerRun run_thacker(int n, double periods) {
  using T = ThackerParaboloid;
  const Stopwatch clock;
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, T::L, T::L, n, n, true});
  Case c = fv_case({"left", "right", "bottom", "top"});
  c.bed.kind = BedConfig::Kind::expression;
  // The formulas above with SWASHES' numbers.
  c.bed.expression = Expression("-0.1 * (1 - ((x - 2)^2 + (y - 2)^2))", "thacker bed");
  c.flow.initial_eta = Expression("0.05 * (2 * (x - 2) - 0.5)", "thacker eta(t = 0)");
  c.flow.initial_u = Expression("0", "thacker u(t = 0)");
  char v0[32];
  std::snprintf(v0, sizeof v0, "%.17g", T::v(0.0));
  c.flow.initial_v = Expression(v0, "thacker v(t = 0)");
  FvEngine engine(mesh, c);
  engine.initialize();
  const double end = periods * T::period();
  run_to(engine, end, T::period() / 40.0);
  const CellMesh& cells = engine.solver().cells();
  const ConservedState& U = engine.solver().state();
  const WaterBalance& balance = engine.water_balance();
  ThackerRun r{};
  r.n = n;
  r.cell_width = cell_width(cells);
  const auto exact = [end](const Vec2& p) { return T::depth(p.x(), p.y(), end); };
  r.error_h = l1_error(cells, U.h, exact);
  r.relative_h = r.error_h / l1_error(cells, std::vector<double>(U.h.size(), 0.0), exact);
  r.error_hu = l1_error(cells, U.hu,
                        [end](const Vec2& p) { return T::depth(p.x(), p.y(), end) * T::u(end); });
  r.volume_change = (balance.volume - balance.initial_volume) / balance.initial_volume;
  r.balance = balance.relative_error();
  r.seconds = clock.seconds();
  return r;
}

/// Rain on a tilted plane (fv_rain_on_tilted_plane.cpp and its slow part): a plane L long and B
/// wide falling at slope S along x, Manning's n, dry at t = 0, rain i from t = 0 on; walls on
/// three sides, the lower end x = L open (RainPlaneOutlet). The kinematic wave's outflow per
/// unit width there
/// (Overton & Meadows 1976, ch. 4):
///   q(t) = i L (t / t_e)^(5/3) for t <= t_e, i L after;  t_e = (n L / (sqrt(S) i^(2/3)))^(3/5),
/// the equilibrium depth at the lower end H_0 = (i L n / sqrt(S))^(3/5), and the kinematic wave
/// number k = S L / (H_0 F_0^2) = g n^2 L / H_0^(4/3) (F_0^2 = u_0^2 / (g H_0), u_0 Manning's).
struct RainPlane {
  static constexpr double L = 100.0, B = 2.0;                  // [m]
  static constexpr double S = 0.01;                            // [-]
  static constexpr double n = 0.03;                            // [s m^-1/3]
  static constexpr double i_mm_h = 100.0;                      // [mm/h]
  static double i() { return i_mm_h * millimetres_per_hour; }  // [m/s]
  static double t_e() {                                        // [s]
    return std::pow(n * L / (std::sqrt(S) * std::pow(i(), 2.0 / 3.0)), 0.6);
  }
  static double H_0() { return std::pow(i() * L * n / std::sqrt(S), 0.6); }  // [m]
  static double kinematic_number() { return gravity * n * n * L / std::pow(H_0(), 4.0 / 3.0); }
  /// The mean of q over [t0, t1] [m^2/s]: int q = i L t_e (3/8) (t/t_e)^(8/3) up to t_e.
  static double q_mean(double t0, double t1) {
    const auto integral = [](double t) {
      const double te = t_e();
      return t <= te ? i() * L * te * 0.375 * std::pow(t / te, 8.0 / 3.0)
                     : i() * L * (0.375 * te + (t - te));
    };
    return (integral(t1) - integral(t0)) / (t1 - t0);
  }
};

/// What one run of the rain plane measures: the outflow over a coupling step against the
/// kinematic wave's mean over it, at t_e / 2, 3 t_e / 4 and t_e, and against i L B at 3 t_e;
/// and at t_e / 2 the largest relative error of the depth and of the unit discharge over the
/// plateau x in [60, 95] m, where the kinematic wave has h = i t and Manning's q(h).
struct RainPlaneRun {
  int cells;
  double kinematic_number, t_e;                                           // [-], [s]
  double ratio_half, ratio_three_quarters, ratio_t_e, ratio_equilibrium;  // [-]
  double plateau_depth, plateau_discharge;                                // [-]
  double balance;                                                         // [-]
  double seconds;
};

/// The largest relative errors of h against i t and of hu against Manning's q(i t) over the
/// cells with x in [60, 95] m at time t [s] (before t_e / 2^(3/5), when all of them are on the
/// kinematic wave's plateau).
inline std::pair<double, double> rain_plateau_errors(const FvEngine& engine, double t) {
  using P = RainPlane;
  const double h = P::i() * t, q = std::sqrt(P::S) / P::n * std::pow(h, 5.0 / 3.0);
  const CellMesh& cells = engine.solver().cells();
  const ConservedState& U = engine.solver().state();
  double depth = 0.0, discharge = 0.0;
  for (int k = 0; k < cells.cell_count; ++k) {
    const double x = cells.centroid[k].x();
    if (x < 60.0 || x > 95.0) continue;
    depth = std::max(depth, std::abs(U.h[k] - h) / h);
    discharge = std::max(discharge, std::abs(U.hu[k] - q) / q);
  }
  return {depth, discharge};
}

/// The rain plane's lower end: `free` (transmissive), or an overfall: an elevation boundary far
/// below the bed, where the water leaves at critical depth (docs/model.md "Boundaries").
enum class RainPlaneOutlet { free, overfall };

/// `nx` x 1 rectangles of two triangles along the plane; coupling steps of t_e / 200.
inline RainPlaneRun run_rain_plane(int nx, RainPlaneOutlet outlet_kind = RainPlaneOutlet::free) {
  using P = RainPlane;
  const Stopwatch clock;
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, P::L, P::B, nx, 1, true});
  Case c = fv_case({"left", "bottom", "top"});
  if (outlet_kind == RainPlaneOutlet::free)
    c.flow.boundaries.push_back({BoundaryCondition::Kind::free, "right", {}, {}});
  else
    c.flow.boundaries.push_back(
        {BoundaryCondition::Kind::elevation, "right", TimeSeries(-P::S * P::L - 5.0), {}});
  c.bed.kind = BedConfig::Kind::slope;
  c.bed.slope = Vec2(P::S, 0.0);
  c.flow.friction = FrictionLaw::manning;
  c.flow.friction_coefficient = P::n;
  c.flow.initial_eta_start = c.flow.initial_eta_end = -10.0;  // below the bed: dry
  c.flow.rain.enabled = true;
  c.flow.rain.intensity = TimeSeries(P::i_mm_h);
  FvEngine engine(mesh, c);
  engine.initialize();
  const int outlet = mesh.find_group("right");
  const double dt = P::t_e() / 200.0;
  RainPlaneRun r{};
  r.cells = engine.solver().cells().cell_count;
  r.kinematic_number = P::kinematic_number();
  r.t_e = P::t_e();
  for (int k = 1; k <= 600; ++k) {
    const double out_before = engine.water_balance().group_outflow[outlet];
    engine.step(dt);
    const double Q = (engine.water_balance().group_outflow[outlet] - out_before) / dt;  // [m^3/s]
    const double ratio = Q / (P::B * P::q_mean((k - 1) * dt, k * dt));
    if (k == 100) {
      r.ratio_half = ratio;
      std::tie(r.plateau_depth, r.plateau_discharge) = rain_plateau_errors(engine, engine.time());
    }
    if (k == 150) r.ratio_three_quarters = ratio;
    if (k == 200) r.ratio_t_e = ratio;
    if (k == 600) r.ratio_equilibrium = Q / (P::i() * P::L * P::B);
  }
  r.balance = engine.water_balance().relative_error();
  r.seconds = clock.seconds();
  return r;
}

}  // namespace flotsam::test
