// Verifies the coloured element blocks of the FEM engine's sweeps (element_blocks.hpp): every
// element in exactly one block, blocks of consecutive elements at most block_size long, and no two
// blocks of one colour sharing a vertex (so two threads never add into the same node at once).
#include "flow/fem/element_blocks.hpp"

#include <gtest/gtest.h>

#include <set>

#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

TEST(ElementBlocks, CoverEveryElementOnceAndNoColourSharesAVertex) {
  // 60 x 40 cells: 4,800 elements, 38 blocks, on the Hilbert numbering build_mesh gives.
  const Mesh mesh = make_rectangle_mesh({.length = 600.0, .width = 400.0, .nx = 60, .ny = 40});
  const ElementBlocks blocks = element_blocks(mesh);
  ASSERT_EQ(blocks.colours.size(), blocks.element_count.size());
  std::vector<int> seen(mesh.element_count(), 0);
  for (std::size_t c = 0; c < blocks.colours.size(); ++c) {
    SCOPED_TRACE(::testing::Message() << "colour " << c);
    std::set<int> vertices;  // of the colour's blocks so far
    int elements = 0;
    for (const auto& [begin, end] : blocks.colours[c]) {
      ASSERT_LT(begin, end);
      ASSERT_LE(end - begin, ElementBlocks::block_size);
      EXPECT_EQ(begin % ElementBlocks::block_size, 0);
      std::set<int> own;
      for (int e = begin; e < end; ++e) {
        ++seen[e];
        for (int k = 0; k < 3; ++k) own.insert(mesh.elements[e][k]);
      }
      for (int v : own) EXPECT_EQ(vertices.count(v), 0u) << "vertex " << v;
      vertices.insert(own.begin(), own.end());
      elements += end - begin;
    }
    EXPECT_EQ(blocks.element_count[c], elements);
  }
  for (int e = 0; e < mesh.element_count(); ++e) EXPECT_EQ(seen[e], 1) << "element " << e;
  // Compact patches along the curve touch few others: a handful of colours, not dozens.
  EXPECT_LE(blocks.colours.size(), 8u);
}

}  // namespace
}  // namespace flotsam
