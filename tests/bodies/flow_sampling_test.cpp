// Sampling a quadratic velocity field at a body position is exact (issue 4 item 6): a P2 field
// holding a quadratic's nodal values reproduces it, and its gradient, anywhere in the mesh, so
// a body moved through a mesh-sampled field feels exactly the forces of the analytic field.
// Uses the neighbour walk (mesh/point_locator.hpp) and P2 interpolation (mesh/interpolation.hpp)
// on a structured mesh, with the body's element hint.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "bodies/body_motion.hpp"
#include "mesh/interpolation.hpp"
#include "mesh/point_locator.hpp"
#include "mesh/structured_mesh.hpp"

namespace flotsam {
namespace {

// u = (0.4 + 0.002 x - 0.001 y + 1e-5 x^2 - 2e-5 x y + 3e-5 y^2,
//      0.1 - 0.003 x + 0.002 y - 2e-5 x^2 + 1e-5 x y - 1e-5 y^2)
Vec2 quadratic_u(const Vec2& p) {
  const double x = p.x(), y = p.y();
  return {0.4 + 0.002 * x - 0.001 * y + 1e-5 * x * x - 2e-5 * x * y + 3e-5 * y * y,
          0.1 - 0.003 * x + 0.002 * y - 2e-5 * x * x + 1e-5 * x * y - 1e-5 * y * y};
}

Mat2 quadratic_grad_u(const Vec2& p) {
  const double x = p.x(), y = p.y();
  Mat2 g;
  g << 0.002 + 2e-5 * x - 2e-5 * y, -0.001 - 2e-5 * x + 6e-5 * y,  //
      -0.003 - 4e-5 * x + 1e-5 * y, 0.002 + 1e-5 * x - 2e-5 * y;
  return g;
}

/// The quadratic field, exactly.
class ExactField : public FlowField {
 public:
  FlowSample sample(const Vec2& p, double, int&) const override {
    FlowSample s;
    s.eta = s.H = 5.0;
    s.u = quadratic_u(p);
    s.grad_u = quadratic_grad_u(p);
    return s;
  }
  double time_begin() const override { return 0; }
  double time_end() const override { return 1e30; }
};

/// The same field through its P2 nodal values on a mesh.
class MeshField : public FlowField {
 public:
  explicit MeshField(const Mesh& mesh) : mesh_(mesh), locator_(mesh) {
    for (const Vec2& node : mesh.nodes) {
      u_x_.push_back(quadratic_u(node).x());
      u_y_.push_back(quadratic_u(node).y());
    }
  }
  FlowSample sample(const Vec2& p, double, int& hint) const override {
    FlowSample s;
    const Location at = locator_.locate(p, hint);
    hint = at.element;
    if (!at.inside) {
      s.inside = false;
      return s;
    }
    s.eta = s.H = 5.0;
    s.u = interpolate_p2(mesh_, at, u_x_, u_y_);
    s.grad_u = gradient_p2(mesh_, at, u_x_, u_y_);
    return s;
  }
  double time_begin() const override { return 0; }
  double time_end() const override { return 1e30; }

 private:
  const Mesh& mesh_;
  PointLocator locator_;
  std::vector<double> u_x_, u_y_;
};

TEST(FlowSampling, QuadraticVelocityAtABodyIsExact) {
  RectangleSpec rect;
  rect.length = 200;
  rect.width = 60;
  rect.nx = 12;
  rect.ny = 5;
  const Mesh mesh = make_rectangle_mesh(rect);
  const MeshField on_mesh(mesh);
  const ExactField exact;
  BodySet bodies;
  bodies.add(BodySpec{.position = {37.3, 21.9}, .angle = 0.4, .velocity = {0.1, 0.05}});
  ForceModel model;
  model.physics.drag_points = 5;  // samples along the body too
  int hint = -1, exact_hint = -1;
  const Vec2 positions[] = {{37.3, 21.9}, {120.0, 10.0}, {180.5, 55.2}};
  for (const Vec2& p : positions) {
    BodyStateVector y;
    y << p, 0.4, 0.1, 0.05, 0.01;
    int sample_hint = hint;
    const FlowSample s = on_mesh.sample(p, 0, sample_hint);
    EXPECT_LT((s.u - quadratic_u(p)).norm(), 1e-13) << p.transpose();
    EXPECT_LT((s.grad_u - quadratic_grad_u(p)).norm(), 1e-13) << p.transpose();
    const BodyStateVector dy = body_derivative(bodies, 0, 0, y, on_mesh, hint, model);
    const BodyStateVector dy_exact = body_derivative(bodies, 0, 0, y, exact, exact_hint, model);
    EXPECT_LT((dy - dy_exact).norm(), 1e-12 * dy_exact.norm()) << p.transpose();
  }
}

}  // namespace
}  // namespace flotsam
