#include "coupling/run_output.hpp"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>

#include "core/error.hpp"
#include "io/output_directory.hpp"
#include "io/run_state.hpp"
#include "io/shared_file.hpp"
#include "io/vtk_writer.hpp"

namespace flotsam {

RunOutput::RunOutput(const std::filesystem::path& directory, const std::string& name,
                     const Mesh& mesh, const RunLayout& layout, bool overwrite,
                     const std::string& case_file, const std::vector<ProtectedInput>& inputs,
                     const std::filesystem::path& shared_folder, PvdWriter::Start indexes)
    : directory_(prepare_output_directory(directory.string(), overwrite, case_file, inputs,
                                          shared_folder)),
      name_(name),
      open_group_(layout.open_group),
      rain_(layout.rain),
      sources_(layout.sources),
      flow_index_((directory_ / (name + ".pvd")).string(), indexes),
      body_index_((directory_ / (name + "_bodies.pvd")).string(), indexes),
      shared_folder_(shared_folder),
      formats_(layout.formats),
      crs_wkt_(layout.crs_wkt),
      time_origin_(layout.time_origin) {
  const auto write_boundary = [&](const std::string& path) { write_boundary_vtp(path, mesh); };
  if (formats_.vtk) {
    if (shared_folder_.empty())
      write_boundary((directory_ / "boundary.vtp").string());
    else
      write_shared_file(shared_folder_, "boundary.vtp", directory_ / "boundary.vtp",
                        write_boundary);
  }
  write_run_description((directory_ / "run.bin").string(), {name, mesh, open_group_, layout.decks});
  balance_ = std::make_unique<CsvWriter>((directory_ / (name + "_balance.csv")).string(),
                                         balance_columns(mesh));
}

// The balance table's columns: the totals (with the rain and the infiltration when it rains, the
// sources' volume when there are sources),
// then the volume that has left through each open boundary group since the start (negative:
// entered), whose differences give mean discharges.
std::vector<std::string> RunOutput::balance_columns(const Mesh& mesh) const {
  std::vector<std::string> columns = {"t [s]", "volume [m^3]", "outflow [m^3]"};
  if (rain_) columns.insert(columns.end(), {"rain [m^3]", "infiltration [m^3]"});
  if (sources_) columns.push_back("sources [m^3]");
  columns.insert(columns.end(), {"balance error [m^3]", "relative error [-]"});
  for (const std::string& group : open_group_names(mesh))
    columns.push_back("outflow " + group + " [m^3]");
  return columns;
}

std::vector<std::string> RunOutput::open_group_names(const Mesh& mesh) const {
  std::vector<std::string> names;
  for (std::size_t g = 0; g < open_group_.size(); ++g)
    if (open_group_[g]) names.push_back(mesh.group_names[g]);
  return names;
}

RunOutput::RunOutput(const std::filesystem::path& directory, const std::string& name,
                     const Mesh& mesh, const RunLayout& layout, const std::vector<double>& times,
                     bool with_bodies, double resume_time)
    : directory_(directory),
      name_(name),
      open_group_(layout.open_group),
      rain_(layout.rain),
      sources_(layout.sources),
      flow_index_((directory_ / (name + ".pvd")).string()),
      body_index_((directory_ / (name + "_bodies.pvd")).string()),
      times_(times),
      resume_(CsvResume{resume_time}),
      formats_(layout.formats),
      crs_wkt_(layout.crs_wkt),
      time_origin_(layout.time_origin) {
  for (std::size_t k = 0; k < times_.size() && formats_.vtk; ++k) {
    flow_index_.add(times_[k], fmt::format("flow_{:06d}.vtu", k));
    if (with_bodies) body_index_.add(times_[k], fmt::format("bodies_{:06d}.vtp", k));
  }
  balance_ = std::make_unique<CsvWriter>((directory_ / (name + "_balance.csv")).string(),
                                         balance_columns(mesh), resume_);
}

void RunOutput::write(double t, const FlowEngine& flow, const BodySet& bodies, bool with_bodies,
                      const std::vector<std::uint8_t>& jammed) {
  if (formats_.vtk) {
    const std::string file = fmt::format("flow_{:06d}.vtu", count());
    const auto write_fields = [&](const std::string& path) { flow.write_fields(path, t); };
    if (shared_folder_.empty())
      write_fields((directory_ / file).string());
    else  // the time's bits name it: the fields of one shared flow depend on the time alone
      write_shared_file(shared_folder_,
                        fmt::format("flow_at_{:016x}.vtu", std::bit_cast<std::uint64_t>(t)),
                        directory_ / file, write_fields);
    flow_index_.add(t, file);
  }
  if (formats_.ugrid) write_ugrid(t, flow);
  if (raster_grid_) flow.write_envelope_rasters((directory_ / name_).string(), *raster_grid_);
  if (with_bodies) write_bodies(bodies, t);
  write_run_snapshot((directory_ / fmt::format("state_{:06d}.bin", count())).string(), t,
                     flow.eta(), flow.u(), flow.v(), flow.wet_nodes(), bodies, jammed);
  const WaterBalance& b = flow.water_balance();
  std::vector<double> row = {t, b.volume, b.outflow};
  if (rain_) row.insert(row.end(), {b.rain, b.infiltration});
  if (sources_) row.push_back(b.sources);
  row.insert(row.end(), {b.error(), b.relative_error()});
  for (std::size_t g = 0; g < open_group_.size(); ++g)
    if (open_group_[g]) row.push_back(b.group_outflow[g]);
  balance_->row(row);
  times_.push_back(t);
}

void RunOutput::close() {
  flow_index_.close();
  body_index_.close();
}

void RunOutput::write_coordinate_system(const std::string& wkt) const {
  std::ofstream crs(directory_ / (name_ + "_crs.wkt"));
  crs << wkt << "\n";
  if (!crs) throw_run_error("could not write '{}'", (directory_ / (name_ + "_crs.wkt")).string());
}

// <name>.nc: the mesh and the variables at the first output (of this run, or of the run a
// restart continues), then a record per output and the static fields rewritten.
void RunOutput::write_ugrid(double t, const FlowEngine& flow) {
  const ResultFields fields = flow.result_fields();
  if (!ugrid_) {
    const ResultMesh faces = flow.result_mesh();
    const UgridMesh mesh{flow.mesh().nodes, faces.faces, faces.node_bed, crs_wkt_, time_origin_};
    const std::string path = (directory_ / (name_ + ".nc")).string();
    ugrid_ = resume_ ? UgridWriter::resume(path, mesh, fields.variables, resume_->time)
                     : UgridWriter(path, mesh, fields.variables, "flotsam run " + name_);
  }
  std::map<std::string, const std::vector<double>*> timed;
  for (std::size_t k = 0; k < fields.variables.size(); ++k)
    if (fields.variables[k].timed)
      timed[fields.variables[k].name] = &fields.values[k];
    else
      ugrid_->set_static(fields.variables[k].name, fields.values[k]);
  ugrid_->append(t, timed);
}

void RunOutput::write_bodies(const BodySet& bodies, double t) {
  if (formats_.vtk) {
    const std::string file = fmt::format("bodies_{:06d}.vtp", count());
    BodyFields extra;
    extra.add_vector("drag [N]", bodies.drag_force);
    extra.add_vector("bed force [N]", bodies.bed_force);
    extra.add_vector("reaction [N]", bodies.reaction_force);
    extra.add_vector("water force [N]", bodies.water_force);
    extra.add_scalar("torque [N m]", bodies.torque);
    write_bodies_vtp((directory_ / file).string(), bodies, extra, t);
    body_index_.add(t, file);
  }
  if (!trajectories_)
    trajectories_ = std::make_unique<CsvWriter>(
        (directory_ / (name_ + "_bodies.csv")).string(),
        std::vector<std::string>{"t [s]", "id", "x [m]", "y [m]", "angle [rad]", "u [m/s]",
                                 "v [m/s]", "omega [rad/s]", "state (0 floating 1 grounded)"},
        resume_);
  for (int i = 0; i < bodies.size(); ++i)
    if (bodies.state[i] != BodyState::gone)
      trajectories_->row({t, static_cast<double>(bodies.id[i]), bodies.position[i].x(),
                          bodies.position[i].y(), bodies.angle[i], bodies.velocity[i].x(),
                          bodies.velocity[i].y(), bodies.angular_velocity[i],
                          static_cast<double>(bodies.state[i])});
}

}  // namespace flotsam

