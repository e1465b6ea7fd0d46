// Verifies that the neighbour walk (spec 4.4) finds an element containing the point whenever a
// scan of all elements finds one, and reports the point outside (with the boundary it crossed)
// exactly when the scan finds none: on a mesh with square, polygonal and U-shaped holes, and on
// curved P2 elements.
#include "mesh/point_locator.hpp"
#include "../support/sanitized.hpp"
#include "../support/two_pier_channel.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

#include "holey_mesh.hpp"
#include "mesh/mesh_generator.hpp"

namespace flotsam {
namespace {

using fixtures::make_curved_square_mesh;
using fixtures::make_holey_mesh;
using fixtures::map_to_element;

// Counts disagreements between the walk (from `hint`) and the scan at p; prints the first few.
struct Comparison {
  const PointLocator& locator;
  int failures = 0;

  void check(const Vec2& p, int hint, bool generic) {
    const Location walk = locator.locate(p, hint);
    const Location scan = locator.locate_brute_force(p);
    bool ok = walk.inside == scan.inside;
    if (ok && walk.inside) {
      ok = locator.contains(walk.element, p);
      // A generic point lies in one element only: the same index.
      if (generic) ok = ok && walk.element == scan.element;
      // (r, s) maps back to p (Newton on a curved element; a straight element's mid nodes may be
      // off their edges' midpoints by up to 1e-9 h, Mesh::is_curved).
      const Mesh& mesh = locator.mesh();
      const Vec2 back = map_to_element(mesh, walk.element, walk.r, walk.s);
      const double h = std::sqrt(mesh.area[walk.element]);
      const double slack = walk.curved ? 0.0 : 2e-9 * h;  // [m]
      ok = ok && (back - p).norm() < 1e-12 * (1 + p.norm()) + slack;
    }
    if (!ok && ++failures <= 5)
      ADD_FAILURE() << "point (" << p.x() << ", " << p.y() << ") hint " << hint << ": walk "
                    << walk.inside << " element " << walk.element << ", scan " << scan.inside
                    << " element " << scan.element;
  }
};

TEST(PointLocator, WalkAgreesWithBruteForceOnAMeshWithHoles) {
  const Mesh mesh = make_holey_mesh(2);
  const PointLocator locator(mesh);
  Comparison comparison{locator};
  std::mt19937 random(12345);
  std::uniform_real_distribution<double> x(-0.5, 12.5), y(-0.5, 8.5), offset(-1.5, 1.5),
      unit(0.0, 1.0);
  std::uniform_int_distribution<int> element(0, mesh.element_count() - 1);
  int queries = 0;

  // Random points over and around the domain (holes, outside): cold starts, random hints (most
  // of them far: the grid takes over), and hints from a point up to 1.5 m away, so that walks
  // meet the holes' walls.
  const int random_points = test::repetitions(60000), all_points = test::repetitions(100000);
  for (int i = 0; i < random_points; ++i, ++queries) {
    const Vec2 p(x(random), y(random));
    int hint = -1;
    if (i % 3 == 1) hint = element(random);
    if (i % 3 == 2)
      hint = locator.locate_brute_force(p + Vec2(offset(random), offset(random))).element;
    comparison.check(p, hint, true);
  }
  // Points exactly on vertices, on edge midpoints and on edges (any containing element is right).
  while (queries < all_points) {
    const int e = element(random), k = queries % 3;
    const auto& el = mesh.elements[e];
    const Vec2 &a = mesh.nodes[el[k]], &b = mesh.nodes[el[(k + 1) % 3]];
    const Vec2 points[3] = {a, mesh.nodes[el[3 + k]], a + unit(random) * (b - a)};
    for (const Vec2& p : points) {
      comparison.check(p, queries % 2 == 0 ? -1 : element(random), false);
      ++queries;
    }
  }
  EXPECT_EQ(comparison.failures, 0) << "of " << queries << " points";
}

TEST(PointLocator, PointInTheUPocketIsInsideAlthoughTheWalkMeetsTheHole) {
  // From (10, 1.8), below the U of hole_3, the straight walk to (10, 3.2) in its pocket leaves
  // the mesh through the U's bottom wall [2, 3]; the point is inside nonetheless.
  const Mesh mesh = make_holey_mesh(2);
  const PointLocator locator(mesh);
  const Vec2 p(10.0, 3.2);
  const int hint = locator.locate(Vec2(10.0, 1.8)).element;
  const Location location = locator.locate(p, hint);
  ASSERT_TRUE(location.inside);
  EXPECT_TRUE(locator.contains(location.element, p));
  EXPECT_EQ(location.element, locator.locate_brute_force(p).element);
}

TEST(PointLocator, PointInAHoleOrBeyondABankIsOutsideWithTheBoundaryCrossed) {
  const Mesh mesh = make_holey_mesh(2);
  const PointLocator locator(mesh);
  auto walk_from = [&](const Vec2& from, const Vec2& to) {
    return locator.locate(to, locator.locate(from).element);
  };
  const Location in_hole = walk_from({1.3, 3.5}, {3.0, 3.5});
  EXPECT_FALSE(in_hole.inside);
  ASSERT_GE(in_hole.boundary_edge, 0);
  EXPECT_EQ(in_hole.boundary_group, mesh.find_group("hole_1"));
  EXPECT_EQ(mesh.boundary[in_hole.boundary_edge].group, in_hole.boundary_group);

  const Location in_diamond = walk_from({8.9, 4.1}, {7.0, 4.0});
  EXPECT_FALSE(in_diamond.inside);
  EXPECT_EQ(in_diamond.boundary_group, mesh.find_group("hole_2"));

  const Location beyond_left = walk_from({0.3, 4.1}, {-0.4, 4.1});
  EXPECT_FALSE(beyond_left.inside);
  EXPECT_EQ(beyond_left.boundary_group, mesh.find_group("left"));

  const Location beyond_top = walk_from({5.1, 7.6}, {5.1, 8.5});
  EXPECT_FALSE(beyond_top.inside);
  EXPECT_EQ(beyond_top.boundary_group, mesh.find_group("top"));

  const Location far_away = locator.locate({100.0, -50.0});  // cold start, far outside the box
  EXPECT_FALSE(far_away.inside);
  EXPECT_FALSE(locator.locate({std::nan(""), 1.0}).inside);
}

TEST(PointLocator, WalkTakesFewStepsForAPointMovingAFractionOfAnElement) {
  // A point moving 0.3 element sizes per query (spec 4.4: "usually 1-3 steps per sample"),
  // turning to a random direction whenever its next position would leave the domain.
  const int n = 4;
  const double h = 1.0 / n;  // [m] cell size
  const Mesh mesh = make_holey_mesh(n);
  const PointLocator locator(mesh);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> angle(0.0, 2 * std::numbers::pi);
  Vec2 p(1.0, 1.0), direction(1.0, 0.0);
  Location location = locator.locate(p);
  long steps = 0;
  const int queries = test::repetitions(20000);
  for (int i = 0; i < queries; ++i) {
    Vec2 next = p + 0.3 * h * direction;
    while (!locator.locate_brute_force(next).inside) {
      const double a = angle(random);
      direction = Vec2(std::cos(a), std::sin(a));
      next = p + 0.3 * h * direction;
    }
    p = next;
    location = locator.locate(p, location.element);
    ASSERT_TRUE(location.inside);
    steps += location.steps;
  }
  const double average = static_cast<double>(steps) / queries;
  RecordProperty("average_steps", std::to_string(average));
  EXPECT_LT(average, 3.0);
}

// locate_batch against locate, lane by lane: the same Location to the bit (element, inside,
// (r, s), curved, boundary edge and group, steps) for 8 points at a time, from cached, fresh,
// stale and invalid hints, at random points (holes, beyond the banks), on edges and vertices.
void expect_batch_equals_locate(const Mesh& mesh, const Vec2& low, const Vec2& high,
                                std::uint32_t seed) {
  const PointLocator locator(mesh);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> x(low.x(), high.x()), y(low.y(), high.y()), unit(0, 1);
  std::uniform_int_distribution<int> element(0, mesh.element_count() - 1), choice(0, 7);
  constexpr int n = 8;
  int cached[n] = {-1, -1, -1, -1, -1, -1, -1, -1}, failures = 0, fast = 0;
  double px[n] = {}, py[n] = {};
  for (int b = 0; b < 4000; ++b) {
    bool active[n];
    int hints[n];
    for (int k = 0; k < n; ++k) {
      const int e = element(random), kind = choice(random);
      const auto& el = mesh.elements[e];
      Vec2 p(x(random), y(random));
      if (kind <= 1)  // on an edge
        p = mesh.nodes[el[kind]] + unit(random) * (mesh.nodes[el[kind + 1]] - mesh.nodes[el[kind]]);
      else if (kind == 2)  // a vertex or a mid node
        p = mesh.nodes[el[choice(random) % 6]];
      else if (kind <= 5 && cached[k] >= 0)  // a short move, as a body's between two stages
        p = Vec2(px[k], py[k]) + 0.05 * Vec2(unit(random) - 0.5, unit(random) - 0.5);
      px[k] = p.x(), py[k] = p.y();
      active[k] = choice(random) != 0;
      const int h = choice(random);
      hints[k] = h < 4 ? cached[k] : h < 5 ? e : h < 6 ? -1 : h < 7 ? mesh.element_count() : e / 2;
    }
    Location batch[n];
    locator.locate_batch(n, px, py, active, hints, batch);
    for (int k = 0; k < n; ++k) {
      if (!active[k]) continue;
      const Location one = locator.locate({px[k], py[k]}, hints[k]);
      const Location& got = batch[k];
      const bool same =
          got.element == one.element && got.inside == one.inside &&
          std::bit_cast<std::uint64_t>(got.r) == std::bit_cast<std::uint64_t>(one.r) &&
          std::bit_cast<std::uint64_t>(got.s) == std::bit_cast<std::uint64_t>(one.s) &&
          got.curved == one.curved && got.boundary_edge == one.boundary_edge &&
          got.boundary_group == one.boundary_group && got.steps == one.steps;
      if (!same && ++failures <= 5)
        ADD_FAILURE() << "point (" << px[k] << ", " << py[k] << ") hint " << hints[k]
                      << ": batch element " << got.element << ", locate " << one.element;
      fast += one.inside && one.element == hints[k] ? 1 : 0;
      if (one.element >= 0) cached[k] = one.element;
    }
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(fast, 2000);  // found in the hint: the path without the walk was taken
}

TEST(PointLocator, BatchLocatesAsLocateOnAMeshWithHoles) {
  expect_batch_equals_locate(make_holey_mesh(2), {-1.0, -1.0}, {13.0, 9.0}, 3);
}

TEST(PointLocator, BatchLocatesAsLocateOnCurvedElements) {
  expect_batch_equals_locate(make_curved_square_mesh(), {-0.1, -0.1}, {1.1, 1.1}, 4);
}

// The walk from a body's last element (locate_batch with the cached element as hint) finds the
// element a fresh search finds (from the bucket grid; a scan of all elements), for a point in
// one element only; for a point on an edge or a vertex, an element that holds it, as the fresh
// search does.
TEST(PointLocator, CachedStartWalkFindsTheElementOfAFreshSearch) {
  const int n = 4;
  const double h = 1.0 / n;  // [m] cell size
  const Mesh mesh = make_holey_mesh(n);
  const PointLocator locator(mesh);
  std::mt19937 random(17);
  std::uniform_real_distribution<double> angle(0.0, 2 * std::numbers::pi), unit(0.0, 1.0);
  constexpr int bodies = 8;
  double px[bodies], py[bodies];
  int cached[bodies];
  const bool active[bodies] = {true, true, true, true, true, true, true, true};
  for (int k = 0; k < bodies; ++k) {
    px[k] = 0.5 + 1.3 * k, py[k] = 0.5;
    cached[k] = locator.locate({px[k], py[k]}).element;
  }
  int generic = 0, shared = 0;
  for (int step = 0; step < test::repetitions(2000); ++step) {
    for (int k = 0; k < bodies; ++k) {  // a move of up to half a cell, or onto a vertex
      Vec2 next;
      do {
        const double a = angle(random);
        next = Vec2(px[k], py[k]) + 0.5 * h * unit(random) * Vec2(std::cos(a), std::sin(a));
        if (step % 50 == k) next = (next / h).array().round().matrix() * h;  // a grid vertex
      } while (!locator.locate_brute_force(next).inside);
      px[k] = next.x(), py[k] = next.y();
    }
    Location walked[bodies];
    locator.locate_batch(bodies, px, py, active, cached, walked);
    for (int k = 0; k < bodies; ++k) {
      const Vec2 p(px[k], py[k]);
      const Location fresh = locator.locate(p, -1);
      const Location scan = locator.locate_brute_force(p);
      ASSERT_TRUE(walked[k].inside && fresh.inside && scan.inside);
      int holding = 0;
      for (int e = 0; e < mesh.element_count(); ++e) holding += locator.contains(e, p) ? 1 : 0;
      if (holding == 1) {
        ++generic;
        EXPECT_EQ(walked[k].element, fresh.element);
        EXPECT_EQ(walked[k].element, scan.element);
      } else {
        ++shared;
        EXPECT_TRUE(locator.contains(walked[k].element, p));
      }
      cached[k] = walked[k].element;
    }
  }
  EXPECT_GT(generic, test::repetitions(10000));
  EXPECT_GT(shared, test::repetitions(200));  // on grid vertices
}

TEST(PointLocator, CurvedElementsUseTheirSubTrianglesAndInvertTheP2Map) {
  const Mesh mesh = make_curved_square_mesh();
  const PointLocator locator(mesh);
  int curved = 0;
  for (int e = 0; e < mesh.element_count(); ++e) curved += mesh.is_curved(e);
  ASSERT_EQ(curved, 4);

  // Between the chord and the outward arc over [0, 0.25]: inside; under the inward arc over
  // [0.25, 0.5]: outside, through the bottom.
  const Location bulge = locator.locate({0.125, -0.02});
  EXPECT_TRUE(bulge.inside);
  EXPECT_TRUE(bulge.curved);
  const Location notch = locator.locate({0.375, 0.02}, locator.locate({0.375, 0.2}).element);
  EXPECT_FALSE(notch.inside);
  EXPECT_EQ(notch.boundary_group, mesh.find_group("bottom"));

  // Walk against scan around the curved edges.
  Comparison comparison{locator};
  std::mt19937 random(99);
  std::uniform_real_distribution<double> x(-0.05, 1.05), y(-0.1, 0.4), unit(0.0, 1.0);
  for (int i = 0; i < test::repetitions(20000); ++i)
    comparison.check({x(random), y(random)}, i % 2 - 1, true);
  EXPECT_EQ(comparison.failures, 0);

  // Newton recovers the reference coordinates of x(r, s) in every curved element.
  for (int e = 0; e < mesh.element_count(); ++e) {
    if (!mesh.is_curved(e)) continue;
    for (int i = 0; i < 50; ++i) {
      const double r = 0.1 + 0.7 * unit(random), s = 0.1 + (0.8 - r) * unit(random);
      const Location location = locator.locate(map_to_element(mesh, e, r, s));
      ASSERT_TRUE(location.inside);
      EXPECT_EQ(location.element, e);
      EXPECT_TRUE(location.curved);
      EXPECT_NEAR(location.r, r, 1e-12);
      EXPECT_NEAR(location.s, s, 1e-12);
    }
  }
}

TEST(PointLocator, ChannelWithTwoCircularPiersFromTheMeshGenerator) {
  // Gmsh's second-order mesh: the elements on the piers are curved, their mid nodes on the
  // circles. The chords of a circle lie inside it, so every point of the channel outside the
  // piers' circles is inside the mesh (sub-triangles, P-33), and points well inside a circle
  // (beyond the chords' sagitta) are outside.
  const MeshSource source = test::two_pier_channel();
  const Mesh mesh = generate_mesh(source);
  const PointLocator locator(mesh);
  const auto& piers = source.channel.piers;
  int curved = 0;
  for (int e = 0; e < mesh.element_count(); ++e) curved += mesh.is_curved(e);
  EXPECT_GT(curved, 0);

  Comparison comparison{locator};
  std::mt19937 random(31);
  std::uniform_real_distribution<double> x(-5.0, 205.0), y(-5.0, 65.0),
      angle(0.0, 2 * std::numbers::pi), gap(0.0, 1.0);
  for (int i = 0; i < test::repetitions(20000); ++i)
    comparison.check({x(random), y(random)}, -1, true);
  // Around the piers, from hints nearby: just outside the circle inside, well inside outside.
  for (int i = 0; i < test::repetitions(4000); ++i) {
    const Pier& pier = piers[i % 2];
    const double a = angle(random);
    const Vec2 direction(std::cos(a), std::sin(a));
    const Vec2 near = pier.centre + (pier.radius + 1e-9 + gap(random)) * direction;
    const Vec2 deep = pier.centre + (0.9 * pier.radius) * gap(random) * direction;
    const int hint = locator.locate(pier.centre + (pier.radius + 3.0) * direction).element;
    comparison.check(near, hint, true);
    comparison.check(deep, hint, true);
    EXPECT_TRUE(locator.locate(near, hint).inside);
    const Location in_pier = locator.locate(deep, hint);
    EXPECT_FALSE(in_pier.inside);
    EXPECT_EQ(in_pier.boundary_group, mesh.find_group(i % 2 == 0 ? "pier_1" : "pier_2"));
  }
  EXPECT_EQ(comparison.failures, 0);
}

}  // namespace
}  // namespace flotsam
