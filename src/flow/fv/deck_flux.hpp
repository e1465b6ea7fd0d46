#pragma once
// The water under and over a bridge deck (docs/model.md "Decks: the water"), finite volumes.
// A deck stands on the edges between the cells on either side of its axis (within the axis'
// span). While the water on both sides stays below the soffit those edges take the ordinary
// flux, bit for bit the flow without a deck. Once the water reaches the soffit on either side,
// an edge passes at most the structure's capacity per metre of axis, from the upstream energy
// head E (over the edge's bed, velocity head included) and the downstream depth h_d:
//
//   under the deck (opening a = z_s - z_e)   q_g = a sqrt(2 g max(0, E - max(a, h_d)))
//   over it (crest z_c, head H = E - z_c)    q_w = (2/3)^{3/2} g^{1/2} H^{3/2} S,
//                                             S = (1 - (h_c / H)^{3/2})^{0.385}  (Villemonte)
//
// the discharge being the ordinary flux's, limited to (q_g + q_w) |n_e . n_axis|. Each side of
// the edge then feels the hydrostatic pressure of its own water on the structure, the upstream
// side gives up the momentum the discharge carries, and the downstream side receives it at the
// speed of the jets: q_g / a under the deck, the critical speed over it. Mass crosses the edge
// as one flux, so it is conserved to round-off; with the water at rest the pressures are those
// of a wall on each side, so a lake at rest stays at rest.
#include <vector>

#include "bridges/bridge_config.hpp"
#include "flow/fv/cell_mesh.hpp"

namespace flotsam {

/// An edge of the cells a deck stands on.
struct DeckEdge {
  int edge = -1;
  double soffit = 0.0;      // [m] z of the deck's underside
  double crest = 0.0;       // [m] z of what the water overtops: the top, or a solid railing's
  double projection = 1.0;  // [-] |n_edge . n_axis|: the edge's share of a metre of axis
};

/// The deck edges of the bridges that have a deck: interior edges whose two cells' centroids lie
/// on either side of the axis' line and whose midpoint lies within its span.
std::vector<DeckEdge> find_deck_edges(const CellMesh& cells,
                                      const std::vector<BridgeConfig>& bridges);

/// What the structure passes per metre of edge, from the upstream side.
struct DeckFlow {
  double discharge = 0.0;  // [m^2/s] >= 0
  double momentum = 0.0;   // [m^3/s^2] the jets' momentum flux into the downstream side
  double jet_speed = 0.0;  // [m/s] the fastest jet (the Courant step)
};

/// The structure's flow for the upstream energy head `energy` and the downstream depth `depth`
/// (both over the edge's bed z_e) [m], its opening `opening` = max(0, z_s - z_e) and crest
/// height `crest` = z_c - z_e [m], limited to `limit` [m^2/s] (the ordinary flux's discharge).
DeckFlow deck_flow(double energy, double depth, double opening, double crest, double projection,
                   double limit, double g);

}  // namespace flotsam
