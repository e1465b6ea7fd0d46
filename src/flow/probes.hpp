#pragma once
// Gauges (output.probes, issue 15 item 4): the flow sampled at fixed points, one CSV row per
// call, `<name>_probes.csv` (docs/output-format.md). Works with any engine through FlowField.
//
//   t [s], then per probe: <name>_eta [m], <name>_H [m], <name>_u [m/s], <name>_v [m/s]
//
// A dry point writes H = 0, the eta the engine returns there (the bed level) and u = v = 0.
#include <string>
#include <vector>

#include "flow/flow_field.hpp"
#include "io/case.hpp"
#include "io/csv_writer.hpp"

namespace flotsam {

/// Checks that every probe lies inside the domain (sampled at field.time_end()): one outside is an
/// InputError naming `case_file`, the probe's line, name and position. A run calls it before it
/// writes anything, so that a bad gauge leaves no output behind.
void check_probes_inside(const std::vector<Probe>& probes, const FlowField& field,
                         const std::string& case_file);

class ProbeWriter {
 public:
  /// Callers construct a ProbeWriter only when the case has probes (no probes: no file).
  /// Checks that every probe lies inside the domain, sampled at field.time_end(); one outside is
  /// an InputError naming `case_file`, the probe's line, name and position. Creates `csv_path`
  /// with its header, or with `resume` (a restarted run) continues it from the checkpoint's time
  /// (io/csv_writer.hpp CsvResume).
  /// Keeps a reference to `field`, which must outlive the writer.
  ProbeWriter(const std::string& csv_path, const std::vector<Probe>& probes, const FlowField& field,
              const std::string& case_file, std::optional<CsvResume> resume);

  /// Samples every probe at t, which must lie in the field's current step
  /// [time_begin(), time_end()], and appends one row.
  void write(double t);

  std::size_t probe_count() const { return positions_.size(); }
  const std::string& path() const { return csv_.path(); }

 private:
  const FlowField& field_;
  std::vector<Vec2> positions_;  // [m]
  std::vector<int> hints_;       // element hint per probe, kept between calls
  std::vector<double> row_;      // t, then eta, H, u, v per probe
  CsvWriter csv_;
};

}  // namespace flotsam
