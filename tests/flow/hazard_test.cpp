// Flood hazard (flow/hazard.hpp): exact values on hand-made states at each class boundary, and
// the envelopes' hazard: the largest over the sub-steps of the value at each sub-step, not the
// value of the largest depth and speed.
#include "flow/hazard.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "flow/flood_envelope.hpp"

namespace flotsam {
namespace {

TEST(Hazard, DebrisFactorCountsOnlyWhereABodyIsAndTheWaterIsDeeperThanAQuarterMetre) {
  EXPECT_EQ(debris_factor(0.25, true), 0.0);  // FD2321: 0 up to 0.25 m
  EXPECT_EQ(debris_factor(0.2501, true), 1.0);
  EXPECT_EQ(debris_factor(3.0, true), 1.0);
  EXPECT_EQ(debris_factor(3.0, false), 0.0);
}

TEST(Hazard, UkRatingAndItsFourClassesAtTheirBoundaries) {
  EXPECT_DOUBLE_EQ(hazard_rating(0.5, 1.0, 0.0), 0.75);  // d (v + 0.5)
  EXPECT_DOUBLE_EQ(hazard_rating(0.5, 1.0, 1.0), 1.75);  // + DF
  EXPECT_DOUBLE_EQ(hazard_rating(0.0, 3.0, 0.0), 0.0);
  EXPECT_EQ(hazard_rating_class(0.7499), 1);  // low
  EXPECT_EQ(hazard_rating_class(0.75), 2);    // moderate from 0.75
  EXPECT_EQ(hazard_rating_class(1.25), 2);    // ... to 1.25
  EXPECT_EQ(hazard_rating_class(1.2501), 3);  // significant
  EXPECT_EQ(hazard_rating_class(2.0), 3);
  EXPECT_EQ(hazard_rating_class(2.0001), 4);  // extreme
  // A body in a cell 0.5 m deep at 0.5 m/s: 0.5 + DF 1 = 1.5, significant; without it, moderate.
  EXPECT_EQ(hazard_rating_class(hazard_rating(0.5, 0.5, debris_factor(0.5, true))), 3);
  EXPECT_EQ(hazard_rating_class(hazard_rating(0.5, 0.5, debris_factor(0.5, false))), 1);
}

TEST(Hazard, AustralianClassesAtEachLimitOfDepthSpeedAndTheirProduct) {
  EXPECT_EQ(australian_hazard_class(0.3, 1.0), 1);   // d = 0.3, dv = 0.3: H1's limits, inclusive
  EXPECT_EQ(australian_hazard_class(0.31, 0.1), 2);  // deeper than 0.3 m
  EXPECT_EQ(australian_hazard_class(0.2, 1.6), 2);   // dv = 0.32 > 0.3
  EXPECT_EQ(australian_hazard_class(0.1, 2.0), 1);   // v = 2.0, inclusive
  EXPECT_EQ(australian_hazard_class(0.1, 2.01), 5);  // faster than 2 m/s: H5 (v <= 4)
  EXPECT_EQ(australian_hazard_class(0.5, 1.2), 2);   // d = 0.5, dv = 0.6
  EXPECT_EQ(australian_hazard_class(0.51, 0.1), 3);  // deeper than 0.5 m
  EXPECT_EQ(australian_hazard_class(1.2, 0.5), 3);   // d = 1.2, dv = 0.6
  EXPECT_EQ(australian_hazard_class(1.2, 0.51), 4);  // dv = 0.612 > 0.6
  EXPECT_EQ(australian_hazard_class(1.21, 0.0), 4);
  EXPECT_EQ(australian_hazard_class(2.0, 0.5), 4);  // d = 2.0, dv = 1.0
  EXPECT_EQ(australian_hazard_class(2.0, 0.51), 5);
  EXPECT_EQ(australian_hazard_class(4.0, 1.0), 5);  // d = 4, dv = 4, v <= 4
  EXPECT_EQ(australian_hazard_class(1.0, 4.0), 5);
  EXPECT_EQ(australian_hazard_class(4.01, 0.0), 6);
  EXPECT_EQ(australian_hazard_class(1.0, 4.01), 6);
  EXPECT_EQ(australian_hazard_class(2.0, 2.01), 6);  // dv = 4.02
}

TEST(Hazard, VehiclesLoseStabilityFromTheSmallestUp) {
  EXPECT_EQ(unstable_vehicle_class(0.3, 1.0), 0);   // small car's limits: d 0.3, dv 0.3
  EXPECT_EQ(unstable_vehicle_class(0.31, 0.0), 1);  // deeper than the small car's still water
  EXPECT_EQ(unstable_vehicle_class(0.15, 2.1), 1);  // dv = 0.315 > 0.3
  EXPECT_EQ(unstable_vehicle_class(0.15, 3.0), 1);  // dv = 0.45, v = 3: large car still stands
  EXPECT_EQ(unstable_vehicle_class(0.4, 1.13), 2);  // dv = 0.452 > 0.45
  EXPECT_EQ(unstable_vehicle_class(0.41, 0.0), 2);
  EXPECT_EQ(unstable_vehicle_class(0.5, 1.2), 2);  // 4WD's limits: d 0.5, dv 0.6
  EXPECT_EQ(unstable_vehicle_class(0.51, 0.0), 3);
  EXPECT_EQ(unstable_vehicle_class(0.05, 3.01), 3);  // faster than 3 m/s: none stands
}

// A cell whose depth peaks after its speed (AIDR 7-3 Fig. 4): the envelope keeps the largest of
// each sub-step's hazard, below what the largest depth with the largest speed would give. Two
// coupling steps, of two and three sub-steps; a body lies on cell 0 during the second.
TEST(Hazard, EnvelopeKeepsTheLargestHazardOfAnySubStepNotOfTheLargestDepthAndSpeed) {
  const std::vector<double> depth = {0.2, 0.6, 1.0, 1.5, 1.2};  // [m]
  const std::vector<double> speed = {2.5, 1.8, 0.9, 0.3, 0.2};  // [m/s]
  FloodEnvelope e;
  e.reset(2, 0.01);
  double hr0 = 0.0, hr1 = 0.0;
  int au = 0, cars = 0;
  for (std::size_t k = 0; k < depth.size(); ++k) {
    if (k == 0 || k == 2) e.start_step();
    const double d = depth[k], q = d * speed[k];
    e.update({d, d}, {q, q}, {0.0, 0.0}, 1.0 + k, 1.0);
    if (k == 1) e.end_step({0, 0});
    if (k == 4) e.end_step({1, 0});
    hr0 = std::max(hr0, hazard_rating(d, speed[k], debris_factor(d, k >= 2)));
    hr1 = std::max(hr1, hazard_rating(d, speed[k], 0.0));
    au = std::max(au, australian_hazard_class(d, speed[k]));
    cars = std::max(cars, unstable_vehicle_class(d, speed[k]));
  }
  EXPECT_DOUBLE_EQ(e.max_hazard_rating[0], hr0);
  EXPECT_DOUBLE_EQ(e.max_hazard_rating[0], 1.0 * 1.4 + 1.0);  // the third sub-step, with DF 1
  EXPECT_DOUBLE_EQ(e.max_hazard_rating[1], hr1);
  EXPECT_DOUBLE_EQ(e.max_hazard_rating[1], 1.0 * 1.4);              // the third, no debris
  EXPECT_LT(e.max_hazard_rating[1], hazard_rating(1.5, 2.5, 0.0));  // max d with max v: 4.5
  EXPECT_EQ(e.australian_class[1], au);
  EXPECT_EQ(e.australian_class[1], 5.0);  // 0.2 m at 2.5 m/s: faster than H4's 2 m/s
  EXPECT_EQ(e.vehicle_class[1], cars);
  EXPECT_EQ(e.vehicle_class[1], 3.0);  // 1.5 m deep floats every vehicle
  const std::vector<double> rating = e.hazard_rating_class();
  EXPECT_EQ(rating[0], 4.0);  // 2.4 > 2: extreme
  EXPECT_EQ(rating[1], 3.0);  // 1.4: significant
}

TEST(Hazard, CellsNeverWetHaveNoClassAndFilmsNoSpeed) {
  FloodEnvelope e;
  e.reset(1, 0.05);
  e.start_step();
  e.update({0.04}, {0.4}, {0.0}, 1.0, 1.0);  // a film at a numerical 10 m/s
  e.end_step({1});
  EXPECT_DOUBLE_EQ(e.max_hazard_rating[0], 0.04 * 0.5);
  EXPECT_EQ(e.australian_class[0], 0.0);
  EXPECT_EQ(e.vehicle_class[0], 0.0);
  EXPECT_EQ(e.hazard_rating_class()[0], 0.0);
}

}  // namespace
}  // namespace flotsam
