#pragma once
// Jam statistics (spec 6.3) at one output time: which bodies touch each solid boundary, the jams
// (connected clusters of touching bodies anchored on a solid boundary) with their blockage of
// the gaps of a bridge, and the fate of the bodies released so far (passed, trapped,
// deposited, floating, left). Every definition is stated in docs/model.md, "Jam statistics".
//
// The geometry the statistics need (which boundary groups are banks and piers, and the bridges
// with their gaps, bridges/bridge.hpp) is set up once per run in a JamGeometry; the statistics
// themselves are a pure function of the bodies and the contact report of the last contact solve.
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "bodies/body_set.hpp"
#include "bridges/bridge.hpp"
#include "bridges/bridge_config.hpp"
#include "contact/contact_report.hpp"
#include "io/csv_writer.hpp"
#include "mesh/geometry.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

enum class SolidKind : std::uint8_t { bank, pier, wall, deck };

/// A solid boundary group whose contacts are counted.
struct SolidGroup {
  int group = -1;  // index into JamGeometry::group_names (= Mesh::group_names = contact groups)
  std::string name;
  SolidKind kind = SolidKind::wall;
  int bridge = -1;  // a pier or a deck: its bridge (index into JamGeometry::bridges); else -1
};

struct JamGeometry {
  std::vector<std::string> group_names;  // every boundary group, then the decks' faces
                                         // ("<bridge>_deck"), for naming a jam's anchors
  std::vector<SolidGroup> solids;        // the groups whose touching bodies are counted
  std::vector<Bridge> bridges;           // empty for a case without bridges

  /// True when p lies beyond every bridge downstream (Bridge::passed); false without bridges.
  bool passed_every_bridge(const Vec2& p) const {
    if (bridges.empty()) return false;
    for (const Bridge& b : bridges)
      if (!b.passed(p)) return false;
    return true;
  }
};

/// The channel of spec 8.2 (mesh/geometry.hpp): solids bank_right (y = 0), bank_left
/// (y = width), pier_1 .. pier_N, and a bridge per line of piers (bridges/bridge_layout.hpp).
/// `group_names` are the mesh's boundary groups; a missing bank or pier group is an InputError
/// naming `source` (the mesh) and the group.
JamGeometry jam_geometry_from_channel(const ChannelGeometry& channel,
                                      const std::vector<std::string>& group_names,
                                      const std::string& source);
JamGeometry jam_geometry_from_channel(const ChannelGeometry& channel, const Mesh& mesh);

/// Any other mesh: the given solid groups (Mesh::group_names indices), kind from the name
/// ("pier*" pier, "bank*" bank, else wall), and the case's bridges on the mesh
/// (bridges_on_mesh); a pier of a bridge is a pier whatever its name. Each deck's face is a
/// solid of its own, "<bridge>_deck", in a group after the mesh's (Bridge::deck_group).
JamGeometry jam_geometry_from_groups(const Mesh& mesh, const std::vector<int>& solid_groups,
                                     const std::vector<BridgeConfig>& bridges = {});

/// The geometry for a case's mesh: from the channel when the mesh was generated from one,
/// else from `solid_groups` and the case's `bridges`.
JamGeometry jam_geometry_for(const MeshSource& source, const Mesh& mesh,
                             const std::vector<int>& solid_groups,
                             const std::vector<BridgeConfig>& bridges = {});

/// A connected cluster of touching bodies anchored on at least one solid boundary.
struct Jam {
  std::vector<int> bodies;           // body indices, ascending
  std::vector<int> anchors;          // boundary groups touched (group_names indices), ascending
  int bridge = -1;                   // the bridge it sits at, -1: none
  std::vector<double> gap_blockage;  // [-] per gap of that bridge (empty when bridge = -1)
  double thickness = 0.0;            // [m] its vertical extent: its bodies' largest wetted
                                     // height (their draft, or (M-J1); coupling/jam_extent.hpp)
  std::vector<double> gap_opening_closed;  // [-] per gap: share of the opening's area closed
                                           // (measure_opening_closure; empty until measured)
  int body_count() const { return static_cast<int>(bodies.size()); }
};

struct JamStatistics {
  std::vector<int> touching;            // per JamGeometry::solids: bodies touching it directly
  std::vector<int> anchored;            // per JamGeometry::solids: bodies in jams anchored on it
  std::vector<Jam> jams;                // ordered by their smallest body index
  std::vector<double> bridge_blockage;  // [-] per bridge: covered span over total gap width
  std::vector<double> bridge_opening_closed;  // [-] per bridge: closed share of the openings'
                                              // area (measure_opening_closure; else empty)
  int released = 0;                           // bodies in the set (every body released so far)
  int passed = 0;           // G beyond every bridge (gone or not); no bridges: gone bodies
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

/// The intervals [s_G - h_s, s_G + h_s] along `bridge`'s axis of the footprints of `members`
/// [m] (h_s: footprint_half_extent_along the axis).
std::vector<std::pair<double, double>> axis_spans(const BodySet& bodies,
                                                  const std::vector<int>& members,
                                                  const Bridge& bridge);

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
  /// largest jam, blockage <bridge> [-]..., opening closed <bridge> [-]..., backwater rise <bridge>
  /// [m]..., touching <group>..., anchored <group>...
  static std::vector<std::string> columns(const JamGeometry& geometry, bool with_backwater);

 private:
  CsvWriter csv_;
  bool with_backwater_;
  std::size_t bridge_count_;
};

/// The end-of-run summary: the counts, one line per bridge (axis centre, gaps, blockage, share of
/// the opening closed, backwater rise when `backwater_rise` is given), one per jam (with its
/// thickness) and one per solid group, in aligned columns.
std::string format_jam_summary(const JamStatistics& statistics, const JamGeometry& geometry,
                               std::span<const double> backwater_rise = {});

}  // namespace flotsam
