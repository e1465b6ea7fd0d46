#include "coupling/run_output.hpp"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <fstream>

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
      shared_folder_(shared_folder) {
  const auto write_boundary = [&](const std::string& path) { write_boundary_vtp(path, mesh); };
  if (shared_folder_.empty())
    write_boundary((directory_ / "boundary.vtp").string());
  else
    write_shared_file(shared_folder_, "boundary.vtp", directory_ / "boundary.vtp", write_boundary);
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
      resume_(CsvResume{resume_time}) {
  for (std::size_t k = 0; k < times_.size(); ++k) {
    flow_index_.add(times_[k], fmt::format("flow_{:06d}.vtu", k));
    if (with_bodies) body_index_.add(times_[k], fmt::format("bodies_{:06d}.vtp", k));
  }
  balance_ = std::make_unique<CsvWriter>((directory_ / (name + "_balance.csv")).string(),
                                         balance_columns(mesh), resume_);
}

void RunOutput::write(double t, const FlowEngine& flow, const BodySet& bodies, bool with_bodies,
                      const std::vector<std::uint8_t>& jammed) {
  const std::string file = fmt::format("flow_{:06d}.vtu", count());
  const auto write_fields = [&](const std::string& path) { flow.write_fields(path, t); };
  if (shared_folder_.empty())
    write_fields((directory_ / file).string());
  else  // the time's bits name it: the fields of one shared flow depend on the time alone
    write_shared_file(shared_folder_,
                      fmt::format("flow_at_{:016x}.vtu", std::bit_cast<std::uint64_t>(t)),
                      directory_ / file, write_fields);
  flow_index_.add(t, file);
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

void RunOutput::write_bodies(const BodySet& bodies, double t) {
  const std::string file = fmt::format("bodies_{:06d}.vtp", count());
  BodyFields extra;
  extra.add_vector("drag [N]", bodies.drag_force);
  extra.add_vector("bed force [N]", bodies.bed_force);
  extra.add_vector("reaction [N]", bodies.reaction_force);
  extra.add_scalar("torque [N m]", bodies.torque);
  write_bodies_vtp((directory_ / file).string(), bodies, extra, t);
  body_index_.add(t, file);
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
                           const std::vector<double>& rise, bool with_backwater) {
  if (!jams_)
    jams_ = std::make_unique<JamStatisticsWriter>((directory_ / (name_ + "_jams.csv")).string(),
                                                  geometry, with_backwater, resume_);
  jams_->write(t, stats, rise);
}

}  // namespace flotsam
