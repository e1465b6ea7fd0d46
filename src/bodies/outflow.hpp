#pragma once
// Bodies leaving the domain (spec 5): a body whose centre G has left through an outflow
// boundary (kind elevation or discharge) is gone and counted; it never comes back. A body
// whose centre is outside through any other boundary (a wall: contacts should have stopped it)
// is reported, not clamped (spec 4.4 step 4): the caller decides what to do with it.
#include <vector>

#include "bodies/body_set.hpp"
#include "flow/flow_field.hpp"

namespace flotsam {

struct OutflowResult {
  int left = 0;            // bodies marked gone now (also added to bodies.outflow_count)
  std::vector<int> stray;  // indices of bodies outside through a non-outflow boundary
};

/// Samples each body's centre at time t; `outflow_groups` are the boundary groups (indices as
/// FlowSample::boundary_group) through which bodies may leave.
OutflowResult remove_outflowing_bodies(BodySet& bodies, const FlowField& flow, double t,
                                       const std::vector<int>& outflow_groups);

}  // namespace flotsam
