#include "flow/fem/element_blocks.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

namespace flotsam {

ElementBlocks element_blocks(const Mesh& mesh) {
  const int element_count = mesh.element_count(), size = ElementBlocks::block_size;
  const int block_count = (element_count + size - 1) / size;
  // The blocks at each vertex, each listed once, in block order.
  std::vector<std::vector<int>> vertex_blocks(mesh.vertex_count);
  for (int e = 0; e < element_count; ++e)
    for (int k = 0; k < 3; ++k) {
      auto& blocks = vertex_blocks[mesh.elements[e][k]];
      if (blocks.empty() || blocks.back() != e / size) blocks.push_back(e / size);
    }
  std::vector<int> colour(block_count, -1);
  ElementBlocks out;
  for (int b = 0; b < block_count; ++b) {
    const int begin = b * size, end = std::min(begin + size, element_count);
    std::uint64_t used = 0;
    for (int e = begin; e < end; ++e)
      for (int k = 0; k < 3; ++k)
        for (int other : vertex_blocks[mesh.elements[e][k]])
          if (colour[other] >= 0) used |= std::uint64_t{1} << colour[other];
    int c = 0;
    while (c < 64 && (used >> c & 1U)) ++c;
    if (c == 64) throw std::logic_error("element_blocks: more than 64 colours needed");
    colour[b] = c;
    if (c >= static_cast<int>(out.colours.size())) {
      out.colours.resize(c + 1);
      out.element_count.resize(c + 1, 0);
    }
    out.colours[c].push_back({begin, end});
    out.element_count[c] += end - begin;
  }
  return out;
}

}  // namespace flotsam
