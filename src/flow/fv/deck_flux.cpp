#include "flow/fv/deck_flux.hpp"

#include <algorithm>
#include <cmath>

namespace flotsam {

std::vector<DeckEdge> find_deck_edges(const CellMesh& cells,
                                      const std::vector<BridgeConfig>& bridges) {
  std::vector<DeckEdge> found;
  for (const BridgeConfig& bridge : bridges) {
    if (!bridge.deck) continue;
    const Vec2 along = bridge.along(), downstream = bridge.downstream();
    const double length = (bridge.end - bridge.start).norm();  // [m]
    const DeckConfig& deck = *bridge.deck;
    for (int e = 0; e < cells.edge_count; ++e) {
      const int i = cells.left[e], j = cells.right[e];
      if (j < 0) continue;
      const double d_i = downstream.dot(cells.centroid[i] - bridge.start);
      const double d_j = downstream.dot(cells.centroid[j] - bridge.start);
      if ((d_i < 0.0) == (d_j < 0.0)) continue;
      const int slot = cells.left_slot[e];
      const double s = along.dot(cells.centroid[i] + cells.to_edge[i][slot] - bridge.start);
      if (s < 0.0 || s > length) continue;
      found.push_back({e, deck.soffit, deck.crest(), std::abs(cells.normal[e].dot(downstream))});
    }
  }
  return found;
}

DeckFlow deck_flow(double energy, double depth, double opening, double crest, double projection,
                   double limit, double g) {
  // Under the deck: the opening flows full; its outlet pressure is the opening's height or the
  // tailwater, whichever is higher.
  const double q_gate =
      opening * std::sqrt(2.0 * g * std::max(0.0, energy - std::max(opening, depth)));
  // Over it: a broad-crested weir, drowned by the tailwater above the crest (Villemonte 1947).
  double q_weir = 0.0;                 // [m^2/s]
  const double head = energy - crest;  // [m]
  if (head > 0.0) {
    const double drowned = std::max(0.0, depth - crest) / head;  // [-]
    const double factor =
        std::pow(std::max(0.0, 1.0 - std::pow(std::min(drowned, 1.0), 1.5)), 0.385);
    q_weir = std::pow(2.0 / 3.0, 1.5) * std::sqrt(g) * head * std::sqrt(head) * factor;
  }
  const double capacity = projection * (q_gate + q_weir);  // [m^2/s]
  DeckFlow flow;
  if (capacity <= 0.0) return flow;
  const double share = std::min(1.0, limit / capacity);  // [-] of each path the flow takes
  const double g_part = share * projection * q_gate, w_part = share * projection * q_weir;
  flow.discharge = g_part + w_part;
  const double gate_speed = opening > 0.0 ? share * q_gate / opening : 0.0;      // [m/s]
  const double weir_speed = q_weir > 0.0 ? std::cbrt(g * share * q_weir) : 0.0;  // sqrt(g y_c)
  flow.momentum = g_part * gate_speed + w_part * weir_speed;
  flow.jet_speed = std::max(gate_speed, weir_speed);
  return flow;
}

}  // namespace flotsam
