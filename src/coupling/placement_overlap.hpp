#pragma once
// Bodies placed on top of each other (issue 20 item 6): the contacts would push them apart in the
// first step, without a word. The run warns, naming both ids and the overlap, so a typo in a
// position is seen; it does not refuse, since a jam built by hand may hold bodies that touch.
#include <string>
#include <vector>

#include "bodies/body_set.hpp"

namespace flotsam {

struct PlacementOverlap {
  int a = 0, b = 0;    // body indices, a < b
  double depth = 0.0;  // [m] how far their footprints overlap
};

/// Pairs of active bodies whose footprints overlap by more than `allowed` [m] (O(n^2) after a
/// bounding-circle test: for the bodies a case lists).
std::vector<PlacementOverlap> placement_overlaps(const BodySet& bodies, double allowed);

/// "bodies 3 and 7 overlap by 0.25 m where the case places them (case.yaml)...", one per line.
std::string describe_overlaps(const BodySet& bodies, const std::vector<PlacementOverlap>& overlaps,
                              const std::string& case_file);

}  // namespace flotsam
