#pragma once
// A bridge as the case file gives it (docs/case-format.md "bridges"): a name, an axis across the
// river from its right bank to its left bank (looking downstream, so that downstream is on the
// axis' right), and the piers it stands on. The bridge on the mesh (gaps, reach, sections) is
// bridges/bridge.hpp; building one from this is bridges/bridge_layout.hpp.
#include <optional>
#include <string>
#include <vector>

#include "core/vec.hpp"

namespace flotsam {

/// A bridge's deck (docs/model.md "Decks"): a slab from the soffit (low chord) to the deck top
/// (high chord), `width` along the flow, centred on the axis, with a railing on top. It spans
/// the whole axis, abutment to abutment.
struct DeckConfig {
  double soffit = 0.0;          // [m] z of the deck's underside
  double top = 0.0;             // [m] z of the deck's road surface, > soffit
  double width = 0.0;           // [m] along the flow, > 0
  double railing_height = 0.0;  // [m] above the top; 0: none
  bool railing_open = true;     // water passes through the railing (floating bodies do not)

  /// [m] z of the highest point that stops a floating body: the railing's top.
  double obstacle_top() const { return top + railing_height; }
  /// [m] z of what the water overtops: the top, or a solid railing's top.
  double crest() const { return railing_open ? top : obstacle_top(); }
};

struct BridgeConfig {
  std::string name;
  Vec2 start = Vec2::Zero();  // [m] the axis' end on the right bank
  Vec2 end = Vec2::Zero();    // [m] the axis' end on the left bank
  // Boundary groups the case names as this bridge's piers (its own circles, meshed by
  // mesh.region, or a mesh file's groups): each must meet the axis. Any other pier the axis
  // crosses belongs to the bridge as well.
  std::vector<std::string> pier_groups;
  std::optional<DeckConfig> deck;   // none: only its piers stand in the water
  double backwater_distance = 0.0;  // [m] upstream of the axis; 0: twice the structure's reach
                                    // (two diameters of its widest pier without a deck)
  std::string origin;  // "case.yaml:40: bridges[0]" or "town.gpkg, layer 'bridges', feature 1"

  /// The unit vector from start to end, and downstream: it turned a quarter turn clockwise.
  Vec2 along() const { return (end - start).normalized(); }
  Vec2 downstream() const { return {along().y(), -along().x()}; }
};

}  // namespace flotsam
