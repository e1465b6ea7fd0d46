// Unit tests of the MUSCL reconstruction (flow/fv/reconstruction.hpp, docs/model.md (M-12)):
// linear data is reproduced without limiting, the Barth-Jespersen limiter keeps every edge value
// within its neighbours' range (so depths stay >= 0), and dry cells and order 1 are constant.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "flow/fv/reconstruction.hpp"
#include "fv_test_cases.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

constexpr double dry_depth = 1e-3;  // [m]

// Parallel diagonals: every two neighbouring cells are point images of each other through the
// midpoint of their shared edge, so the neighbour's centroid is c_i + 2 r_k and the edge value
// of linear data, phi_i + g.r_k, lies halfway to the neighbour's: the limiter keeps alpha = 1.
CellMesh parallelogram_cells() {
  return build_cell_mesh(make_rectangle_mesh({0.0, 0.0, 10.0, 4.0, 10, 4, false}));
}

CellField field_from(const CellMesh& c, double (*h)(const Vec2&), double (*eta)(const Vec2&),
                     double (*u)(const Vec2&), double (*v)(const Vec2&)) {
  CellField f;
  f.resize(c.cell_count);
  for (int i = 0; i < c.cell_count; ++i) {
    const Vec2& x = c.centroid[i];
    f.h[i] = h(x), f.eta[i] = eta(x), f.u[i] = u(x), f.v[i] = v(x);
  }
  return f;
}

double linear_h(const Vec2& x) {
  return 2.0 + 0.1 * x.x() + 0.05 * x.y();
}
double linear_eta(const Vec2& x) {
  return 3.0 + 0.02 * x.x() - 0.03 * x.y();
}
double linear_u(const Vec2& x) {
  return 0.5 + 0.1 * x.x() - 0.2 * x.y();
}
double linear_v(const Vec2& x) {
  return -0.2 + 0.05 * x.y();
}

TEST(Reconstruction, LinearFieldIsReproducedExactlyOnInnerCells) {
  const CellMesh c = parallelogram_cells();
  CellField f = field_from(c, linear_h, linear_eta, linear_u, linear_v);
  reconstruct(c, 2, dry_depth, f);
  int inner = 0;
  for (int i = 0; i < c.cell_count; ++i) {
    if (!test::is_inner_cell(c, i)) continue;  // a boundary edge's ghost is zero-gradient
    ++inner;
    EXPECT_NEAR((f.grad_h[i] - Vec2(0.1, 0.05)).norm(), 0.0, 1e-10) << "cell " << i;
    EXPECT_NEAR((f.grad_eta[i] - Vec2(0.02, -0.03)).norm(), 0.0, 1e-10) << "cell " << i;
    EXPECT_NEAR((f.grad_u[i] - Vec2(0.1, -0.2)).norm(), 0.0, 1e-10) << "cell " << i;
    EXPECT_NEAR((f.grad_v[i] - Vec2(0.0, 0.05)).norm(), 0.0, 1e-10) << "cell " << i;
  }
  EXPECT_GT(inner, c.cell_count / 2);
}

TEST(Reconstruction, OrderOneGivesZeroGradients) {
  const CellMesh c = parallelogram_cells();
  CellField f = field_from(c, linear_h, linear_eta, linear_u, linear_v);
  reconstruct(c, 1, dry_depth, f);
  for (int i = 0; i < c.cell_count; ++i) {
    EXPECT_EQ(f.grad_h[i], Vec2::Zero());
    EXPECT_EQ(f.grad_eta[i], Vec2::Zero());
    EXPECT_EQ(f.grad_u[i], Vec2::Zero());
    EXPECT_EQ(f.grad_v[i], Vec2::Zero());
  }
}

TEST(Reconstruction, DryCellIsConstant) {
  const CellMesh c = parallelogram_cells();
  CellField f = field_from(c, linear_h, linear_eta, linear_u, linear_v);
  const int dry = c.cell_count / 2;  // an inner cell, surrounded by wet ones
  ASSERT_TRUE(test::is_inner_cell(c, dry));
  f.h[dry] = 0.5 * dry_depth;
  reconstruct(c, 2, dry_depth, f);
  EXPECT_EQ(f.grad_h[dry], Vec2::Zero());
  EXPECT_EQ(f.grad_eta[dry], Vec2::Zero());
  EXPECT_EQ(f.grad_u[dry], Vec2::Zero());
  EXPECT_EQ(f.grad_v[dry], Vec2::Zero());
}

