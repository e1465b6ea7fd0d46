// Islands are the connected components of the contact graph (bodies joined by body-body
// contacts; walls join nothing), checked against a breadth-first search on random graphs.
#include "contact/islands.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <queue>
#include <random>
#include <set>

namespace flotsam {
namespace {

// Random contacts among n bodies: mostly short-range pairs (chains and clusters, as in a jam),
// some walls (b = -1). The segment field numbers the contacts, to follow them through group().
std::vector<ContactConstraint> random_contacts(int n, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> body(0, n - 1), near(1, 4), coin(0, 9);
  std::vector<ContactConstraint> contacts;
  for (int m = 0; m < count; ++m) {
    ContactConstraint c;
    c.a = body(rng);
    c.b = coin(rng) == 0 ? -1 : std::min(n - 1, c.a + near(rng));
    if (c.b == c.a) c.b = -1;
    c.segment = m;
    contacts.push_back(c);
  }
  return contacts;
}

// Component of every body by breadth-first search over the body-body contacts.
std::vector<int> components(int n, const std::vector<ContactConstraint>& contacts) {
  std::vector<std::vector<int>> next(static_cast<std::size_t>(n));
  for (const auto& c : contacts) {
    if (c.b >= 0) next[c.a].push_back(c.b), next[c.b].push_back(c.a);
  }
  std::vector<int> component(static_cast<std::size_t>(n), -1);
  int count = 0;
  for (int s = 0; s < n; ++s) {
    if (component[s] >= 0) continue;
    std::queue<int> queue;
    queue.push(s), component[s] = count;
    while (!queue.empty()) {
      const int i = queue.front();
      queue.pop();
      for (const int j : next[i]) {
        if (component[j] < 0) component[j] = count, queue.push(j);
      }
    }
    ++count;
  }
  return component;
}

TEST(Islands, AreTheConnectedComponentsOfTheContactGraph) {
  for (unsigned seed = 1; seed <= 50; ++seed) {
    const int n = 10 + static_cast<int>(seed) * 7;
    std::vector<ContactConstraint> contacts = random_contacts(n, n * 3 / 4, seed);
    const std::vector<int> component = components(n, contacts);
    std::set<int> with_contacts;
    for (const auto& c : contacts) with_contacts.insert(component[c.a]);

    const std::vector<ContactConstraint> before = contacts;
    Islands islands;
    islands.group(contacts, n);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    ASSERT_EQ(islands.count(), static_cast<int>(with_contacts.size()));
    ASSERT_EQ(contacts.size(), before.size());
    std::set<int> seen_components, seen_contacts;
    for (int k = 0; k < islands.count(); ++k) {
      const auto island = islands.island(contacts, k);
      ASSERT_FALSE(island.empty());
      const int own = component[island.front().a];
      EXPECT_TRUE(seen_components.insert(own).second);  // one island per component
      int last = -1;
      for (const ContactConstraint& c : island) {
        EXPECT_EQ(component[c.a], own);
        if (c.b >= 0) {
          EXPECT_EQ(component[c.b], own);
        }
        EXPECT_GT(c.segment, last);  // the contacts' order is kept within an island
        last = c.segment;
        EXPECT_TRUE(seen_contacts.insert(c.segment).second);  // each contact once
      }
    }
    EXPECT_EQ(seen_contacts.size(), before.size());
  }
}

// group() touches only the bodies of its contacts (a small group's step costs its own size): one
// object used for contact sets of different bodies in turn must give what a fresh one gives.
TEST(Islands, AReusedObjectGroupsAsAFreshOne) {
  Islands reused;
  const int n = 400;
  for (unsigned seed = 1; seed <= 50; ++seed) {
    std::vector<ContactConstraint> contacts = random_contacts(n, 3 + 7 * (seed % 13), seed);
    std::vector<ContactConstraint> again = contacts;
    Islands fresh;
    fresh.group(contacts, n);
    reused.group(again, n);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    ASSERT_EQ(reused.count(), fresh.count());
    ASSERT_EQ(reused.largest_first(), fresh.largest_first());
    for (std::size_t m = 0; m < contacts.size(); ++m)
      EXPECT_EQ(again[m].segment, contacts[m].segment);
  }
}

TEST(Islands, ALogAgainstAPierAndAnotherAgainstTheSamePierAreTwoIslands) {
  std::vector<ContactConstraint> contacts(2);
  contacts[0].a = 0, contacts[0].b = -1, contacts[0].segment = 7;
  contacts[1].a = 1, contacts[1].b = -1, contacts[1].segment = 7;
  Islands islands;
  islands.group(contacts, 2);
  EXPECT_EQ(islands.count(), 2);
}

TEST(Islands, AreHandedOutLargestFirst) {
  std::vector<ContactConstraint> contacts(4);
  contacts[0].a = 0, contacts[0].b = -1;  // island of body 0: one contact
  contacts[1].a = 1, contacts[1].b = 2;   // island of bodies 1, 2, 3: three contacts
  contacts[2].a = 2, contacts[2].b = 3;
  contacts[3].a = 3, contacts[3].b = -1;
  Islands islands;
  islands.group(contacts, 4);
  ASSERT_EQ(islands.count(), 2);
  EXPECT_EQ(islands.largest_first(), (std::vector<int>{1, 0}));
  EXPECT_EQ(islands.largest(), 3);
}

// number() (the contact world's narrow phase builds its contacts straight into their islands'
// order with it) puts each contact where group() moves it, from the contacts' bodies alone.
TEST(Islands, NumberingByTheBodiesGivesTheOrderOfGroup) {
  const int n = 400;
  for (unsigned seed = 1; seed <= 50; ++seed) {
    const std::vector<ContactConstraint> contacts = random_contacts(n, 3 + 7 * (seed % 13), seed);
    std::vector<ContactConstraint> grouped = contacts;
    Islands by_contacts, by_bodies;
    by_contacts.group(grouped, n);
    std::vector<BodyPair> ends;
    for (const ContactConstraint& c : contacts) ends.emplace_back(c.a, c.b);
    const std::vector<int> destination = by_bodies.number(ends, n);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    ASSERT_EQ(by_bodies.count(), by_contacts.count());
    ASSERT_EQ(by_bodies.largest_first(), by_contacts.largest_first());
    ASSERT_EQ(destination.size(), contacts.size());
    for (std::size_t m = 0; m < contacts.size(); ++m)  // the segment field numbers the contacts
      EXPECT_EQ(grouped[static_cast<std::size_t>(destination[m])].segment, contacts[m].segment);
  }
}

// From 2,000 contacts number() runs on the threads (a union-find joined by compare-and-swap): the
// same islands and places as the definition gives, islands in the order of their first contact
// and each keeping its contacts' order, on 1 and 2 threads.
TEST(Islands, NumberingOnTheThreadsGivesTheDefinitionsOrder) {
  const int n = 6000;
  const std::vector<ContactConstraint> contacts = random_contacts(n, 5000, 3);
  const std::vector<int> component = components(n, contacts);
  std::vector<int> island_of_component(static_cast<std::size_t>(n), -1), size;
  std::vector<int> island(contacts.size());
  for (std::size_t m = 0; m < contacts.size(); ++m) {
    int& k = island_of_component[static_cast<std::size_t>(component[contacts[m].a])];
    if (k < 0) k = static_cast<int>(size.size()), size.push_back(0);
    island[m] = k, ++size[static_cast<std::size_t>(k)];
  }
  std::vector<int> next(size.size() + 1, 0), expected(contacts.size());
  for (std::size_t k = 0; k < size.size(); ++k) next[k + 1] = next[k] + size[k];
  for (std::size_t m = 0; m < contacts.size(); ++m)
    expected[m] = next[static_cast<std::size_t>(island[m])]++;
  std::vector<BodyPair> ends;
  for (const ContactConstraint& c : contacts) ends.emplace_back(c.a, c.b);
  ASSERT_GT(size.size(), 100u);  // many islands, some of many contacts
  ASSERT_GT(*std::max_element(size.begin(), size.end()), 10);
  const int old_threads = omp_get_max_threads();
  for (const int threads : {1, 2}) {
    omp_set_num_threads(threads);
    Islands islands;
    const std::vector<int> destination = islands.number(ends, n);
    EXPECT_EQ(islands.count(), static_cast<int>(size.size())) << threads << " threads";
    EXPECT_EQ(destination, expected) << threads << " threads";
  }
  omp_set_num_threads(old_threads);
}

}  // namespace
}  // namespace flotsam
