#pragma once
// What one picture shows (docs/rendering.md): a field coloured over the mesh, the banks and the
// piers, the bodies coloured by category, optional velocity arrows, a colour bar, title, time
// stamp and scale bar. A Scene holds its own copies of the values (a frame is drawn long after
// the step that made it may have moved on); only the mesh is referenced.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "io/case.hpp"
#include "mesh/mesh.hpp"
#include "render/colour_map.hpp"

namespace flotsam {

/// How a body is drawn. `jammed` is the caller's (jam statistics, spec 6.3): a body in a
/// cluster of touching bodies anchored on a solid boundary.
enum class BodyCategory : std::uint8_t { floating, grounded, jammed, gone };

/// The bodies as drawn, one entry per body (structure of arrays, as BodySet).
struct SceneBodies {
  std::vector<Vec2> position;  // x_G [m]
  std::vector<double> angle;   // theta [rad], long axis from the x axis
  std::vector<double> length;  // L [m]
  std::vector<double> width;   // l [m]
  std::vector<BodyCategory> category;

  int size() const { return static_cast<int>(position.size()); }
  void add(const Vec2& x_G, double theta, double L, double l, BodyCategory category_of_body);
};

/// The bodies of a BodySet: floating / grounded / gone from their state; jammed[i] != 0 turns a
/// body that is not gone into `jammed` (empty span: nobody is jammed).
SceneBodies scene_bodies(const BodySet& bodies, std::span<const std::uint8_t> jammed = {});

/// One scalar field over the mesh: P1 (Mesh::vertex_count values) or P2 (Mesh::node_count()
/// values), vertex-first numbering. NaN marks a node without a value (drawn no_data_colour).
struct ScalarField {
  std::string name;  // shown on the colour bar: "eta", "|u|", "vorticity"
  std::string unit;  // "m", "m/s", "1/s"
  std::vector<double> values;
};

/// The values the colour map's ends stand for.
struct ColourRange {
  enum class Kind : std::uint8_t {
    data,       // [min, max] of the field over the nodes inside the view window
    symmetric,  // [-m, m], m = max |field| over the same nodes (signed fields)
    fixed       // [min, max] below (a series of frames with one colour bar)
  } kind = Kind::data;
  double min = 0.0;  // [field unit], kind == fixed
  double max = 1.0;  // [field unit], kind == fixed
};

/// A world rectangle [m].
struct ViewWindow {
  double x_min = 0.0, x_max = 1.0;  // [m]
  double y_min = 0.0, y_max = 1.0;  // [m]
};

/// How a boundary group is drawn: walls as thick dark grey lines, open boundaries (inflow,
/// outflow) as dashed blue lines. Holes in the mesh (piers, islands) are filled grey whatever
/// their kind.
enum class BoundaryKind : std::uint8_t { wall, open };

struct Scene {
  const Mesh* mesh = nullptr;  // must outlive the drawing

  ScalarField field;
  std::vector<std::uint8_t> wet;  // per mesh node: 1 wet, 0 dry (drawn as land); empty: all wet
  ColourMapName colour_map = ColourMapName::viridis;
  ColourRange range;

  // Velocity arrows, sampled on a regular grid of the picture; empty: no arrows.
  std::vector<double> u_x;             // [m/s] P2 (node_count() values)
  std::vector<double> u_y;             // [m/s] P2
  double arrow_spacing = 40.0;         // [px] between sample points
  double arrow_reference_speed = 0.0;  // [m/s] drawn one spacing long; 0: the largest sampled

  SceneBodies bodies;

  std::optional<double> time;  // [s] shown as h:mm:ss; none: no time stamp
  std::string title;

  int width = 1600;  // [px]
  int height = 400;  // [px]
  // [m] the region to show; none: the mesh's bounding box with a 3% margin. Either way the
  // window grows along one axis to the picture's aspect ratio (one scale in x and y).
  std::optional<ViewWindow> view;

  // Per Mesh::group_names entry; empty: by name (default_boundary_kind).
  std::vector<BoundaryKind> boundary_kinds;
  // Bridge decks' footprints [m] (corners in order), drawn translucent over the water so that
  // what floats against and under them stays visible; empty: none.
  std::vector<std::array<Vec2, 4>> decks;
};

/// Open when the name contains "inflow", "outflow", "inlet", "outlet" or "open"; else wall.
BoundaryKind default_boundary_kind(const std::string& group_name);

/// Per mesh group from the flow's boundary conditions: elevation, discharge and velocity are
/// open, wall and noslip are walls; a group without a condition by its name.
std::vector<BoundaryKind> boundary_kinds(const Mesh& mesh,
                                         std::span<const BoundaryCondition> conditions);

/// The mesh's bounding box [m].
ViewWindow bounding_box(const Mesh& mesh);

/// The colour map's ends [field unit] for the scene (ColourRange), widened when degenerate:
/// a constant field c gets [c - d, c + d], d = 0.05 |c|, or 1 when c = 0.
std::pair<double, double> resolve_colour_range(const Scene& scene, const ViewWindow& window);

/// "h:mm:ss" of a time [s], rounded to the second; "-h:mm:ss" before zero.
std::string format_clock(double seconds);

/// Throws InputError naming the scene's title and field and what was expected when the mesh is
/// missing, an array has the wrong length, the size or the view window is unusable.
void validate_scene(const Scene& scene);

}  // namespace flotsam
