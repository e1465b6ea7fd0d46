#include "mesh/interpolation.hpp"

#include <cassert>

#include "mesh/shape_functions.hpp"

namespace flotsam {
namespace {

// grad_rs f = sum_k f_k grad_rs N_k over the first n nodes of the element.
template <std::size_t n>
Vec2 reference_gradient(const std::array<int, 6>& el, const std::array<Vec2, n>& G,
                        std::span<const double> field) {
  Vec2 g = Vec2::Zero();
  for (std::size_t k = 0; k < n; ++k) g += field[el[k]] * G[k];
  return g;
}

}  // namespace

Mat2 jacobian_at(const Mesh& mesh, const Location& location) {
  assert(location.inside);
  if (!location.curved) return mesh.jacobian(location.element);
  const auto& el = mesh.elements[location.element];
  const P2Gradients G = p2_reference_gradients(location.r, location.s);
  Mat2 J = Mat2::Zero();
  for (int k = 0; k < 6; ++k) J += mesh.nodes[el[k]] * G[k].transpose();
  return J;
}

double interpolate_p1(const Mesh& mesh, const Location& location, std::span<const double> field) {
  assert(location.inside && static_cast<int>(field.size()) == mesh.vertex_count);
  const auto& el = mesh.elements[location.element];
  const P1Values N = p1_values(location.r, location.s);
  return N[0] * field[el[0]] + N[1] * field[el[1]] + N[2] * field[el[2]];
}

double interpolate_p2(const Mesh& mesh, const Location& location, std::span<const double> field) {
  assert(location.inside && static_cast<int>(field.size()) == mesh.node_count());
  const auto& el = mesh.elements[location.element];
  const P2Values N = p2_values(location.r, location.s);
  double f = 0.0;
  for (int k = 0; k < 6; ++k) f += N[k] * field[el[k]];
  return f;
}

// grad_x f = J^-T grad_rs f (chain rule: grad_rs f = J^T grad_x f).
Vec2 gradient_p1(const Mesh& mesh, const Location& location, std::span<const double> field) {
  assert(location.inside && static_cast<int>(field.size()) == mesh.vertex_count);
  const Vec2 g =
      reference_gradient(mesh.elements[location.element], p1_reference_gradients(), field);
  return jacobian_at(mesh, location).transpose().inverse() * g;
}

Vec2 gradient_p2(const Mesh& mesh, const Location& location, std::span<const double> field) {
  assert(location.inside && static_cast<int>(field.size()) == mesh.node_count());
  const Vec2 g = reference_gradient(mesh.elements[location.element],
                                    p2_reference_gradients(location.r, location.s), field);
  return jacobian_at(mesh, location).transpose().inverse() * g;
}

Vec2 interpolate_p1(const Mesh& mesh, const Location& location, std::span<const double> u_x,
                    std::span<const double> u_y) {
  return {interpolate_p1(mesh, location, u_x), interpolate_p1(mesh, location, u_y)};
}

Vec2 interpolate_p2(const Mesh& mesh, const Location& location, std::span<const double> u_x,
                    std::span<const double> u_y) {
  assert(location.inside && static_cast<int>(u_x.size()) == mesh.node_count() &&
         static_cast<int>(u_y.size()) == mesh.node_count());
  const auto& el = mesh.elements[location.element];
  const P2Values N = p2_values(location.r, location.s);
  Vec2 u = Vec2::Zero();
  for (int k = 0; k < 6; ++k) u += N[k] * Vec2(u_x[el[k]], u_y[el[k]]);
  return u;
}

// Row i of grad u is (grad_x u_i)^T = (grad_rs u_i)^T J^-1.
Mat2 gradient_p1(const Mesh& mesh, const Location& location, std::span<const double> u_x,
                 std::span<const double> u_y) {
  assert(location.inside && static_cast<int>(u_x.size()) == mesh.vertex_count &&
         static_cast<int>(u_y.size()) == mesh.vertex_count);
  const auto& el = mesh.elements[location.element];
  const P1Gradients G = p1_reference_gradients();
  Mat2 grad_rs;
  grad_rs.row(0) = reference_gradient(el, G, u_x).transpose();
  grad_rs.row(1) = reference_gradient(el, G, u_y).transpose();
  return grad_rs * jacobian_at(mesh, location).inverse();
}

Mat2 gradient_p2(const Mesh& mesh, const Location& location, std::span<const double> u_x,
                 std::span<const double> u_y) {
  assert(location.inside && static_cast<int>(u_x.size()) == mesh.node_count() &&
         static_cast<int>(u_y.size()) == mesh.node_count());
  const auto& el = mesh.elements[location.element];
  const P2Gradients G = p2_reference_gradients(location.r, location.s);
  Mat2 grad_rs;
  grad_rs.row(0) = reference_gradient(el, G, u_x).transpose();
  grad_rs.row(1) = reference_gradient(el, G, u_y).transpose();
  return grad_rs * jacobian_at(mesh, location).inverse();
}

}  // namespace flotsam
