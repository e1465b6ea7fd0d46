// Writes the sample files that tests/scripts/check_vtk.py reads back with VTK's own readers:
//   flow_000000.vtu, flow_000001.vtu  a 3 x 2 rectangle of P2 triangles [0.5, 3.5] x [-1, 1] m
//                                     with f = x + 2y (P2), g = 3x - y + 1 (P1), q = x^2 (P2),
//                                     u = (y, -x) (P2 vector), "element" = element index (cell)
//   flow.pvd                          the two .vtu at t = 0 s and t = 7.5 s
//   boundary.vtp                      the rectangle's boundary edges
//   bodies.vtp                        the bodies of body_specs() below, the second one gone
// The expected values in check_vtk.py are the formulas and the body table, written out again
// there: keep the two in step.
//
// Usage: write_vtk_samples <folder>
#include <fmt/core.h>

#include <filesystem>
#include <numbers>
#include <vector>

#include "bodies/body_set.hpp"
#include "io/pvd_writer.hpp"
#include "io/vtp_writer.hpp"
#include "io/vtu_writer.hpp"
#include "mesh/structured_mesh.hpp"

namespace {

using namespace flotsam;

void write_flow(const std::string& folder) {
  RectangleSpec spec;
  spec.x0 = 0.5;
  spec.y0 = -1.0;
  spec.length = 3.0;
  spec.width = 2.0;
  spec.nx = 3;
  spec.ny = 2;
  const Mesh mesh = make_rectangle_mesh(spec);

  std::vector<double> f, q, g, element;
  std::vector<Vec2> u;
  for (const Vec2& x : mesh.nodes) {
    f.push_back(x.x() + 2 * x.y());
    q.push_back(x.x() * x.x());
    u.emplace_back(x.y(), -x.x());
  }
  for (int v = 0; v < mesh.vertex_count; ++v)
    g.push_back(3 * mesh.nodes[v].x() - mesh.nodes[v].y() + 1);
  for (int e = 0; e < mesh.element_count(); ++e) element.push_back(e);

  VtuFields fields;
  fields.add_point_scalar("f [m]", f);
  fields.add_point_scalar("q [m^2]", q);
  fields.add_p1_scalar("g [m]", g);
  fields.add_point_vector("u [m/s]", u);
  fields.add_cell_scalar("element", element);

  PvdWriter pvd(folder + "/flow.pvd");
  const double times[] = {0.0, 7.5};
  for (int k = 0; k < 2; ++k) {
    const std::string file = fmt::format("flow_{:06d}.vtu", k);
    write_vtu(folder + "/" + file, mesh, fields, times[k]);
    pvd.add(times[k], file);
  }
  write_boundary_vtp(folder + "/boundary.vtp", mesh);
}

void write_bodies(const std::string& folder) {
  struct Row {
    long id;
    double x, y;           // x_G [m]
    double angle;          // theta [rad]
    double length, width;  // L, l [m]
  };
  const Row rows[] = {{7, 10.0, 5.0, 0.0, 20.0, 1.0},
                      {13, 0.0, 0.0, 1.0, 5.0, 1.0},  // gone: not written
                      {11, -3.0, 2.0, std::numbers::pi / 2, 4.0, 2.0},
                      {42, 1.0, -1.0, std::numbers::pi / 6, 2.0, 1.0}};
  BodySet bodies;
  for (const Row& row : rows) {
    BodySpec spec;
    spec.id = row.id;
    spec.position = {row.x, row.y};
    spec.angle = row.angle;
    spec.length = row.length;
    spec.width = row.width;
    spec.height = row.width;
    spec.velocity = {0.5 * row.id, -0.25 * row.id};  // u_p [m/s]
    spec.angular_velocity = 0.01 * row.id;           // omega [rad/s]
    bodies.add(spec);
  }
  bodies.state[1] = BodyState::gone;
  bodies.state[2] = BodyState::grounded;
  std::vector<double> drag;  // [N]
  for (const long id : bodies.id) drag.push_back(100.0 * id);
  BodyFields extra;
  extra.add_scalar("drag [N]", drag);
  write_bodies_vtp(folder + "/bodies.vtp", bodies, extra, 7.5);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    fmt::print(stderr, "usage: write_vtk_samples <folder>\n");
    return 2;
  }
  const std::string folder = argv[1];
  std::filesystem::create_directories(folder);
  write_flow(folder);
  write_bodies(folder);
  fmt::print("wrote VTK samples in {}\n", folder);
  return 0;
}
