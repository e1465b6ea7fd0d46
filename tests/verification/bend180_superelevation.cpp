// Verifies that in the 180-degree bend (spec 8.1, examples/bend180.yaml: Rozovskii's flume,
// B = 0.8 m, inner radius R_i = 0.4 m, centre-line radius R_c = 0.8 m, Q = 0.0123 m^3/s, outlet
// depth 0.058 m) the steady water surface stands higher at the outer bank than at the inner bank,
// and the velocity maximum sits near the inner bank, at the bend's apex.
//
// Reference. The radial balance g d eta/dr = u^2 / r with the irrotational (free-vortex) velocity
// of a bend, u = C / r, C = Q / (H ln(R_o/R_i)), gives
//     Delta eta = C^2 / (2 g) (1/R_i^2 - 1/R_o^2),
// whose leading term for B << R_c is the spec's U^2 B / (g R_c) (U = Q / (B H)). This bend is
// sharp (R_c / B = 1): the free vortex gives 1.47 U^2 B / (g R_c). The test asserts the
// free-vortex value within 10%, and reports the ratio to U^2 B / (g R_c) (issue 3 asks for 30%
// of it; docs/validation.md explains why the sharp bend exceeds that). H is the section's mean
// depth at the apex. The mesh is coarsened to 0.08 m (the case's 0.04 m; the super-elevation
// changes by 3% between them) to keep the test under a few seconds.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <string>

#include "flow/fem/shallow_water_solver.hpp"
#include "io/case_file.hpp"
#include "mesh/interpolation.hpp"
#include "mesh/mesh_generator.hpp"
#include "mesh/point_locator.hpp"

namespace flotsam {
namespace {

TEST(Bend180, OuterBankStandsHigherByTheSuperElevation) {
  Case c = read_case(FLOTSAM_SOURCE_DIR "/examples/bend180.yaml");
  c.mesh.bend.mesh_size = 0.08;  // [m]
  const int threads = omp_get_max_threads();
  const Mesh mesh = generate_mesh(c.mesh);
  omp_set_num_threads(threads);  // Gmsh leaves the process at one thread
  ShallowWaterSolver solver(mesh, c);
  solver.initialize();
  const SteadyReport report = solver.solve_steady();
  ASSERT_TRUE(report.converged) << report.residuals.back();

  const BendGeometry& bend = c.mesh.bend;
  const double B = bend.width, R_i = bend.inner_radius, R_o = R_i + B;  // [m]
  const double R_c = R_i + 0.5 * B;                                     // [m]
  double Q = 0.0;                                                       // [m^3/s]
  for (const auto& b : c.flow.boundaries)
    if (b.group == "inflow") Q = b.value(0.0);
  ASSERT_GT(Q, 0.0);

  // The apex of the bend: the ray from the centre along -x.
  const PointLocator locator(mesh);
  const auto at = [&](double r) {
    const Location where = locator.locate(bend.centre + Vec2(-r, 0.0));
    EXPECT_TRUE(where.inside) << r;
    return where;
  };
  const auto eta_at = [&](double r) { return interpolate_p1(mesh, at(r), solver.eta()); };
  const auto speed_at = [&](double r) {
    return interpolate_p2(mesh, at(r), solver.u(), solver.v()).norm();
  };
  // Mean depth across the apex (flat bed z_b = 0; midpoint rule on 80 strips).
  double H = 0.0;  // [m]
  for (int k = 0; k < 80; ++k) H += eta_at(R_i + (k + 0.5) * B / 80) / 80;
  const double C = Q / (H * std::log(R_o / R_i));  // [m^2/s] free-vortex circulation / 2 pi
  const double free_vortex = C * C / (2 * 9.81) * (1 / (R_i * R_i) - 1 / (R_o * R_o));  // [m]
  const double U = Q / (B * H);                                                         // [m/s]
  const double narrow_bend = U * U * B / (9.81 * R_c);                                  // [m]

  const double inset = 1e-3;  // [m] off the bank
  const double rise = eta_at(R_o - inset) - eta_at(R_i + inset);
  EXPECT_GT(rise, 0.0);
  EXPECT_NEAR(rise / free_vortex, 1.0, 0.1);
  EXPECT_GT(speed_at(R_i + 0.1 * B), speed_at(R_o - 0.1 * B));  // fastest near the inner bank
  std::printf(
      "bend: apex depth %.4f m, super-elevation %.4e m; free vortex %.4e m (ratio %.3f); "
      "U^2 B/(g R_c) %.4e m (ratio %.3f); %d iterations\n",
      H, rise, free_vortex, rise / free_vortex, narrow_bend, rise / narrow_bend, report.iterations);
}

}  // namespace
}  // namespace flotsam
