// Verifies FlowField::sample_batch in both engines' fields (fem_batch_sample.cpp,
// fv_batch_sample.cpp): every lane of a batch is, bit for bit, what sample gives at that point,
// time and hint, with the same updated hint; on Gmsh's channel with two piers (curved elements
// on the circles, points in the piers and beyond the banks), at random points, on element edges
// and vertices, from fresh, cached, stale and invalid hints, at times in and beyond the step, in
// a flow that moves and, for the finite-volume engine, over a bed that rises out of the water
// (dry cells); for the FEM's field also after a restore and further steps (the elements' packs
// follow the states), and a field whose states changed since they were packed refuses a batch.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <stdexcept>

#include "../support/scratch_path.hpp"
#include "../support/two_pier_channel.hpp"
#include "coupling/flow_engines.hpp"
#include "flow/fem/fem_flow_field.hpp"
#include "flow/flow_batch.hpp"
#include "io/binary_archive.hpp"
#include "mesh/mesh_generator.hpp"

namespace flotsam {
namespace {

Mesh channel_with_piers() {
  return generate_mesh(test::two_pier_channel());
}

/// A moving flow over a sloping bed. The finite-volume bed rises above the water for x > 150 m
/// (dry cells); the FEM's stays under it.
Case moving_flow_case(FlowEngineKind kind) {
  Case c;
  c.name = "batch_sampling";
  c.mesh.kind = MeshSource::Kind::file;
  c.flow.engine = kind;
  c.flow.initial_eta_start = c.flow.initial_eta_end = 1.0;
  c.flow.initial_u = Expression("0.4 + 0.002*y", "test");
  c.flow.initial_v = Expression("0.05*sin(x/20)", "test");
  c.flow.viscosity = 0.01;
  c.bed.kind = BedConfig::Kind::expression;
  c.bed.expression = Expression(
      kind == FlowEngineKind::fv ? "-2 + 0.02*x - 0.003*y" : "-3 + 0.005*x - 0.003*y", "test");
  c.time = {.end = 10.0, .step = 0.5, .mode = CouplingMode::one_way};
  return c;
}

/// That flow's engine (which keeps a reference to the case), stepped `steps` times by 0.5 s, so
/// that the step's two states differ.
struct SteppedFlow {
  Case flow_case;
  std::unique_ptr<FlowEngine> engine;

