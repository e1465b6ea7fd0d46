// Verifies the water under and over a bridge deck (src/flow/fv/deck_flux.hpp, docs/model.md
// "Decks: the water") in a frictionless flume 100 m long and 2 m wide, a discharge q per metre
// in at x = 0, the deck's axis across it at x = 50 m, and beyond it the bed 1 m lower with a free
// outflow at x = 100 m, so that nothing downstream drowns the structure. At the steady state the
// upstream energy head E = h + u^2 / (2 g) (mean of the cells 20-30 m upstream) must carry q by:
//   (b) the opening a under the deck as a sluice gate flowing free with its jet filling the
//       opening (contraction coefficient C_c = 1, the energy relation of a gate):
//         q = a sqrt(2 g (E - a))                                   within 3 %, on three meshes;
//   (c) a deck without opening, overtopped: the broad-crested weir of crest height P,
//         q = (2/3)^{3/2} g^{1/2} (E - P)^{3/2}                      within 3 %;
//   (d) both at once: q = the sum of the two                          within 3 %;
// (b') the gate again on a flume turned by 30 degrees and meshed by Gmsh (mesh.region), where the
// deck stands on a staircase of edges oblique to the axis, each passing its share |n_e . n_axis|
// (within 8 %: the jets through the staircase partly drown it);
// and (a) with the water below the soffit the flow is that of the flume without a deck, bit for
// bit; (e) a slowly rising hydrograph through both transitions gives an upstream stage that rises
// without oscillating; (f) a lake at rest under and around a submerged deck over a wavy bed stays
// at rest to round-off. The water balance closes to round-off in all of them.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "../support/bridge_across.hpp"
#include "../support/fv_cases.hpp"
#include "mesh/mesh_generator.hpp"

