#pragma once
// Cuthill-McKee order of a graph (Cuthill & McKee 1969; George & Liu 1981, ch. 4): breadth-first
// levels from a pseudo-peripheral start, each node's unnumbered neighbours in increasing degree
// (equal degrees in the order of its list), every connected part in turn from its lowest node.
// The levels are fronts across the graph: a node's neighbours lie in its own level or the ones
// before and after, close in the order. Used for the mesh's elements (mesh/element_order.hpp) and,
// reversed, for the FEM's unknowns (flow/fem/node_ordering.hpp).
#include <span>
#include <vector>

namespace flotsam {

/// The nodes in Cuthill-McKee order (position k holds the k-th node) of the graph whose node i
/// has the neighbours index[start[i]] .. index[start[i + 1] - 1] (symmetric; an entry i itself is
/// ignored). The start of each part: George & Liu's search, from the part's lowest node, of the
/// least degree node of the last level (the last such in the search's order), while the number of
/// levels grows (at most 8 searches).
std::vector<int> cuthill_mckee(std::span<const int> start, std::span<const int> index);

}  // namespace flotsam
