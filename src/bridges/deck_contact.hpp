#pragma once
// Decks stop what floats (docs/model.md "Decks"): each deck's upstream face is a wall segment
// for the contacts that stops only the bodies whose vertical extent meets the deck's, from its
// soffit to the top of its railing. A body whose top is below the soffit passes under; one whose
// underside is above the railing floats over; the others stop against the face, and a jam can
// build along it. Both are judged at the start of each flow step from the water at the body.
#include <string>
#include <vector>

#include "bodies/body_set.hpp"
#include "bridges/bridge.hpp"
#include "contact/boundary_segments.hpp"
#include "flow/flow_field.hpp"

namespace flotsam {

/// Appends the upstream face of every bridge's deck to `walls` (the water on its upstream side,
/// stopping bodies in [soffit, top + railing]) in the bridge's deck_group, takes `group_names`
/// (which name the deck groups too) and rebuilds the grid. Nothing changes without a deck.
void add_deck_faces(BoundarySegments& walls, const std::vector<Bridge>& bridges,
                    const std::vector<std::string>& group_names);

/// The z of each body's underside and top [m] at time t: floating, the water surface at G less
/// its draft, grounded, the bed at G (z_b = eta - H); the top is the underside plus its height.
struct BodyLevels {
  std::vector<double> bottom, top;
};
BodyLevels body_levels(const BodySet& bodies, const FlowField& flow, double t);

/// The lowest bed [m] at `samples` points spread evenly over the bridge's gaps (midpoint rule),
/// as the flow holds it at time t (z_b = eta - H).
double lowest_bed_on_axis(const Bridge& bridge, const FlowField& flow, double t, int samples = 100);

}  // namespace flotsam
