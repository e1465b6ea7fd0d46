// Verifies that sort-and-sweep detection returns exactly the pairs brute force returns, on
// 10,000 random bodies in several configurations, and keeps doing so as the bodies move.
#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "contact/contact_world.hpp"

namespace flotsam {
namespace {

struct Layout {
  const char* name;
  double extent;  // [m] side of the square the centres are drawn in
  bool aligned;   // every body along x
  bool lattice;   // exactly touching boxes on a lattice
};

BodySet make_bodies(const Layout& layout, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  BodySet bodies;
  const int side = 100;
  for (int k = 0; k < count; ++k) {
    BodySpec b;
    if (layout.lattice) {  // 4 m x 1 m boxes, exactly abutting: powers of two, exact sums
      b.length = 4.0, b.width = 1.0;
      b.position = {4.0 * (k % side), 1.0 * (k / side)};
    } else {
      b.length = 1.0 + 19.0 * unit(rng);
      b.width = 0.2 + 0.8 * unit(rng);
      b.position = {layout.extent * unit(rng), layout.extent * unit(rng)};
      b.angle = layout.aligned ? 0.0 : 6.283185307179586 * unit(rng);
    }
    bodies.add(b);
  }
  return bodies;
}

std::vector<BodyPair> sorted(std::vector<BodyPair> pairs) {
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::vector<BodyPair> contact_pairs(const ContactWorld& world) {
  std::vector<BodyPair> pairs;
  for (const ContactConstraint& c : world.contacts()) {
    if (c.b >= 0) pairs.emplace_back(c.a, c.b);
  }
  return sorted(pairs);
}

TEST(SweepAndPrune, SamePairsAsBruteForceOnTenThousandBodies) {
  const Layout layouts[] = {{"dense", 300.0, false, false},
                            {"sparse", 5000.0, false, false},
                            {"aligned", 400.0, true, false},
                            {"touching", 0.0, false, true}};
  for (const Layout& layout : layouts) {
    SCOPED_TRACE(layout.name);
    BodySet bodies = make_bodies(layout, 10000, 7);
    ContactWorld sweep{ContactConfig{}}, brute{ContactConfig{}};
    brute.set_broad_phase(BroadPhase::brute_force);
    for (int round = 0; round < 2; ++round) {  // second round: order kept from the first
      sweep.detect(bodies, BoundarySegments{});
      brute.detect(bodies, BoundarySegments{});
      ASSERT_EQ(sorted(sweep.body_pairs()), sorted(brute.body_pairs()));
      ASSERT_EQ(contact_pairs(sweep), contact_pairs(brute));
      EXPECT_GT(brute.body_pairs().size(), 0u);
      for (int i = 0; i < bodies.size(); ++i) bodies.position[i].x() += 0.01 * (i % 7);
    }
  }
}

// The sweep runs in parallel from 2,000 boxes (sweep_and_prune.cpp): the pairs come out in the
// same order on 1 and 2 threads (the contacts, and so the solve, follow that order).
TEST(SweepAndPrune, SamePairsInTheSameOrderOnOneAndTwoThreads) {
  const BodySet bodies = make_bodies({"dense", 300.0, false, false}, 10000, 11);
  std::vector<Aabb> boxes;
  for (int i = 0; i < bodies.size(); ++i) {
    const Vec2 u = bodies.axis(i), h = bodies.half_extents(i);
    const Vec2 extent(std::abs(u.x()) * h.x() + std::abs(u.y()) * h.y(),
                      std::abs(u.y()) * h.x() + std::abs(u.x()) * h.y());
    boxes.push_back({bodies.position[i] - extent, bodies.position[i] + extent});
  }
  const std::vector<char> active(boxes.size(), 1);
  std::vector<BodyPair> pairs[2];
  for (int threads = 1; threads <= 2; ++threads) {
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
    SweepAndPrune sweep;
    sweep.find_pairs(boxes, active, pairs[threads - 1]);
    omp_set_num_threads(before);
  }
  EXPECT_GT(pairs[0].size(), 10000u);
  EXPECT_EQ(pairs[0], pairs[1]);  // the same pairs in the same order
}

// A contact group's detection lists its bodies (find_pairs with `listed`): one sweep used for
// groups of different bodies in turn, and for all of them, finds what brute force finds.
TEST(SweepAndPrune, ListedGroupsInTurnGiveTheBruteForcePairs) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int n = 2000;
  std::vector<Aabb> boxes(static_cast<std::size_t>(n));
  for (Aabb& b : boxes) {
    const Vec2 c(400.0 * unit(rng), 400.0 * unit(rng)),
        h(0.5 + 10.0 * unit(rng), 0.5 + 10.0 * unit(rng));
    b = {c - h, c + h};
  }
  SweepAndPrune sweep;
  std::vector<BodyPair> found, expected;
  for (int round = 0; round < 40; ++round) {
    SCOPED_TRACE(::testing::Message() << "round " << round);
    std::vector<char> active(static_cast<std::size_t>(n), 0);
    std::vector<int> listed;
    const double share = round % 5 == 4 ? 1.0 : 0.01 + 0.1 * unit(rng);  // [-] of the bodies
    for (int i = 0; i < n; ++i) {
      if (unit(rng) < share) active[i] = 1, listed.push_back(i);
    }
    sweep.find_pairs(boxes, active, listed, found);
    brute_force_pairs(boxes, active, expected);
    ASSERT_EQ(sorted(found), sorted(expected));
    for (Aabb& b : boxes) {  // the bodies move on a little
      const Vec2 d(unit(rng) - 0.5, unit(rng) - 0.5);
      b = {b.lower + d, b.upper + d};
    }
  }
}

// The sweep meets only the boxes of each box's bands (sweep_and_prune.hpp): on a wide jam whose
// boxes span one to many bands, and on boxes lying exactly on the bands' edges, it emits the
// pairs of one plain sweep over its order, in that sweep's order (the contacts, and so the
// solve's bits, follow it).
TEST(SweepAndPrune, BandsGiveThePairsOfOnePlainSweepInItsOrder) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const double long_side : {2.0, 20.0, 400.0}) {  // [m] up to most of the other axis
    SCOPED_TRACE(::testing::Message() << "long side " << long_side);
    std::vector<Aabb> boxes;
    for (int i = 0; i < 6000; ++i) {  // spread along x (the sweep axis), 500 m across y
      const Vec2 c(5000.0 * unit(rng), 500.0 * unit(rng));
      const Vec2 h = unit(rng) < 0.5 ? Vec2(0.5, 0.5 * long_side) : Vec2(0.5 * long_side, 0.5);
      boxes.push_back({c - h, c + h});
    }
    for (int i = 0; i < 200; ++i) boxes.push_back({Vec2(2.0 * i, 0.0), Vec2(2.0 * i + 4.0, 250.0)});
    const std::vector<char> active(boxes.size(), 1);
    for (int threads = 1; threads <= 2; ++threads) {
      const int before = omp_get_max_threads();
      omp_set_num_threads(threads);
      SweepAndPrune sweep;
      std::vector<BodyPair> found;
      sweep.find_pairs(boxes, active, found);
      omp_set_num_threads(before);
      ASSERT_EQ(sweep.axis(), 0);
      std::vector<BodyPair> plain;  // for k in order, for m after k while open: (k, m)
      const std::vector<int>& order = sweep.order();
      for (std::size_t k = 0; k < order.size(); ++k) {
        const Aabb& a = boxes[order[k]];
        for (std::size_t m = k + 1; m < order.size() && boxes[order[m]].lower.x() <= a.upper.x();
             ++m) {
          if (a.overlaps(boxes[order[m]]))
            plain.emplace_back(std::min(order[k], order[m]), std::max(order[k], order[m]));
        }
      }
      EXPECT_GT(plain.size(), 1000u);
      EXPECT_EQ(found, plain);
    }
  }
}

TEST(SweepAndPrune, ExactlyTouchingNeighboursAreInContact) {
  // 100 x 100 lattice of 4 m x 1 m boxes: each touches its neighbours along whole edges.
  const BodySet bodies = make_bodies({"touching", 0.0, false, true}, 10000, 1);
  ContactWorld world{ContactConfig{}};
  world.detect(bodies, BoundarySegments{});
  const std::vector<BodyPair> found = contact_pairs(world);
  int missing = 0;
  for (int k = 0; k < 10000; ++k) {
    if (k % 100 != 99 && !std::binary_search(found.begin(), found.end(), BodyPair(k, k + 1))) {
      ++missing;
    }
    if (k + 100 < 10000 && !std::binary_search(found.begin(), found.end(), BodyPair(k, k + 100))) {
      ++missing;
    }
  }
  EXPECT_EQ(missing, 0);
}

}  // namespace
}  // namespace flotsam
