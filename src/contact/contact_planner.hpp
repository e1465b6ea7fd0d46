#pragma once
// The contact plan of one flow step (body_integrator.hpp): which bodies may touch one another or a
// wall before the step ends, grouped, and how many contact intervals each group needs so that no
// contact can be tunnelled through.
//
//   reach_i    = s (|u_i| + |omega_i| R_i) dt + s a_i dt^2 / 2     how far body i may move [m]
//   swept box  = footprint box grown by reach_i + margin_i       (broad phase: sweep-and-prune)
//   i, j linked when gap(i, j) <= closing_ij + margin_i + margin_j, with
//   closing_ij = s c_ij dt + s (a_i + a_j) dt^2 / 2
//   c_ij       = |u_i - u_j + omega_j k x (x_j - x_i)| + |omega_i - omega_j| R_i
//                (the smaller of the two orderings, and at most the sum of the two bodies'
//                fastest points, |u_i| + |omega_i| R_i + |u_j| + |omega_j| R_j)
//   i linked to a wall segment when gap(i, segment) <= reach_i + margin_i
//   groups     = connected components of the links (union-find)
//   K_group    = max over its links of the fewest intervals h = dt/K with
//                s (c h + a h^2 / 2) <= l_min / 4     (a = a_i + a_j; at least 1, at most 1000)
//
// c_ij is the largest speed at which a point of i and a point of j at the same place close on
// each other (derived in contact_planner.cpp): bodies turning together as a raft close only by
// the velocity difference that is not their common rotation. R_i is half the body's diagonal;
// gap is the distance between the footprints' bounding boxes, a lower bound of the true one. a_i
// is the acceleration the body's last loads give, (|F_drag| + |F_bed| + |F_x - F_drag|) / m (a log
// pressed into a jam by the drag moves a h^2 / 2 into it within an interval, before the contacts
// stop it again: its intervals are kept short enough for that to stay under l/4). s = 1.5 is a
// safety factor for forces that grow within the step; margin_i = 2 allowed_overlap l_i is the
// contact margin of the narrow phase. Within each interval, then, two linked bodies close by at
// most a quarter of the thinner width: the rule the spec (3.5) sets for every body, applied only
// where something is within reach. Bodies with no link are free.
#include <vector>

#include "bodies/body_integrator.hpp"
#include "bodies/body_set.hpp"
#include "contact/boundary_segments.hpp"
#include "contact/sweep_and_prune.hpp"
#include "io/case.hpp"

namespace flotsam {

class ContactPlanner {
 public:
  /// The schedule of the flow step of length dt [s] starting from the bodies' current state.
  ContactSchedule plan(const BodySet& bodies, const BoundarySegments& walls, double dt,
                       const ContactConfig& config);

 private:
  SweepAndPrune sweep_;
  std::vector<Aabb> footprint_, swept_;
  std::vector<char> active_;
  std::vector<double> reach_, speed_, drift_, spin_, acceleration_;
  std::vector<BodyPair> pairs_;
  std::vector<int> fine_parent_, intervals_, found_, stamp_;
  int stamp_value_ = 0;
};

}  // namespace flotsam