  SteppedFlow(const Mesh& mesh, FlowEngineKind kind, int steps)
      : flow_case(moving_flow_case(kind)), engine(make_flow_engine(mesh, flow_case)) {
    engine->initialize();
    for (int i = 0; i < steps; ++i) engine->step(0.5);
  }
  SteppedFlow(const SteppedFlow&) = delete;
  SteppedFlow& operator=(const SteppedFlow&) = delete;
};

/// The bits of every lane of a and b are the same.
int lanes_differing(const BatchFlow& a, const BatchFlow& b) {
  const Lanes* fields[2][13] = {{&a.inside, &a.H, &a.u, &a.v, &a.g00, &a.g01, &a.g10, &a.g11,
                                 &a.du_dt, &a.dv_dt, &a.zb_x, &a.zb_y, &a.inside},
                                {&b.inside, &b.H, &b.u, &b.v, &b.g00, &b.g01, &b.g10, &b.g11,
                                 &b.du_dt, &b.dv_dt, &b.zb_x, &b.zb_y, &b.inside}};
  int differing = 0;
  for (int k = 0; k < batch_width; ++k) {
    bool same = true;
    for (int f = 0; f < 12; ++f)
      same = same && std::bit_cast<std::uint64_t>((*fields[0][f])[k]) ==
                         std::bit_cast<std::uint64_t>((*fields[1][f])[k]);
    differing += same ? 0 : 1;
  }
  return differing;
}

struct BatchCounts {
  int batches = 0, inside = 0, outside = 0, dry = 0, curved = 0, on_edges = 0;
};

/// Random batches of points and hints: sample_batch against sample, lane by lane.
BatchCounts compare_batches(const Mesh& mesh, const FlowField& field, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> x(-10.0, 210.0), y(-10.0, 70.0), unit(0.0, 1.0);
  std::uniform_int_distribution<int> element(0, mesh.element_count() - 1), choice(0, 7);
  const double t0 = field.time_begin(), span = field.time_end() - t0;
  BatchCounts counts;
  std::vector<int> cached(batch_width, -1);  // each lane's element from its last point
  for (int b = 0; b < 3000; ++b) {
    alignas(64) Lanes px, py, t;
    bool active[batch_width];
    int hints[batch_width], expected_hints[batch_width];
    for (int k = 0; k < batch_width; ++k) {
      Vec2 p(x(random), y(random));
      const int e = element(random);
      const auto& el = mesh.elements[e];
      const int kind = choice(random);
      if (kind == 0 || kind == 1) {  // on an edge (a straight edge, or a curved one's chord)
        const int j = choice(random) % 3;
        p = mesh.nodes[el[j]] + unit(random) * (mesh.nodes[el[(j + 1) % 3]] - mesh.nodes[el[j]]);
        ++counts.on_edges;
      } else if (kind == 2) {  // a vertex or a mid node
        p = mesh.nodes[el[choice(random) % 6]];
        ++counts.on_edges;
      } else if (kind == 3 && cached[k] >= 0) {  // a short move from the last point
        p = Vec2(px[k], py[k]) + Vec2(unit(random) - 0.5, unit(random) - 0.5);
      }
      px[k] = p.x(), py[k] = p.y();
      t[k] = t0 + (1.2 * unit(random) - 0.1) * span;  // beyond the step too: clamped
      active[k] = choice(random) != 0;
      const int hint_kind = choice(random);
      hints[k] = hint_kind < 3   ? cached[k]                 // the lane's last element
                 : hint_kind < 5 ? e                         // an element near or far
                 : hint_kind < 6 ? -1                        // unknown
                 : hint_kind < 7 ? mesh.element_count() + 3  // invalid
                                 : element(random);          // stale
    }
    BatchFlow expected, batch;
    const FlowSample outside{.inside = false};
    for (int k = 0; k < batch_width; ++k) {
      expected_hints[k] = hints[k];
      expected.set(k, active[k] ? field.sample({px[k], py[k]}, t[k], expected_hints[k]) : outside);
    }
    field.sample_batch(px, py, t, active, hints, batch);
    EXPECT_EQ(lanes_differing(expected, batch), 0) << "batch " << b;
    for (int k = 0; k < batch_width; ++k) {
      EXPECT_EQ(hints[k], expected_hints[k]) << "batch " << b << " lane " << k;
      if (!active[k]) continue;
      cached[k] = hints[k];
      if (batch.inside[k] == 0.0) {
        ++counts.outside;
        continue;
      }
      ++counts.inside;
      counts.dry += batch.H[k] == 0.0 ? 1 : 0;
      counts.curved += hints[k] >= 0 && mesh.is_curved(hints[k]) ? 1 : 0;
    }
    ++counts.batches;
  }
  return counts;
}

TEST(BatchSampling, FemBatchEqualsPointByPointBitForBit) {
  const Mesh mesh = channel_with_piers();
  const SteppedFlow flow(mesh, FlowEngineKind::fem, 2);
  const FlowField& field = flow.engine->field();
  ASSERT_LT(field.time_begin(), field.time_end());
  const BatchCounts counts = compare_batches(mesh, field, 11);
  EXPECT_GT(counts.inside, 10000);
  EXPECT_GT(counts.outside, 1000);  // in the piers and beyond the banks
  EXPECT_GT(counts.curved, 100);
  EXPECT_GT(counts.on_edges, 5000);
}

TEST(BatchSampling, FiniteVolumeBatchEqualsPointByPointBitForBit) {
  const Mesh mesh = channel_with_piers();
  const SteppedFlow flow(mesh, FlowEngineKind::fv, 2);
  const FlowField& field = flow.engine->field();
  ASSERT_LT(field.time_begin(), field.time_end());
  const BatchCounts counts = compare_batches(mesh, field, 12);
  EXPECT_GT(counts.inside, 10000);
  EXPECT_GT(counts.outside, 1000);
  EXPECT_GT(counts.dry, 1000);  // x > 150 m: the bed above the water
  EXPECT_GT(counts.on_edges, 5000);
}

// The FEM's batch reads the elements' packs of the states (FemFlowField::pack_states): the
// engine packs them again after a restore from a checkpoint and after each further step, so the
// batch still equals sample bit for bit.
TEST(BatchSampling, FemBatchFollowsTheStatesThroughARestoreAndSteps) {
  const Mesh mesh = channel_with_piers();
  const std::string path = test::scratch_path("batch_sampling_fem.bin").string();
  {
    const SteppedFlow stepped(mesh, FlowEngineKind::fem, 2);
    ArchiveWriter w(path);
    stepped.engine->save(w, "flow");
    w.close();
  }
  const SteppedFlow flow(mesh, FlowEngineKind::fem, 0);  // both states at t = 0 before this
  ArchiveReader r(path);
  flow.engine->restore(r, "flow");
  const FlowField& field = flow.engine->field();
  EXPECT_EQ(field.time_begin(), 0.5);
  EXPECT_EQ(field.time_end(), 1.0);
  EXPECT_GT(compare_batches(mesh, field, 13).inside, 10000);
  flow.engine->step(0.5);
  EXPECT_EQ(field.time_end(), 1.5);
  EXPECT_GT(compare_batches(mesh, field, 14).inside, 10000);
}

// A field whose solver stepped without pack_states refuses to sample a batch from the old packs.
TEST(BatchSampling, FemBatchRefusesStatesChangedSincePacked) {
  const Mesh mesh = channel_with_piers();
  const Case c = moving_flow_case(FlowEngineKind::fem);
  ShallowWaterSolver solver(mesh, c);
  solver.initialize();
  FemFlowField field(solver);
  field.pack_states();
  solver.step(0.5);
  alignas(64) Lanes x, y, t;
  bool active[batch_width];
  int hints[batch_width];
  for (int k = 0; k < batch_width; ++k) x[k] = 20.0 + k, y[k] = 30.0, t[k] = 0.25;
  for (int k = 0; k < batch_width; ++k) active[k] = true, hints[k] = -1;
  BatchFlow out;
  EXPECT_THROW(field.sample_batch(x, y, t, active, hints, out), std::logic_error);
  field.pack_states();
  field.sample_batch(x, y, t, active, hints, out);
  for (int k = 0; k < batch_width; ++k) {
    int hint = -1;
    const FlowSample expected = field.sample({x[k], y[k]}, t[k], hint);
    ASSERT_TRUE(expected.inside);
    EXPECT_EQ(out.u[k], expected.u.x());
    EXPECT_EQ(out.H[k], expected.H);
    EXPECT_EQ(hints[k], hint);
  }
}

}  // namespace
}  // namespace flotsam
