#include "flow/fem/fem_engine.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "core/error.hpp"
#include "flow/friction_map.hpp"
#include "io/binary_archive.hpp"
#include "io/vtu_writer.hpp"

namespace flotsam {

FemEngine::FemEngine(const Mesh& mesh, const Case& flow_case)
    : solver_(mesh, flow_case), field_(solver_) {}

void FemEngine::initialize() {
  solver_.initialize();
  field_.pack_states();
}

void FemEngine::step(double dt) {
  solver_.step(dt);
  field_.pack_states();
}

// Frozen mode's flow: the steady solve, or when it does not converge (a flow with no steady
// state at its viscosity, whose continuation stops short of it) or time.steady_method is march,
// a march in time from the initial state until the flow stops changing. The state found becomes
// the flow at t = 0, at rest in time.
void FemEngine::settle(const TimeConfig& time) {
  const double viscosity = solver_.flow_case().flow.viscosity;
  if (time.steady_method == SteadyMethod::solve) {
    const SteadyReport steady = solver_.solve_steady();
    if (steady.converged) {
      spdlog::info("steady flow: residual {:.3g} after {} iterations", steady.residuals.back(),
                   steady.iterations);
      field_.pack_states();
      return;
    }
    spdlog::info(
        "the steady solve stopped at residual {:.3g} after {} iterations (lowest viscosity with "
        "a steady state: {:.3g} m^2/s, case: {:.3g} m^2/s); marching in time instead",
        steady.residuals.empty() ? 0.0 : steady.residuals.back(), steady.iterations,
        steady.viscosity, viscosity);
    solver_.initialize();  // from the initial state again, not from where the solve stopped
  }
  spdlog::info("marching in time with {} s steps to the steady state", time.spin_up_step);
  finish_march(solver_.march_to_steady(time.spin_up_step, settled_change, time.spin_up_end),
               solver_.time());
  FlowState steady_state = solver_.state();
  steady_state.time = 0.0;
  solver_.set_state(steady_state);  // previous = current: du/dt = 0
  WaterBalance balance;             // the frozen run's balance starts here
  balance.initial_volume = balance.volume = solver_.volume();
  balance.group_outflow.assign(mesh().group_names.size(), 0.0);
  balance.group_rate.assign(mesh().group_names.size(), 0.0);
  solver_.restore_water_balance(balance);
  field_.pack_states();
}

void FemEngine::write_fields(const std::string& path, double t) const {
  const Mesh& mesh = solver_.mesh();
  const std::vector<double> H = solver_.depth(), vorticity = solver_.vorticity(),
                            nu_t = solver_.eddy_viscosity();  // the fields hold views of these
  std::vector<Vec2> u(mesh.node_count());
  std::vector<double> speed(mesh.node_count());
  for (int n = 0; n < mesh.node_count(); ++n) {
    u[n] = Vec2(solver_.u()[n], solver_.v()[n]);
    speed[n] = u[n].norm();
  }
  VtuFields fields;
  fields.add_p1_scalar("eta [m]", solver_.eta());
  fields.add_point_scalar("H [m]", H);
  fields.add_point_scalar("z_b [m]", solver_.bed());
  fields.add_point_vector("u [m/s]", u);
  fields.add_point_scalar("|u| [m/s]", speed);
  fields.add_point_scalar("vorticity [1/s]", vorticity);
  fields.add_cell_scalar("nu_t [m^2/s]", nu_t);
  const FlowConfig& flow = solver_.flow_case().flow;
  if (!flow.friction_map.empty() && !solver_.friction_coefficients().empty())
    fields.add_cell_scalar(friction_field_name(flow.friction), solver_.friction_coefficients());
  write_vtu(path, mesh, fields, t);
}

namespace {

void write_state(ArchiveWriter& w, const std::string& prefix, const FlowState& s) {
  w.write_value(prefix + ".time", s.time);
  w.write(prefix + ".eta", s.eta);
  w.write(prefix + ".u", s.u);
  w.write(prefix + ".v", s.v);
}

FlowState read_state(ArchiveReader& r, const std::string& prefix, const ShallowWaterSolver& flow) {
  FlowState s;
  s.time = r.read_value<double>(prefix + ".time");
  s.eta = r.read<double>(prefix + ".eta");
  s.u = r.read<double>(prefix + ".u");
  s.v = r.read<double>(prefix + ".v");
  if (s.eta.size() != flow.eta().size() || s.u.size() != flow.u().size())
    throw_input_error(
        "{}: the checkpoint's flow has {} vertices and {} nodes, the case's mesh "
        "{} and {}: the case or its mesh changed since the run",
        r.path(), s.eta.size(), s.u.size(), flow.eta().size(), flow.u().size());
  return s;
}

}  // namespace

// The flow's state and the one a step before it (BDF2's history), and its water balance.
void FemEngine::save(ArchiveWriter& w, const std::string& prefix) const {
  const WaterBalance& b = solver_.water_balance();
  write_state(w, prefix, solver_.state());
  write_state(w, prefix + ".previous", solver_.previous_state());
  write_water_balance(w, prefix, b);
}

void FemEngine::restore(ArchiveReader& r, const std::string& prefix) {
  const FlowState s = read_state(r, prefix, solver_),
                  previous = read_state(r, prefix + ".previous", solver_);
  solver_.set_state(s, &previous);
  solver_.restore_water_balance(read_water_balance(r, prefix));
  field_.pack_states();
}

// The FEM's self-check: how much the last step changed the flow. With steady boundaries a flow
// that settles shows 1e-6 or less; one that does not (a drifting or chaotic state, or real
// unsteadiness such as eddies shed by a pier) shows it here (docs/model.md "Reading the summary").
std::string FemEngine::summary() const {
  const Case& c = solver_.flow_case();
  const std::string change = c.time.mode == CouplingMode::frozen
                                 ? std::string("the flow is frozen at its steady state")
                                 : fmt::format("the last step changed u by {:.2g} of its largest",
                                               solver_.last_step_change());
  return fmt::format("finite elements  {} elements, {} nodes; {}\n", mesh().element_count(),
                     mesh().node_count(), change);
}

}  // namespace flotsam
