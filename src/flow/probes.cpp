#include "flow/probes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>

#include "core/error.hpp"

namespace flotsam {

namespace {

std::vector<std::string> probe_columns(const std::vector<Probe>& probes) {
  std::vector<std::string> columns = {"t [s]"};
  for (const Probe& probe : probes) {
    columns.push_back(probe.name + "_eta [m]");
    columns.push_back(probe.name + "_H [m]");
    columns.push_back(probe.name + "_u [m/s]");
    columns.push_back(probe.name + "_v [m/s]");
  }
  return columns;
}

/// "<file>:<line>" as in the case file's other messages; the file alone for a probe built in
/// code (line 0), "case" for a case built in code.
std::string probe_location(const std::string& case_file, const Probe& probe) {
  const std::string file = case_file.empty() ? "case" : case_file;
  return probe.line > 0 ? fmt::format("{}:{}", file, probe.line) : file;
}

/// The element hint of each probe, sampled at field.time_end(); throws InputError for a probe
/// outside the domain. Runs before the CSV file is created, so a bad probe leaves no file.
std::vector<int> locate_probes(const std::vector<Probe>& probes, const FlowField& field,
                               const std::string& case_file) {
  std::vector<int> hints(probes.size(), -1);
  const double t = field.time_end();  // [s]
  for (std::size_t k = 0; k < probes.size(); ++k) {
    const Probe& probe = probes[k];
    if (field.sample(probe.position, t, hints[k]).inside) continue;
    throw_input_error(
        "{}: output.probes: probe '{}' at ({}, {}) m is outside the domain; move it inside "
        "the mesh",
        probe_location(case_file, probe), probe.name, probe.position.x(), probe.position.y());
  }
  return hints;
}

}  // namespace

void check_probes_inside(const std::vector<Probe>& probes, const FlowField& field,
                         const std::string& case_file) {
  locate_probes(probes, field, case_file);
}

ProbeWriter::ProbeWriter(const std::string& csv_path, const std::vector<Probe>& probes,
                         const FlowField& field, const std::string& case_file,
                         std::optional<CsvResume> resume)
    : field_(field),
      hints_(locate_probes(probes, field, case_file)),
      row_(1 + 4 * probes.size(), 0.0),
      csv_(csv_path, probe_columns(probes), resume) {
  assert(!probes.empty() && "callers construct a ProbeWriter only when the case has probes");
  positions_.reserve(probes.size());
  for (const Probe& probe : probes) positions_.push_back(probe.position);
}

void ProbeWriter::write(double t) {
  assert(t >= field_.time_begin() && t <= field_.time_end());
  row_[0] = t;
  for (std::size_t k = 0; k < positions_.size(); ++k) {
    const FlowSample s = field_.sample(positions_[k], t, hints_[k]);
    // A probe checked inside stays inside (the mesh does not move); a dry point has H <= 0.
    const double H = std::max(s.H, 0.0);                // [m]
    const Vec2 u = H > 0.0 ? s.u : Vec2(Vec2::Zero());  // [m/s]
    double* cells = &row_[1 + 4 * k];
    cells[0] = s.eta;
    cells[1] = H;
    cells[2] = u.x();
    cells[3] = u.y();
  }
  csv_.row(row_);
}

}  // namespace flotsam
