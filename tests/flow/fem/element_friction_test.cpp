// The FEM engine's friction over the domain (docs/model.md "Friction over the domain"): each
// element takes the coefficient at the centroid of its corners, the zone's where a zone holds it,
// else the default (exact: coefficients are copied); without friction there are none.
#include <gtest/gtest.h>

#include "flow/fem/shallow_water_solver.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

TEST(ElementFriction, EachElementTakesTheCoefficientAtItsCentroid) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 20.0, 10.0, 20, 10, true});
  Case c;
  c.flow.initial_eta_start = c.flow.initial_eta_end = 1.0;
  c.flow.friction = FrictionLaw::chezy;
  c.flow.friction_coefficient = 40.0;  // C [m^1/2 s^-1]
  c.flow.friction_map.zones = {{{{3, 2}, {9, 2}, {9, 7}, {3, 7}}, {}, 25.0, "zone"}};
  const ShallowWaterSolver solver(mesh, c);
  const std::vector<double>& k = solver.friction_coefficients();
  ASSERT_EQ(static_cast<int>(k.size()), mesh.element_count());
  int in_zone = 0;
  for (int e = 0; e < mesh.element_count(); ++e) {
    const auto& el = mesh.elements[e];
    const Vec2 p = (mesh.nodes[el[0]] + mesh.nodes[el[1]] + mesh.nodes[el[2]]) / 3.0;
    const bool inside = p.x() > 3 && p.x() < 9 && p.y() > 2 && p.y() < 7;
    EXPECT_EQ(k[e], inside ? 25.0 : 40.0) << "element " << e;
    in_zone += inside;
  }
  EXPECT_EQ(in_zone, 6 * 5 * 2);
  c.flow.friction = FrictionLaw::none;
  EXPECT_TRUE(ShallowWaterSolver(mesh, c).friction_coefficients().empty());
}

}  // namespace
}  // namespace flotsam
