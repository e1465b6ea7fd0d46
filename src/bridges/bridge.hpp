#pragma once
// A bridge on the mesh (docs/model.md "Bridges"): its axis as a frame, the piers that stand on
// it and the free gaps between them, and how far its structure reaches along the flow. The jam
// statistics (coupling/jam_statistics.hpp), the backwater sections (coupling/backwater.hpp) and
// the ensembles' blocking criteria ask a Bridge rather than the channel's coordinates.
//
// Frame: s = along . (p - start) runs along the axis from its right-bank end (0) to its
// left-bank end (length()); d = downstream . p grows downstream, downstream being the axis
// turned a quarter turn clockwise (the right of a walker from start to end). On the paper's
// channel (axis from (x, 0) to (x, width)) s is y and d is x, bit for bit.
#include <string>
#include <vector>

#include <optional>

#include "bodies/body_set.hpp"
#include "bridges/bridge_config.hpp"
#include "core/vec.hpp"

namespace flotsam {

/// The free water between two consecutive obstacles along a bridge's axis.
struct Gap {
  double lower = 0.0;    // [m] s where it starts
  double upper = 0.0;    // [m] s where it ends
  int lower_solid = -1;  // the obstacle at `lower` (index into JamGeometry::solids); -1: an
                         // abutment (the axis' end inside the domain) or an open boundary
  int upper_solid = -1;  // the obstacle at `upper`
  double width() const { return upper - lower; }  // [m]
};

struct Bridge {
  std::string name;
  Vec2 start = Vec2::Zero();        // [m] axis end on the right bank
  Vec2 end = Vec2::Zero();          // [m] axis end on the left bank
  Vec2 along = Vec2::UnitY();       // [-] unit vector start -> end
  Vec2 downstream = Vec2::UnitX();  // [-] unit normal to the axis, pointing downstream
  double reach = 0.0;               // [m] the structure's half extent along the flow: its piers'
                                    // farthest point from the axis, or half its deck's width
  std::optional<DeckConfig> deck;   // none: a bridge of piers only
  int deck_group = -1;              // the contact group of its deck's face (after the mesh's
                                    // boundary groups; JamGeometry::group_names names it)
  std::vector<int> piers;           // its piers (indices into JamGeometry::solids), s ascending
  std::vector<Gap> gaps;            // s ascending
  double backwater_distance = 0.0;  // [m] the backwater section's distance upstream of the axis

  double length() const { return (end - start).norm(); }                   // [m]
  double along_of(const Vec2& p) const { return along.dot(p - start); }    // s [m]
  double downstream_of(const Vec2& p) const { return downstream.dot(p); }  // d [m]
  double axis_downstream() const { return downstream.dot(start); }         // d of the axis [m]
  /// The deck's upstream face: the axis moved half the deck's width upstream [m] (a deck only).
  Vec2 face_start() const { return start - 0.5 * deck->width * downstream; }
  Vec2 face_end() const { return end - 0.5 * deck->width * downstream; }
  /// True when p lies beyond the structure downstream: d(p) > d(axis) + reach.
  bool passed(const Vec2& p) const { return downstream_of(p) > axis_downstream() + reach; }
};

/// Half the extent of body i's footprint (a rotated rectangle) along the unit vector `direction`
/// [m]: (L/2)|a . direction| + (l/2)|perp(a) . direction|, a = (cos theta, sin theta).
double footprint_half_extent_along(const BodySet& bodies, int i, const Vec2& direction);

}  // namespace flotsam