TEST(Reconstruction, ShorelineDoesNotTiltTheSurfaceOfALakeAtRest) {
  // eta = 1 in the wet cells, the bed (higher) in the dry ones: the wet cells' eta gradient
  // leaves the dry neighbours out and stays exactly 0.
  const CellMesh c = parallelogram_cells();
  CellField f;
  f.resize(c.cell_count);
  int shore = 0;
  for (int i = 0; i < c.cell_count; ++i) {
    const double z = 0.25 * c.centroid[i].x() - 0.5;  // [m] dry from x = 6 m on
    f.h[i] = std::max(0.0, 1.0 - z);
    f.eta[i] = f.h[i] + z;
  }
  reconstruct(c, 2, dry_depth, f);
  for (int i = 0; i < c.cell_count; ++i) {
    if (f.h[i] <= dry_depth) continue;
    EXPECT_EQ(f.grad_eta[i], Vec2::Zero()) << "cell " << i;
    for (int j : c.neighbour[i]) shore += j >= 0 && f.h[j] <= dry_depth;
  }
  EXPECT_GT(shore, 0);  // the case has a shoreline
}

// Pseudo-random numbers in [0, 1) (a fixed linear congruential sequence).
struct Sequence {
  std::uint64_t state = 12345;
  double next() {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  }
};

// Every edge value phi_i + grad phi . r_k lies within [min, max] of phi over the cell and the
// neighbours its gradient reads (Barth-Jespersen), up to round-off.
void expect_within_neighbours(const CellMesh& c, const CellField& f, int i,
                              const std::vector<double>& phi, const Vec2& grad, bool wet_only,
                              const char* name) {
  double lo = phi[i], hi = phi[i];
  for (int j : c.neighbour[i])
    if (j >= 0 && (!wet_only || f.h[j] > dry_depth))
      lo = std::min(lo, phi[j]), hi = std::max(hi, phi[j]);
  for (int k = 0; k < 3; ++k) {
    const double edge = phi[i] + grad.dot(c.to_edge[i][k]);
    EXPECT_GE(edge, lo - 1e-14) << name << " cell " << i << " edge " << k;
    EXPECT_LE(edge, hi + 1e-14) << name << " cell " << i << " edge " << k;
  }
}

TEST(Reconstruction, LimiterKeepsEdgeValuesWithinNeighboursAndDepthsPositive) {
  // A ramp ending in a step onto a dry bed, and rough data, on the criss-cross mesh (where linear
  // data too may be limited).
  const CellMesh c = build_cell_mesh(make_rectangle_mesh({0.0, 0.0, 10.0, 4.0, 10, 4, true}));
  for (int pattern = 0; pattern < 2; ++pattern) {
    CellField f;
    f.resize(c.cell_count);
    Sequence random;
    for (int i = 0; i < c.cell_count; ++i) {
      const Vec2& x = c.centroid[i];
      if (pattern == 0) {
        f.h[i] = x.x() + 0.3 * x.y() < 5.0 ? 1.0 + 0.1 * x.x() : 0.0;  // a ramp, then dry
        f.u[i] = f.h[i] > 0.0 ? 0.5 : 0.0;
      } else {
        f.h[i] = random.next() < 0.2 ? 0.0 : 2.0 * random.next();
        f.u[i] = random.next() - 0.5;
      }
      f.eta[i] = f.h[i] + 0.1 * x.x();
      f.v[i] = random.next() - 0.5;
    }
    reconstruct(c, 2, dry_depth, f);
    int sloped = 0;
    for (int i = 0; i < c.cell_count; ++i) {
      if (f.h[i] <= dry_depth) continue;
      expect_within_neighbours(c, f, i, f.h, f.grad_h[i], false, "h");
      expect_within_neighbours(c, f, i, f.eta, f.grad_eta[i], true, "eta");
      expect_within_neighbours(c, f, i, f.u, f.grad_u[i], true, "u");
      expect_within_neighbours(c, f, i, f.v, f.grad_v[i], true, "v");
      for (int k = 0; k < 3; ++k)
        EXPECT_GE(f.h[i] + f.grad_h[i].dot(c.to_edge[i][k]), -1e-15) << "cell " << i;
      sloped += f.grad_h[i] != Vec2::Zero();
    }
    EXPECT_GT(sloped, 0) << "pattern " << pattern << ": no gradient survived the limiter";
  }
}

}  // namespace
}  // namespace flotsam