namespace flotsam {

void RunOutput::write_jams(double t, const JamStatistics& stats, const JamGeometry& geometry,
                           const std::vector<double>& rise, bool with_backwater,
                           const BodySet& bodies) {
  if (!jams_)
    jams_ = std::make_unique<JamStatisticsWriter>((directory_ / (name_ + "_jams.csv")).string(),
                                                  geometry, with_backwater, resume_);
  jams_->write(t, stats, rise);
  if (formats_.gpkg) write_debris_layers(t, stats, geometry, bodies);
}

// <name>_debris.gpkg: every body in the domain with its fate (the jam statistics' categories,
// docs/model.md "Jam statistics": trapped in a jam, else passed every bridge, else deposited or
// floating), and every jam with the share of its bridge's free width it covers.
void RunOutput::write_debris_layers(double t, const JamStatistics& stats,
                                    const JamGeometry& geometry, const BodySet& bodies) {
  if (!debris_) {
    const std::string path = (directory_ / (name_ + "_debris.gpkg")).string();
    debris_ = resume_ ? DebrisLayers::resume(path, crs_wkt_, time_origin_, resume_->time)
                      : DebrisLayers(path, crs_wkt_, time_origin_);
  }
  const auto bridge_name = [&](int b) { return b < 0 ? std::string() : geometry.bridges[b].name; };
  std::vector<int> jam_of(bodies.size(), -1);
  std::vector<JamOutline> jams;
  for (int j = 0; j < static_cast<int>(stats.jams.size()); ++j) {
    const Jam& jam = stats.jams[j];
    JamOutline outline{j,
                       {},
                       jam.body_count(),
                       bridge_name(jam.bridge),
                       std::numeric_limits<double>::quiet_NaN(),
                       jam.thickness};
    for (int i : jam.bodies) {
      jam_of[i] = j;
      outline.footprints.push_back(body_corners(bodies, i));
    }
    if (jam.bridge >= 0) {                // covered share of the bridge's free width
      double covered = 0.0, width = 0.0;  // [m]
      const auto& gaps = geometry.bridges[jam.bridge].gaps;
      for (std::size_t g = 0; g < gaps.size(); ++g) {
        covered += jam.gap_blockage[g] * gaps[g].width();
        width += gaps[g].width();
      }
      outline.blockage = width > 0.0 ? covered / width : 0.0;
    }
    jams.push_back(std::move(outline));
  }
  std::vector<TrackPoint> tracks;
  for (int i = 0; i < bodies.size(); ++i) {
    if (bodies.state[i] == BodyState::gone) continue;
    const int j = jam_of[i];
    const bool grounded = bodies.state[i] == BodyState::grounded;
    const char* fate = j >= 0                                             ? "trapped"
                       : geometry.passed_every_bridge(bodies.position[i]) ? "passed"
                       : grounded                                         ? "deposited"
                                                                          : "floating";
    tracks.push_back({bodies.id[i], bodies.position[i], bodies.half_extents(i), bodies.angle[i],
                      bodies.shape[i] == Shape::log ? "log" : "box", bodies.velocity[i].norm(),
                      grounded ? "grounded" : "floating", fate, j,
                      j >= 0 ? bridge_name(stats.jams[j].bridge) : std::string()});
  }
  debris_->write(t, tracks, jams);
}

}  // namespace flotsam
