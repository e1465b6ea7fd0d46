// Geometry -> Gmsh built-in (geo) model -> order-2 (or order-1) mesh -> RawMesh.
//
// Every generator:
//   1. validates the geometry (InputError naming the pier, point or side);
//   2. builds the boundary counter-clockwise from points, lines and circle arcs (each arc at
//      most a quarter circle), one plane surface, one physical group per boundary name and the
//      surface group "water" (so that a written .msh holds the triangles);
//   3. sets the size: Mesh.MeshSizeMax everywhere, and for the channel a Threshold field of the
//      Distance to the piers, growing from pier_mesh_size on the circles to mesh_size at
//      refine_distance;
//   4. meshes in 2D (Frontal-Delaunay), raises to order 2 (mid nodes on the curves) unless
//      three-node triangles were asked for, writes the .msh if asked, and hands the model to
//      raw_mesh_from_gmsh_model.
#include "mesh/mesh_generator.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "mesh/gmsh_model.hpp"
#include "mesh/gmsh_session.hpp"
#include "mesh/msh_reader.hpp"
#include "mesh/simple_polygon.hpp"

namespace flotsam {
namespace {

namespace geo = gmsh::model::geo;

// ---- channel with piers ----------------------------------------------------------------------

void check_channel(const ChannelGeometry& channel, const std::string& source) {
  require_positive(source, "length", channel.length);
  require_positive(source, "width", channel.width);
  require_positive(source, "mesh_size", channel.mesh_size);
  require_positive(source, "pier_mesh_size", channel.pier_mesh_size);
  if (!(channel.refine_distance >= 0))
    throw_input_error("{}: refine_distance must not be negative; got {}", source,
                      channel.refine_distance);
  const auto& piers = channel.piers;
  for (std::size_t i = 0; i < piers.size(); ++i) {
    const Pier& p = piers[i];
    const double x = p.centre.x(), y = p.centre.y(), r = p.radius;
    const auto name = fmt::format("pier_{} (centre ({}, {}) m, radius {} m)", i + 1, x, y, r);
    if (!(r > 0)) throw_input_error("{}: {} needs a positive radius", source, name);
    if (y - r <= 0) throw_input_error("{}: {} reaches the right bank (y = 0)", source, name);
    if (y + r >= channel.width)
      throw_input_error("{}: {} reaches the left bank (y = {} m)", source, name, channel.width);
    if (x - r <= 0) throw_input_error("{}: {} reaches the inflow (x = 0)", source, name);
    if (x + r >= channel.length)
      throw_input_error("{}: {} reaches the outflow (x = {} m)", source, name, channel.length);
    for (std::size_t j = 0; j < i; ++j) {
      const double gap = (p.centre - piers[j].centre).norm() - r - piers[j].radius;  // [m]
      if (gap <= 0)
        throw_input_error(
            "{}: pier_{} and pier_{} overlap (their centres are {:.6g} m apart, their radii add "
            "up to {:.6g} m)",
            source, j + 1, i + 1, (p.centre - piers[j].centre).norm(), r + piers[j].radius);
    }
  }
}

void add_pier_size_field(const ChannelGeometry& channel, const std::vector<int>& pier_curves) {
  gmsh::model::mesh::field::setAsBackgroundMesh(add_distance_size_field(
      pier_curves, channel.pier_mesh_size, channel.mesh_size, channel.refine_distance));
}

// ---- polygon -----------------------------------------------------------------------------------

void check_polygon(const PolygonGeometry& polygon, const std::string& source) {
  const auto& p = polygon.points;
  const std::size_t n = p.size();
  if (const std::string defect = polygon_defect(p); !defect.empty())
    throw_input_error("{}: {}", source, defect);
  if (polygon.groups.size() != n)
    throw_input_error("{}: {} points make {} sides, but {} group names are given (one per side)",
                      source, n, n, polygon.groups.size());
  require_positive(source, "mesh_size", polygon.mesh_size);
  for (std::size_t i = 0; i < n; ++i)
    if (polygon.groups[i].empty())
      throw_input_error("{}: side {} (points {} to {}) has an empty group name", source, i + 1,
                        i + 1, (i + 1) % n + 1);
}

}  // namespace

RawMesh generate_channel_mesh(const ChannelGeometry& channel, const std::string& msh_path,
                              const MshFormat& format, int order) {
  const std::string source = "generated channel";
  check_channel(channel, source);
  const double L = channel.length, W = channel.width;  // [m]
  GmshSession session;
  set_common_options(channel.mesh_size);
  BoundaryGroups groups;
  const int p00 = add_point({0, 0}), p10 = add_point({L, 0});
  const int p11 = add_point({L, W}), p01 = add_point({0, W});
  const int right = geo::addLine(p00, p10), outflow = geo::addLine(p10, p11);
  const int left = geo::addLine(p11, p01), inflow = geo::addLine(p01, p00);
  groups.add("inflow", inflow);
  groups.add("outflow", outflow);
  groups.add("bank_right", right);
  groups.add("bank_left", left);
  std::vector<int> loops = {geo::addCurveLoop({right, outflow, left, inflow})};
  std::vector<int> pier_curves;
  for (std::size_t i = 0; i < channel.piers.size(); ++i) {
    const auto arcs = add_circle(channel.piers[i].centre, channel.piers[i].radius);
    for (int arc : arcs) groups.add(fmt::format("pier_{}", i + 1), arc);
    pier_curves.insert(pier_curves.end(), arcs.begin(), arcs.end());
    loops.push_back(geo::addCurveLoop(arcs));
  }
  if (!pier_curves.empty()) {
    geo::synchronize();
    add_pier_size_field(channel, pier_curves);
  }
  return mesh_current_model(source, loops, groups, msh_path, format, order);
}

RawMesh generate_bend_mesh(const BendGeometry& bend, const std::string& msh_path,
                           const MshFormat& format, int order) {
  const std::string source = "generated bend";
  require_positive(source, "width", bend.width);
  require_positive(source, "inner_radius", bend.inner_radius);
  require_positive(source, "inlet_length", bend.inlet_length);
  require_positive(source, "outlet_length", bend.outlet_length);
  require_positive(source, "mesh_size", bend.mesh_size);
  const Vec2 c = bend.centre;
  const double R_i = bend.inner_radius, R_o = bend.inner_radius + bend.width;  // [m]
  const double L_in = bend.inlet_length, L_out = bend.outlet_length;           // [m]
  GmshSession session;
  set_common_options(bend.mesh_size);
  // Counter-clockwise: A -> H along the outer bank of the inlet reach, the outer half circle
  // H -> G, the outlet reach's outer bank G -> F, the outflow F -> E, back along the inner bank
  // E -> D, the inner half circle D -> C, C -> B, and the inflow B -> A.
  const int centre = add_point(c);
  const int A = add_point(c + Vec2(L_in, R_o)), H = add_point(c + Vec2(0, R_o));
  const int outer_mid = add_point(c + Vec2(-R_o, 0)), G = add_point(c + Vec2(0, -R_o));
  const int F = add_point(c + Vec2(L_out, -R_o)), E = add_point(c + Vec2(L_out, -R_i));
  const int D = add_point(c + Vec2(0, -R_i)), inner_mid = add_point(c + Vec2(-R_i, 0));
  const int C = add_point(c + Vec2(0, R_i)), B = add_point(c + Vec2(L_in, R_i));
  const int outer_in = geo::addLine(A, H), outer_arc_1 = add_arc(H, centre, outer_mid);
  const int outer_arc_2 = add_arc(outer_mid, centre, G), outer_out = geo::addLine(G, F);
  const int outflow = geo::addLine(F, E);
  const int inner_out = geo::addLine(E, D), inner_arc_1 = add_arc(D, centre, inner_mid);
  const int inner_arc_2 = add_arc(inner_mid, centre, C), inner_in = geo::addLine(C, B);
  const int inflow = geo::addLine(B, A);
  BoundaryGroups groups;
  groups.add("inflow", inflow);
  groups.add("outflow", outflow);
  for (int curve : {inner_out, inner_arc_1, inner_arc_2, inner_in}) groups.add("bank_inner", curve);
  for (int curve : {outer_in, outer_arc_1, outer_arc_2, outer_out}) groups.add("bank_outer", curve);
  const std::vector<int> loop = {outer_in,  outer_arc_1, outer_arc_2, outer_out, outflow,
                                 inner_out, inner_arc_1, inner_arc_2, inner_in,  inflow};
  return mesh_current_model(source, {geo::addCurveLoop(loop)}, groups, msh_path, format, order);
}

RawMesh generate_polygon_mesh(const PolygonGeometry& polygon, const std::string& msh_path,
                              const MshFormat& format, int order) {
  const std::string source = "generated polygon";
  check_polygon(polygon, source);
  GmshSession session;
  set_common_options(polygon.mesh_size);
  const Vec2 origin = local_origin(polygon.points);
  std::vector<int> points, sides;
  for (const Vec2& p : polygon.points) points.push_back(add_point(p - origin));
  BoundaryGroups groups;
  for (std::size_t i = 0; i < points.size(); ++i) {
    sides.push_back(geo::addLine(points[i], points[(i + 1) % points.size()]));
    groups.add(polygon.groups[i], sides.back());
  }
  return mesh_current_model(source, {geo::addCurveLoop(sides)}, groups, msh_path, format, order,
                            origin);
}

Mesh generate_mesh(const MeshSource& source, const std::string& msh_path, const MshFormat& format) {
  switch (source.kind) {
    case MeshSource::Kind::file: {
      Mesh mesh = read_msh(source.file);
      if (!msh_path.empty()) {  // a copy in the asked format
        GmshSession session;
        try {
          gmsh::open(source.file);
        } catch (...) {
          throw_input_error("{}: Gmsh cannot read the mesh file: {}", source.file,
                            current_gmsh_error());
        }
        write_current_model(msh_path, format);
      }
      return mesh;
    }
    case MeshSource::Kind::channel:
      return build_mesh(
          generate_channel_mesh(source.channel, msh_path, format, source.element_order));
    case MeshSource::Kind::bend:
      return build_mesh(generate_bend_mesh(source.bend, msh_path, format, source.element_order));
    case MeshSource::Kind::polygon:
      return build_mesh(
          generate_polygon_mesh(source.polygon, msh_path, format, source.element_order));
    case MeshSource::Kind::region:
      return build_mesh(
          generate_region_mesh(source.region, msh_path, format, source.element_order));
  }
  throw_input_error("mesh source: unknown kind {}", static_cast<int>(source.kind));
}

}  // namespace flotsam
