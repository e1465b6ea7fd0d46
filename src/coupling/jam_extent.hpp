#pragma once
// How far down a jam at a bridge reaches, and how much of a bridge's opening it closes
// (docs/model.md "Vertical extent of a jam"). With `bodies.jams.vertical_extent: accumulation`
// a jam at a bridge is a porous accumulation whose bulk holds its wood at porosity P, as deep
// as it is long along the flow (M-J1):
//   T = sqrt(V_s / ((1 - P) w_c)),
// V_s the wood volume of its bodies [m^3], w_c the width of the bridge's gaps it covers [m].
// Its bodies act on the water over max(d, T) rather than their own draft d (the wetted height
// of (M-6) and (M-8)), so that the flow meets the blocked area; the force each body exchanges
// with the water stays its own drag, so momentum is exchanged exactly (spec 5).
#include <vector>

#include "bodies/body_set.hpp"
#include "coupling/jam_statistics.hpp"
#include "io/case.hpp"

namespace flotsam {

/// (M-J1) T = sqrt(V_s / ((1 - P) w_c)) [m]; 0 when w_c <= 0.
double accumulation_thickness(double wood_volume, double covered_width, double porosity);

/// Every body's wetted height (BodySet::wetted_height): its draft, or, with the accumulation
/// model, max(draft, T) for a body of a jam at a bridge.
void set_wetted_heights(BodySet& bodies, const JamStatistics& statistics,
                        const JamGeometry& geometry, const JamConfig& config);

/// The water at a gap of a bridge, where a jam stands against it.
struct GapLevel {
  double surface = 0.0;  // eta [m]
  double bed = 0.0;      // z_b [m]
};

/// The water at every gap of every bridge ([bridge][gap]): at the gap's middle, `reach` upstream
/// of the axis (the face a jam stands against). `sample(p)` gives the level at point p.
template <class Sample>
std::vector<std::vector<GapLevel>> gap_levels(const JamGeometry& geometry, Sample&& sample) {
  std::vector<std::vector<GapLevel>> levels;
  for (const Bridge& b : geometry.bridges) {
    auto& bridge = levels.emplace_back();
    for (const Gap& gap : b.gaps) {
      const Vec2 p = b.start + 0.5 * (gap.lower + gap.upper) * b.along - b.reach * b.downstream;
      bridge.push_back(sample(p));
    }
  }
  return levels;
}

/// Height of a gap's opening [m]: from the bed to the surface, or to the soffit below it.
double opening_height(const GapLevel& level, const Bridge& bridge);

/// Height of that opening a jam of thickness T closes [m]: the overlap of [eta - T, eta] with
/// the opening.
double closed_height(const GapLevel& level, const Bridge& bridge, double thickness);

/// Fills each jam's gap_opening_closed and the statistics' bridge_opening_closed: the share of
/// each opening's area (its width times opening_height) the jams' covered widths close over
/// their closed_height; several jams in one gap (one behind the other) close at most all of it.
void measure_opening_closure(JamStatistics& statistics, const JamGeometry& geometry,
                             const std::vector<std::vector<GapLevel>>& levels);

}  // namespace flotsam
