// ctest-label: slow
// The report of issue 42 with the coupled step (subcritical_bump.hpp): the bump on Gmsh's channel
// marched from rest settles after the backflow at the outlet's corner (slow: 2.5 min, the
// coupled step's direct solves on 3,400 nodes).
#include "subcritical_bump.hpp"

namespace flotsam {
namespace {

TEST(SubcriticalBumpMarchedSlow, CoupledGmshChannelSettlesAfterBackflowAtTheOutlet) {
  test::march_bump_on_gmsh_channel(FlowScheme::coupled);
}

}  // namespace
}  // namespace flotsam
