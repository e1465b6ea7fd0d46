#pragma once
// Jam statistics (spec 6.3) at one output time: which bodies touch each solid boundary, the jams
// (connected clusters of touching bodies anchored on a solid boundary) with their blockage of
// the gaps of a bridge line, and the fate of the bodies released so far (passed, trapped,
// deposited, floating, left). Every definition is stated in docs/model.md, "Jam statistics".
//
// The geometry the statistics need (which boundary groups are banks and piers, how the piers
// form bridge lines across the channel, and the free gaps of each line) is set up once per run
// in a JamGeometry; the statistics themselves are a pure function of the bodies and the contact
// report of the last contact solve.
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "bodies/body_set.hpp"
#include "contact/contact_report.hpp"
#include "io/csv_writer.hpp"
#include "mesh/geometry.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

enum class SolidKind : std::uint8_t { bank, pier, wall };

/// A solid boundary group whose contacts are counted.
struct SolidGroup {
  int group = -1;  // index into JamGeometry::group_names (= Mesh::group_names = contact groups)
  std::string name;
  SolidKind kind = SolidKind::wall;
  int bridge = -1;  // a pier: its bridge line (index into JamGeometry::bridges); else -1
};

/// The free water between two consecutive solid obstacles of a bridge line, across the channel.
struct Gap {
  double y_lower = 0.0;  // [m]
  double y_upper = 0.0;  // [m]
  int lower_solid = -1;  // the obstacle at y_lower (index into JamGeometry::solids)
  int upper_solid = -1;  // the obstacle at y_upper
  double width() const { return y_upper - y_lower; }  // [m]
};

/// Piers standing in one line across the channel (a bridge).
struct BridgeLine {
  std::string name;         // "bridge_1", "bridge_2", ... numbered downstream (x ascending)
  double x = 0.0;           // [m] mean x of its piers' centres
  double max_radius = 0.0;  // [m] its largest pier radius
  std::vector<int> piers;   // indices into JamGeometry::solids, y ascending
  std::vector<Gap> gaps;    // y ascending: bank_right - pier - ... - pier - bank_left
};

struct JamGeometry {
  std::vector<std::string> group_names;  // every boundary group, for naming a jam's anchors
  std::vector<SolidGroup> solids;        // the groups whose touching bodies are counted
  std::vector<BridgeLine> bridges;       // x ascending; empty for a mesh without bridges
  double y_lower = 0.0;                  // [m] the channel's right bank (bridges only)
  double y_upper = 0.0;                  // [m] the channel's left bank (bridges only)

  /// [m] x beyond which a body has passed every bridge: last bridge x + its max_radius
  /// (infinity without bridges).
  double passed_x() const {
    return bridges.empty() ? std::numeric_limits<double>::infinity()
                           : bridges.back().x + bridges.back().max_radius;
  }
};

/// The channel of spec 8.2 (mesh/geometry.hpp): solids bank_right (y = 0), bank_left
/// (y = width), pier_1 .. pier_N; piers grouped into bridge lines by x (two piers whose centre x
/// differ by less than the smaller radius stand in one line, and lines chain), and each line's
/// gaps between consecutive obstacles. `group_names` are the mesh's boundary groups; a missing
/// bank or pier group is an InputError naming `source` (the mesh) and the group.
JamGeometry jam_geometry_from_channel(const ChannelGeometry& channel,
                                      const std::vector<std::string>& group_names,
                                      const std::string& source);
JamGeometry jam_geometry_from_channel(const ChannelGeometry& channel, const Mesh& mesh);

/// Any other mesh: the given solid groups (Mesh::group_names indices), kind from the name
/// ("pier*" pier, "bank*" bank, else wall), no bridge lines: touching counts and jams only.
JamGeometry jam_geometry_from_groups(const Mesh& mesh, const std::vector<int>& solid_groups);

/// The geometry for a case's mesh: from the channel when the mesh was generated from one,
/// else from `solid_groups`.
JamGeometry jam_geometry_for(const MeshSource& source, const Mesh& mesh,
                             const std::vector<int>& solid_groups);

/// A connected cluster of touching bodies anchored on at least one solid boundary.
struct Jam {
  std::vector<int> bodies;           // body indices, ascending
  std::vector<int> anchors;          // boundary groups touched (group_names indices), ascending
  int bridge = -1;                   // the bridge line it sits at, -1: none
  std::vector<double> gap_blockage;  // [-] per gap of that bridge (empty when bridge = -1)
  int body_count() const { return static_cast<int>(bodies.size()); }
};

struct JamStatistics {
  std::vector<int> touching;            // per JamGeometry::solids: bodies touching it directly
  std::vector<int> anchored;            // per JamGeometry::solids: bodies in jams anchored on it
  std::vector<Jam> jams;                // ordered by their smallest body index
  std::vector<double> bridge_blockage;  // [-] per bridge: covered span over total gap width
  int released = 0;                     // bodies in the set (every body released so far)
  int passed = 0;           // G beyond passed_x() (gone or not); no bridges: gone bodies
  int left = 0;             // BodySet::outflow_count: gone through an outflow boundary
  int trapped = 0;          // in a jam
  int deposited = 0;        // grounded, not in a jam
  int floating = 0;         // floating, not in a jam
  int largest_jam() const;  // body count of the largest jam, 0 when there is none
};

/// The statistics of the bodies' current state; `report` is the contact report of the last
/// contact solve (bodies added after it, report.body_count <= bodies.size(), touch nothing).
JamStatistics compute_jam_statistics(const BodySet& bodies, const ContactReport& report,
                                     const JamGeometry& geometry);

/// Length of [lower, upper] covered by the union of `intervals` (each (lo, hi) [m]) [m].
double covered_length(std::vector<std::pair<double, double>> intervals, double lower, double upper);

/// Half the extent of body i's footprint (rotated rectangle) along x and along y [m].
Vec2 footprint_half_extent(const BodySet& bodies, int i);

/// `<name>_jams.csv` (docs/output-format.md): one row per output time. The backwater columns
/// are there only when the run has a reference flow without bodies (`with_backwater`).
class JamStatisticsWriter {
 public:
  /// `resume`: continue the file of a restarted run from its checkpoint's time (CsvResume).
  JamStatisticsWriter(const std::string& path, const JamGeometry& geometry, bool with_backwater,
                      std::optional<CsvResume> resume = std::nullopt);

  /// One row at time t [s]; `backwater_rise` [m] has one value per bridge when the writer was
  /// made with_backwater (else it must be empty): std::invalid_argument otherwise.
  void write(double t, const JamStatistics& statistics,
             std::span<const double> backwater_rise = {});

  /// The header: time [s], released, passed, left, trapped, deposited, floating, jams,
  /// largest jam, blockage <bridge> [-]..., backwater rise <bridge> [m]..., touching <group>...,
  /// anchored <group>...
  static std::vector<std::string> columns(const JamGeometry& geometry, bool with_backwater);

 private:
  CsvWriter csv_;
  bool with_backwater_;
  std::size_t bridge_count_;
};

/// The end-of-run summary: the counts, one line per bridge (x, gaps, blockage, backwater rise
/// when `backwater_rise` is given), one per jam and one per solid group, in aligned columns.
std::string format_jam_summary(const JamStatistics& statistics, const JamGeometry& geometry,
                               std::span<const double> backwater_rise = {});

}  // namespace flotsam
