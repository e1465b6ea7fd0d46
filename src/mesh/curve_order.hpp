#pragma once
// The numbering of every mesh: nodes and elements along a space-filling curve (docs/mesh.md
// "Numbering").
//
// A mesh sweep (assembly, interpolation, a sparse product) reads the values of an element's
// nodes; when elements that follow each other in the numbering lie side by side, and so do their
// nodes, those values come from the cache instead of memory. Gmsh's order is far from that. So
// build_mesh renumbers every mesh, read or generated:
//
//   * each node and element gets a key: the index along a Hilbert curve through a grid of
//     2^20 x 2^20 cells laid over the mesh's bounding square, of its position (an element: the
//     mean of its three vertices' cells, in integers);
//   * vertices keep coming first (P1 fields are the first vertex_count values), each group of
//     nodes in the order of its keys; elements in the order of theirs; equal keys in the order
//     they came in (so the same input gives the same numbering on any machine);
//   * boundary edges in the order of their element, then of their local edge.
//
// Each node and element keeps its source tag (Mesh::node_tags, element_tags) for messages.
#include <cstdint>
#include <vector>

#include "mesh/mesh.hpp"

namespace flotsam {

/// Index along the Hilbert curve of order `bits` (a grid of 2^bits x 2^bits cells) of cell (x, y),
/// 0 <= x, y < 2^bits: neighbouring indices are neighbouring cells.
std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y, int bits);

/// The permutation that sorts `keys`: position i holds the index of the i-th smallest key, equal
/// keys in the order of their indices.
std::vector<int> sorting_permutation(const std::vector<std::uint64_t>& keys);

/// The mesh renumbered as above: the same nodes, elements, boundary edges and groups.
Mesh ordered_along_curve(const Mesh& mesh);

/// The mesh with node i of the result node_order[i] of `mesh` and element i element_order[i]
/// (permutations; vertices must stay first), boundary edges in the order of (element, local edge).
Mesh renumbered(const Mesh& mesh, const std::vector<int>& node_order,
                const std::vector<int>& element_order);

}  // namespace flotsam
