#pragma once
// Elements in blocks of consecutive numbers, the blocks coloured: the order of the FEM engine's
// element sweeps (ShallowWaterSolver::for_each_element).
//
// The mesh's elements run along a space-filling curve (mesh/curve_order.hpp), so a block of
// consecutive elements is a compact patch whose nodes lie close together in memory. Blocks that
// share no vertex get one colour: a colour's blocks may be swept by different threads at once,
// each block by one thread in element order. A sweep goes colour by colour, and the sum into each
// node is in the same order for any number of threads. (Colouring single elements instead made
// each colour's sweep stride through the whole mesh, once per colour.)
#include <array>
#include <vector>

#include "mesh/mesh.hpp"

namespace flotsam {

struct ElementBlocks {
  static constexpr int block_size = 128;  // [elements]
  /// Per colour: its blocks, each the element range [begin, end).
  std::vector<std::vector<std::array<int, 2>>> colours;
  std::vector<int> element_count;  // per colour
};

/// Blocks of block_size consecutive elements (the last one shorter), coloured greedily in block
/// order so that no two blocks of a colour share a vertex (hence no node).
ElementBlocks element_blocks(const Mesh& mesh);

}  // namespace flotsam
