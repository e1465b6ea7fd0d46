// Body geometry and mass (spec 2): mass, inertia, draft from Archimedes, shape factors.
#include "bodies/body_set.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"

namespace flotsam {
namespace {

TEST(BodySet, LogMassInertiaAndDraft) {
  BodySet bodies;
  BodySpec spec;  // log 20 m x 1 m
  spec.density = 500.0;
  bodies.add(spec);
  const double m = 500.0 * pi / 4 * 20;
  EXPECT_NEAR(bodies.mass[0], m, 1e-9);
  EXPECT_NEAR(bodies.inertia[0], m * (400.0 / 12 + 1.0 / 16), 1e-6);
  EXPECT_NEAR(bodies.draft[0], 0.5, 1e-12);  // half as dense as water: floats half-immersed
  EXPECT_NEAR(bodies.submerged_volume(0, 0.5), 0.5 * pi / 4 * 20, 1e-12);
  EXPECT_NEAR(bodies.submerged_volume(0, 7.0), pi / 4 * 20, 1e-12);  // capped at b
}

TEST(BodySet, BoxDraftAndSphericityOfACube) {
  BodySet bodies;
  BodySpec spec;
  spec.shape = Shape::box;
  spec.length = spec.width = spec.height = 2.0;
  spec.density = 250.0;
  bodies.add(spec);
  EXPECT_NEAR(bodies.draft[0], 0.5, 1e-15);  // 250/1000 of 2 m
  EXPECT_NEAR(bodies.inertia[0], 2000.0 * 8.0 / 12, 1e-9);
  EXPECT_NEAR(bodies.sphericity[0], std::cbrt(pi) * std::cbrt(36.0) / 6.0, 1e-12);  // 0.806
  EXPECT_NEAR(bodies.ganser_K2[0],
              std::pow(10.0, 1.8148 * std::pow(-std::log10(bodies.sphericity[0]), 0.5743)), 1e-12);
}

TEST(BodySet, DenserThanWaterGetsItsFullHeight) {
  EXPECT_EQ(floating_draft(Shape::log, 1.0, 1.0, 1200.0, 1000.0), 1.0);
  EXPECT_EQ(floating_draft(Shape::box, 1.0, 3.0, 1000.0, 1000.0), 3.0);
}

TEST(BodySet, IdsAndPerBodyArraysGrowTogether) {
  BodySet bodies;
  BodySpec a;
  a.id = 7;
  bodies.add(a);
  bodies.add(BodySpec{});
  EXPECT_EQ(bodies.id[0], 7);
  EXPECT_EQ(bodies.id[1], 8);
  EXPECT_EQ(bodies.step_size.size(), 2u);
  EXPECT_EQ(bodies.reaction_force.size(), 2u);
  EXPECT_EQ(bodies.state[1], BodyState::floating);
}

}  // namespace
}  // namespace flotsam
