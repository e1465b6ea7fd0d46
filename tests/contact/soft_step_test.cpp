// The soft step (src/contact/soft_step.hpp, `bodies.contact.solver: soft_step`): a resting column
// carries the analytic load, no contact gains energy, a free collision keeps momentum, and the
// colours solved in parallel give the same result on one and two threads.
#include "contact/soft_step.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../support/thrown_jam.hpp"
#include "contact/contact_world.hpp"
#include "contact/jam_scene.hpp"
#include "core/constants.hpp"

namespace flotsam {
namespace {

ContactConfig soft_config() {
  ContactConfig config = jam_contact_config();
  config.solver = ContactSolverKind::soft_step;
  return config;
}

// N logs 10 m x 0.5 m lying across a channel, in a column touching a wall at x = 0, each pushed
// along +x by m a (jam_push): at rest, the wall carries N m a and the contact behind log k the
// push of the N - 1 - k logs behind it (static equilibrium of the column). Each contact's impulse
// over the interval h is its force times h; tolerance 0.1 % of N m a h.
TEST(SoftStep, AColumnOfLogsAtRestCarriesTheSumOfThePushesBehindEachContact) {
  constexpr int N = 20;
  JamScene scene;
  scene.walls.group_names = {"wall"};
  scene.walls.add_segment({0.0, -20.0}, {0.0, 20.0}, 0);  // water on the left: x < 0
  scene.walls.build_grid(2.0);
  for (int k = 0; k < N; ++k) {
    scene.bodies.add(BodySpec{
        .length = 10.0, .width = 0.5, .position = {-0.25 - 0.5 * k, 0.0}, .angle = 0.5 * pi});
  }
  ContactWorld world(soft_config());
  double h = 0.0;  // [s]
  for (int step = 0; step < 1500; ++step) {
    h = move_jam_logs(scene);
    world.step(scene.bodies, scene.walls, h);
  }
  const double m = scene.bodies.mass[0];    // [kg]
  const double unit = m * jam_push * h;     // one log's push over the interval [N s]
  std::vector<double> carried(N + 1, 0.0);  // [N s]: index k = contact in front of log k
  for (const ContactConstraint& c : world.contacts()) {
    double impulse = 0.0;
    for (int p = 0; p < c.point_count; ++p)
      impulse += c.points[static_cast<std::size_t>(p)].normal_impulse;
    const int front = c.b < 0 ? 0 : std::min(c.a, c.b) + 1;  // the wall, or log j's back
    carried[front] += impulse;
  }
  EXPECT_NEAR(carried[0], N * unit, 1e-3 * N * unit);
  for (int k = 1; k < N; ++k) EXPECT_NEAR(carried[k], (N - k) * unit, 1e-3 * N * unit) << k;
  double fastest = 0.0;  // [m/s]
  for (int i = 0; i < N; ++i) fastest = std::max(fastest, scene.bodies.velocity[i].norm());
  EXPECT_LT(fastest, 1e-5);
}

double kinetic_energy(const BodySet& b) {  // [J]
  double e = 0.0;
  for (int i = 0; i < b.size(); ++i)
    e += 0.5 * (b.mass[i] * b.velocity[i].squaredNorm() +
                b.inertia[i] * b.angular_velocity[i] * b.angular_velocity[i]);
  return e;
}

// Two logs (or a log and a wall) meeting at random: placements from 1 cm apart to 1 cm into each
// other, any angles, speeds up to 2 m/s, spins, e in {0, 0.3, 1} (at a wall too: the restitution
// is bounded by the energy the compression took, restitution_energy.hpp), friction 0.5. One contact
// step of a new world: the kinetic energy never grows (to rounding, 1e-12 relative), and between
// two logs the linear and the angular momentum (about the origin, at the poses the impulses acted
// at) are kept to 1e-12 relative.
TEST(SoftStep, NoContactGainsEnergyAndAFreeCollisionKeepsMomentum) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  BoundarySegments walls;
  walls.group_names = {"wall"};
  walls.add_segment({0.0, -30.0}, {0.0, 30.0}, 0);
  walls.build_grid(2.0);
  const BoundarySegments none;
  int struck = 0;
  for (int trial = 0; trial < 600; ++trial) {
    ContactConfig config = soft_config();
    const bool wall = trial % 2 == 1;
    config.restitution = std::array{0.0, 0.3, 1.0}[(wall ? trial / 2 : trial) % 3];
    BodySet b;
    const double angle = pi * unit(rng);  // [rad]
    b.add(BodySpec{.length = 10.0,
                   .width = 0.5,
                   .position = {-6.0, 0.0},
                   .angle = angle,
                   .velocity = {2.0 * std::abs(unit(rng)), 0.5 * unit(rng)},
                   .angular_velocity = 0.3 * unit(rng)});
    // Slide the log along x until its nearest point is at the chosen gap from x = 0.
    const Vec2 u = b.axis(0), half = b.half_extents(0);
    const double reach = std::abs(u.x()) * half.x() + std::abs(u.y()) * half.y();  // [m]
    const double gap = 0.01 * unit(rng);                                           // [m]
    b.position[0].x() = -reach - gap;
    if (!wall) {
      b.add(BodySpec{.length = 10.0,
                     .width = 0.5,
                     .position = {5.0 + 0.3 * unit(rng), 3.0 * unit(rng)},
                     .angle = 0.5 * pi + 0.3 * unit(rng),
                     .velocity = {-std::abs(unit(rng)), 0.5 * unit(rng)},
                     .angular_velocity = 0.3 * unit(rng)});
      const Vec2 w = b.axis(1), half_b = b.half_extents(1);
      b.position[1].x() = std::abs(w.x()) * half_b.x() + std::abs(w.y()) * half_b.y() + gap;
    }
    auto momentum = [&] {
      Vec2 p = Vec2::Zero();
      double L = 0.0;
      for (int i = 0; i < b.size(); ++i) {
        p += b.mass[i] * b.velocity[i];
        L += b.mass[i] * cross(b.position[i], b.velocity[i]) + b.inertia[i] * b.angular_velocity[i];
      }
      return std::pair{p, L};
    };
    const std::vector<Vec2> poses = b.position;
    const double e0 = kinetic_energy(b);
    const auto [p0, L0] = momentum();
    ContactWorld world(config);
    world.step(b, wall ? walls : none, 0.02);
    struck += world.profile().points > 0;
    EXPECT_LE(kinetic_energy(b), e0 * (1.0 + 1e-12)) << "trial " << trial;
    if (wall) continue;
    const std::vector<Vec2> moved = b.position;
    b.position = poses;
    const auto [p1, L1] = momentum();
    b.position = moved;
    const double scale = b.mass[0] * 2.0;  // [kg m/s]
    EXPECT_NEAR((p1 - p0).norm(), 0.0, 1e-12 * scale) << "trial " << trial;
    EXPECT_NEAR(L1, L0, 1e-12 * scale * 10.0) << "trial " << trial;
  }
  EXPECT_GT(struck, 250);  // the contacts were found
}

// The colours of one island are solved in parallel (contact/contact_colours.hpp): the result is
// the same, bit for bit, on 1 and 2 threads. 2,100 logs packed in rows before 43 piers (one
// island, over 2,000 contacts and 2,000 bodies: the parallel paths of the solver and of the
// detection, boxes, wall pairs and islands included), thrown about at up to 1 m/s, 10 steps.
BodySet thrown_logs_after(int threads, int& most_contacts) {
  const auto contacts = [](const ContactProfile& p) { return p.contacts; };
  return test::stepped_on_threads(test::thrown_jam_scene(2100, 43, 0.0),  // row gap [m]
                                  soft_config(), threads, 10, contacts, most_contacts);
}

TEST(SoftStep, ColoursSolvedInParallelGiveTheSameResultOnOneAndTwoThreads) {
  int contacts_1 = 0, contacts_2 = 0;
  const BodySet one = thrown_logs_after(1, contacts_1);
  const BodySet two = thrown_logs_after(2, contacts_2);
  EXPECT_GE(contacts_2, 2000);  // the parallel path ran (soft_step.cpp: parallel_contacts)
  EXPECT_EQ(contacts_1, contacts_2);
  EXPECT_EQ(test::count_different_states(one, two), 0);  // exact equality, not a tolerance
}

// Colours: no two contacts of one colour share a movable body; walls and anchored bodies join
// nothing.
TEST(SoftStep, NoTwoContactsOfAColourShareAMovableBody) {
  std::vector<ContactConstraint> contacts;
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> body(0, 39);
  for (int k = 0; k < 400; ++k) {
    ContactConstraint c;
    c.a = body(rng);
    c.b = k % 5 == 0 ? -1 : body(rng);
    if (c.b == c.a) c.b = -1;
    contacts.push_back(c);
  }
  std::vector<char> movable(40, 1);
  movable[7] = 0;  // anchored
  ContactColours colours;
  colours.assign(contacts, movable);
  std::vector<int> seen(contacts.size(), 0);
  for (int g = 0; g < colours.groups(); ++g) {
    std::vector<int> users(40, 0);
    for (int k = colours.start(g); k < colours.start(g + 1); ++k) {
      const ContactConstraint& c = contacts[static_cast<std::size_t>(colours.order()[k])];
      ++seen[static_cast<std::size_t>(colours.order()[k])];
      if (colours.is_overflow(g)) continue;
      if (movable[c.a]) {
        EXPECT_EQ(users[c.a]++, 0);
      }
      if (c.b >= 0 && movable[c.b]) {
        EXPECT_EQ(users[c.b]++, 0);
      }
    }
  }
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), 400);  // each contact once
}

}  // namespace
}  // namespace flotsam
