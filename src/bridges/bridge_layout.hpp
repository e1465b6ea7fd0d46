#pragma once
// Where a case's bridges stand on its mesh (docs/model.md "Bridges"): the paper's channel makes
// one bridge of each line of piers across it; any other mesh takes the case's `bridges:`, whose
// axes are cut by the mesh's boundary into the gaps between piers, banks and abutments.
#include <string>
#include <vector>

#include "bridges/bridge.hpp"
#include "bridges/bridge_config.hpp"
#include "mesh/geometry.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

/// The paper's channel: piers whose centre x differ by less than the smaller radius stand in one
/// line (lines chain), numbered downstream ("bridge_1", ...). Each line is a bridge with the axis
/// (x, 0) -> (x, width), x the mean of its piers' centres, reach its largest radius, gaps between
/// the banks and the piers' circles [y_c - r, y_c + r]. `pier_solid[p]` is the solid of the
/// channel's pier p, `right_bank` and `left_bank` the banks'.
std::vector<Bridge> channel_bridges(const ChannelGeometry& channel,
                                    const std::vector<int>& pier_solid, int right_bank,
                                    int left_bank);

/// The case's bridges on `mesh`. The axis is cut where it crosses the mesh's boundary edges; the
/// pieces inside the domain are the gaps, each ending at the solid of the boundary crossed
/// (`solid_of_group[group]`, -1 for an open boundary) or at an abutment (-1: the axis' end inside
/// the domain). Its piers are the solids crossed between two gaps and the groups its config
/// names; its reach the largest distance of a pier's boundary from the axis. InputError naming
/// the bridge's origin: an axis that crosses no water, a named pier group the mesh lacks or the
/// axis does not meet, two axes that cross.
std::vector<Bridge> bridges_on_mesh(const std::vector<BridgeConfig>& configs, const Mesh& mesh,
                                    const std::vector<int>& solid_of_group);

}  // namespace flotsam