namespace flotsam {
namespace {

constexpr double g = 9.81;          // [m s^-2]
constexpr double width = 2.0;       // [m]
constexpr double axis_x = 50.0;     // [m]
constexpr double tolerance = 0.03;  // [-] of the discharge

Case flume(double q, double soffit, double top) {
  Case c = test::fv_case({"bottom", "top"});
  c.flow.boundaries.push_back(
      {BoundaryCondition::Kind::discharge, "left", TimeSeries(q * width), TimeSeries(0.0)});
  c.flow.boundaries.push_back(
      {BoundaryCondition::Kind::free, "right", TimeSeries(0.0), TimeSeries(0.0)});
  c.bed.kind = BedConfig::Kind::expression;
  c.bed.expression = Expression("x <= 50 ? 0 : -1", "the flume's drop");
  c.flow.initial_eta = Expression("x <= 50 ? 0.5 : -0.9", "still water");
  c.bridges = {test::bridge_across("deck", axis_x, width, test::plain_deck(soffit, top, 6.0))};
  return c;
}

Mesh flume_mesh(int cells_per_metre) {
  return make_rectangle_mesh({0.0, 0.0, 100.0, width, 100 * cells_per_metre, 2, true});
}

struct Steady {
  double energy = 0.0;   // [m] upstream energy head over the bed (x in [20, 30] m)
  double stage = 0.0;    // [m] upstream surface there
  double outflow = 0.0;  // [m^3/s] through the outlet at the end
  double balance = 0.0;  // [-] the water balance's relative error
};

/// The upstream means over the cells with centroid x in [x0, x1] [m].
Steady measure(const FvEngine& engine, double x0 = 20.0, double x1 = 30.0) {
  const FiniteVolumeSolver& s = engine.solver();
  const CellMesh& cells = s.cells();
  Steady m;
  double area = 0.0;
  for (int i = 0; i < cells.cell_count; ++i) {
    const double x = cells.centroid[i].x();
    if (x < x0 || x > x1) continue;
    const double h = s.state().h[i], u = s.state().hu[i] / h;
    m.energy += cells.area[i] * (h + u * u / (2 * g));
    m.stage += cells.area[i] * (h + s.bed()[i]);
    area += cells.area[i];
  }
  m.energy /= area;
  m.stage /= area;
  m.outflow = engine.water_balance().group_rate.at(
      static_cast<std::size_t>(engine.mesh().find_group("right")));
  m.balance = engine.water_balance().relative_error();
  return m;
}

Steady run_steady(const Case& c, int cells_per_metre, double end = 400.0) {
  const Mesh mesh = flume_mesh(cells_per_metre);
  FvEngine engine(mesh, c);
  engine.initialize();
  test::run_to(engine, end, 1.0);
  return measure(engine);
}

double gate(double E, double a) {
  return a * std::sqrt(2 * g * (E - a));
}
double weir(double E, double P) {
  return std::pow(2.0 / 3.0, 1.5) * std::sqrt(g) * std::pow(E - P, 1.5);
}

TEST(DeckHydraulics, BelowTheSoffitTheFlowIsThatWithoutADeckBitForBit) {
  Case with = flume(0.3, 3.0, 4.0);
  Case without = with;
  without.bridges.clear();
  const Mesh mesh = flume_mesh(2);
  FvEngine a(mesh, with), b(mesh, without);
  a.initialize();
  b.initialize();
  test::run_to(a, 200.0, 1.0);
  test::run_to(b, 200.0, 1.0);
  EXPECT_LT(*std::max_element(a.solver().state().h.begin(), a.solver().state().h.end()), 3.0);
  EXPECT_EQ(a.solver().state().h, b.solver().state().h);
  EXPECT_EQ(a.solver().state().hu, b.solver().state().hu);
  EXPECT_EQ(a.solver().state().hv, b.solver().state().hv);
}

/// Prints and checks one steady case: the discharge the relation gives from the measured head
/// against the flume's q, the outflow against the inflow (steady), the balance to round-off.
void expect_relation(const std::string& label, const Steady& m, double predicted, double q,
                     double relative = tolerance) {
  std::printf(
      "%s: E = %.4f m, q by the relation %.4f against %.4f m^2/s (%+.2f %%), balance "
      "%.1e\n",
      label.c_str(), m.energy, predicted, q, 100 * (predicted / q - 1), m.balance);
  EXPECT_NEAR(predicted / q, 1.0, relative) << label;
  EXPECT_NEAR(m.outflow, q * width, 1e-3 * q * width) << label << ": not steady";
  EXPECT_LT(std::abs(m.balance), 1e-12) << label;
}

TEST(DeckHydraulics, UnderTheDeckASluiceGateFlowingFreeOnThreeMeshes) {
  const double q = 1.0, a = 0.3;  // [m^2/s], [m]: E about 0.87 m, upstream Froude 0.46
  for (const int n : {1, 2, 4}) {
    const Steady m = run_steady(flume(q, a, 5.0), n);
    expect_relation("gate, " + std::to_string(n) + " cells/m", m, gate(m.energy, a), q);
  }
}

TEST(DeckHydraulics, ADeckWithoutOpeningOvertoppedIsABroadCrestedWeir) {
  const double q = 1.0, P = 1.0;  // [m^2/s], [m]: the soffit at the bed, the top 1 m above it
  const Steady m = run_steady(flume(q, 0.0, P), 2);
  expect_relation("weir", m, weir(m.energy, P), q);
}

TEST(DeckHydraulics, UnderAndOverAtOnceTheDischargesAdd) {
  const double q = 2.0, a = 0.3, P = 1.0;  // [m^2/s], [m], [m]: E about 1.47 m
  const Steady m = run_steady(flume(q, a, P), 2);
  expect_relation("gate and weir", m, gate(m.energy, a) + weir(m.energy, P), q);
}

TEST(DeckHydraulics, ARisingHydrographGivesAStageThatRisesWithoutOscillating) {
  // q from 0.1 to 4 m^2/s over 3,000 s: the surface just upstream of the deck (44-49 m) rises
  // through the soffit (0.5 m) and the deck top (1.2 m); the stage every 10 s must never fall by
  // more than 1 mm.
  Case c = flume(0.0, 0.5, 1.2);
  c.flow.boundaries[2].value =
      TimeSeries(std::vector<std::pair<double, double>>{{0.0, 0.1 * width}, {3000.0, 4.0 * width}});
  const Mesh mesh = flume_mesh(2);
  FvEngine engine(mesh, c);
  engine.initialize();
  test::run_to(engine, 200.0, 1.0);  // settled at the lowest discharge
  double previous = measure(engine, 44.0, 49.0).stage, lowest = previous, fall = 0.0;
  while (engine.time() < 3000.0 - 1e-9) {
    test::run_to(engine, engine.time() + 10.0, 1.0);
    const double stage = measure(engine, 44.0, 49.0).stage;
    fall = std::max(fall, previous - stage);
    previous = stage;
  }
  std::printf("rising hydrograph: stage %.3f -> %.3f m, largest fall over 10 s %.2e m\n", lowest,
              previous, fall);
  EXPECT_LT(lowest, 0.5);    // it started below the soffit
  EXPECT_GT(previous, 1.2);  // and ended over the deck
  EXPECT_LT(fall, 1e-3);
  EXPECT_LT(std::abs(engine.water_balance().relative_error()), 1e-12);
}

TEST(DeckHydraulics, ALakeAtRestUnderAndAroundASubmergedDeckStaysAtRest) {
  Case c = test::fv_case({"left", "right", "bottom", "top"});
  c.bed.kind = BedConfig::Kind::expression;
  c.bed.expression = Expression("0.2 * sin(x / 7) + 0.1 * cos(y * 2)", "a wavy bed");
  c.flow.initial_eta_start = c.flow.initial_eta_end = 1.0;
  c.bridges = {test::bridge_across("deck", axis_x, width, test::plain_deck(0.6, 0.9, 6.0))};
  const Mesh mesh = flume_mesh(2);
  FvEngine engine(mesh, c);
  engine.initialize();
  test::run_to(engine, 100.0, 1.0);
  const FiniteVolumeSolver& s = engine.solver();
  double speed = 0.0, surface = 0.0;
  for (int i = 0; i < s.cells().cell_count; ++i) {
    speed = std::max({speed, std::abs(s.state().hu[i]), std::abs(s.state().hv[i])});
    surface = std::max(surface, std::abs(s.state().h[i] + s.bed()[i] - 1.0));
  }
  std::printf("lake at rest under a deck: |hu| %.1e m^2/s, |eta - 1| %.1e m\n", speed, surface);
  EXPECT_LE(speed, 1e-12);
  EXPECT_LE(surface, 1e-12);
  EXPECT_LT(std::abs(engine.water_balance().relative_error()), 1e-12);
}

TEST(DeckHydraulics, OnAGmshMeshTurnedAcrossTheAxisTheGateStillHolds) {
  // The flume of `flume` turned by 30 degrees about the origin: local x' = c x + s y along it.
  const double c = std::cos(pi / 6), s = std::sin(pi / 6), q = 1.0, a = 0.3;
  const auto world = [&](double x, double y) { return Vec2(c * x - s * y, s * x + c * y); };
  const std::string along = fmt::format("({} * x + {} * y)", c, s);
  MeshSource source;
  source.kind = MeshSource::Kind::region;
  RegionGeometry& r = source.region;
  r.outline = {{world(0, 0), world(100, 0), world(100, width), world(0, width)}, "outline"};
  r.lines = {{"inflow", {world(0, width), world(0, 0)}, "inflow"},
             {"outflow", {world(100, 0), world(100, width)}, "outflow"}};
  r.mesh_size = 0.5;
  const Mesh mesh = generate_mesh(source);
  Case f = test::fv_case({"bank"});
  f.flow.boundaries.push_back(
      {BoundaryCondition::Kind::discharge, "inflow", TimeSeries(q * width), TimeSeries(0.0)});
  f.flow.boundaries.push_back(
      {BoundaryCondition::Kind::free, "outflow", TimeSeries(0.0), TimeSeries(0.0)});
  f.bed.kind = BedConfig::Kind::expression;
  // The drop 2 m past the axis: the cells the oblique staircase of deck edges separates have
  // corners on both sides of the axis, and a drop at the axis would lower their beds (each the
  // mean of its corners) and so the deck's opening measured from them.
  f.bed.expression = Expression(along + " <= 52 ? 0 : -1", "the turned flume's drop");
  f.flow.initial_eta = Expression(along + " <= 52 ? 0.5 : -0.9", "still water");
  BridgeConfig deck = test::bridge_across("deck", axis_x, width, test::plain_deck(a, 5.0, 6.0));
  deck.start = world(deck.start.x(), deck.start.y());  // the flume's frame turned
  deck.end = world(deck.end.x(), deck.end.y());
  f.bridges = {deck};
  FvEngine engine(mesh, f);
  engine.initialize();
  test::run_to(engine, 400.0, 1.0);
  // The energy head of the cells 20-30 m along the flume (x' from the centroids).
  const FiniteVolumeSolver& solver = engine.solver();
  Steady m;
  double area = 0.0;
  for (int i = 0; i < solver.cells().cell_count; ++i) {
    const Vec2 p = solver.cells().centroid[i];
    const double x = c * p.x() + s * p.y();
    if (x < 20.0 || x > 30.0) continue;
    const double h = solver.state().h[i];
    const double speed2 =
        (std::pow(solver.state().hu[i], 2) + std::pow(solver.state().hv[i], 2)) / (h * h);
    m.energy += solver.cells().area[i] * (h + speed2 / (2 * g));
    area += solver.cells().area[i];
  }
  m.energy /= area;
  m.outflow =
      engine.water_balance().group_rate.at(static_cast<std::size_t>(mesh.find_group("outflow")));
  m.balance = engine.water_balance().relative_error();
  // 8 %: the jets leave an oblique staircase of edges through cells of mixed shape, and where
  // one of them runs deeper than the opening it drowns that edge's share (D-1's tailwater);
  // measured +5.0 % (the aligned flume: within 0.05 %).
  expect_relation("gate, turned Gmsh mesh", m, gate(m.energy, a), q, 0.08);
}

}  // namespace
}  // namespace flotsam
