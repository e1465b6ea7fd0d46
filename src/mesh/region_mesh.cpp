// A domain from geodata (RegionGeometry, geometry.hpp) -> checked rings -> Gmsh model -> mesh.
//
//   1. clean: consecutive vertices closer than merge_distance merged, buildings smaller than
//      min_building_area dropped (a warning names them), never meshed as slivers;
//   2. check: every ring simple, every hole inside the outline and apart from every other hole;
//      errors name the features (file, layer, feature id) and what is wrong;
//   3. boundary lines: their ends are inserted into the outline where they fall on a side, and
//      every side lying along a line takes its group, the others default_group;
//   4. the outline and its holes as curve loops, built around a local origin (local_origin: map
//      coordinates far from 0 stall Gmsh); sizes: Threshold fields of the distance to the
//      buildings and to the piers, their minimum, and size_at (steep terrain) through Gmsh's
//      size callback; then the common mesh, order 2, nodes moved back, write, extract
//      (gmsh_model.hpp).
#include <gmsh.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "mesh/gmsh_model.hpp"
#include "mesh/gmsh_session.hpp"
#include "mesh/mesh_generator.hpp"
#include "mesh/simple_polygon.hpp"

namespace flotsam {
namespace {

namespace geo = gmsh::model::geo;

const std::string source = "mesh.region";

/// Consecutive points closer than `merge` become one (the first); the closing repeat goes.
std::vector<Vec2> cleaned(std::vector<Vec2> ring, double merge) {
  std::vector<Vec2> out;
  for (const Vec2& p : ring)
    if (out.empty() || (p - out.back()).norm() > merge) out.push_back(p);
  while (out.size() > 1 && (out.front() - out.back()).norm() <= merge) out.pop_back();
  return out;
}

void check_simple(const NamedRing& ring) {
  const auto& p = ring.points;
  if (p.size() < 3)
    throw_input_error("{}: {} has fewer than 3 distinct corners; it is not a polygon", source,
                      ring.name);
  if (const auto crossing = first_crossing(p)) {
    const auto [i, j] = *crossing;
    throw_input_error(
        "{}: {} intersects itself: its side from ({:.3f}, {:.3f}) to ({:.3f}, {:.3f}) meets its "
        "side from ({:.3f}, {:.3f}) to ({:.3f}, {:.3f}) m",
        source, ring.name, p[i].x(), p[i].y(), p[(i + 1) % p.size()].x(), p[(i + 1) % p.size()].y(),
        p[j].x(), p[j].y(), p[(j + 1) % p.size()].x(), p[(j + 1) % p.size()].y());
  }
}

/// A hole of the domain, as a ring (a circle as its 64-gon for the checks).
struct Hole {
  std::vector<Vec2> ring;
  std::string name;
  Vec2 lo, hi;  // bounding box [m]
};

Hole make_hole(std::vector<Vec2> ring, std::string name) {
  Hole h{std::move(ring), std::move(name), {}, {}};
  h.lo = h.hi = h.ring.front();
  for (const Vec2& p : h.ring) h.lo = h.lo.cwiseMin(p), h.hi = h.hi.cwiseMax(p);
  return h;
}

void check_holes(const NamedRing& outline, const std::vector<Hole>& holes) {
  for (const Hole& h : holes) {
    for (std::size_t i = 0; i < outline.points.size(); ++i)
      for (std::size_t j = 0; j < h.ring.size(); ++j)
        if (segments_meet(outline.points[i], outline.points[(i + 1) % outline.points.size()],
                          h.ring[j], h.ring[(j + 1) % h.ring.size()]))
          throw_input_error("{}: {} crosses the outline ({}) near ({:.3f}, {:.3f}) m", source,
                            h.name, outline.name, h.ring[j].x(), h.ring[j].y());
    if (!polygon_contains(outline.points, h.ring.front()))
      throw_input_error("{}: {} lies outside the outline ({})", source, h.name, outline.name);
  }
  // Pairs whose boxes touch are tested exactly (sorted by x_min: a sweep along x).
  std::vector<int> order(holes.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return holes[a].lo.x() < holes[b].lo.x(); });
  for (std::size_t a = 0; a < order.size(); ++a)
    for (std::size_t b = a + 1; b < order.size(); ++b) {
      const Hole &p = holes[order[a]], &q = holes[order[b]];
      if (q.lo.x() > p.hi.x()) break;
      if (q.lo.y() > p.hi.y() || q.hi.y() < p.lo.y()) continue;
      if (polygons_overlap(p.ring, q.ring))
        throw_input_error("{}: {} and {} overlap; footprints, piers and islands must be apart",
                          source, p.name, q.name);
    }
}

/// Inserts the ends of the lines into the outline where they fall on a side, then names each
/// side: the group of the line it lies along, else the default.
std::vector<std::string> side_groups(std::vector<Vec2>& outline, const RegionGeometry& g) {
  const double tol = std::max(g.merge(), 1e-9);
  for (const BoundaryLine& line : g.lines)
    for (const Vec2& end : {line.points.front(), line.points.back()}) {
      const std::size_t n = outline.size();
      bool at_corner = false;
      for (const Vec2& p : outline) at_corner |= (p - end).norm() <= tol;
      if (at_corner) continue;
      for (std::size_t i = 0; i < n; ++i)
        if (distance_to_segment(end, outline[i], outline[(i + 1) % n]) <= tol) {
          outline.insert(outline.begin() + static_cast<long>(i) + 1, end);
          break;
        }
    }
  const std::size_t n = outline.size();
  std::vector<std::string> groups(n, g.default_group);
  const auto near_line = [&](const BoundaryLine& line, const Vec2& p) {
    for (std::size_t k = 0; k + 1 < line.points.size(); ++k)
      if (distance_to_segment(p, line.points[k], line.points[k + 1]) <= tol) return true;
    return false;
  };
  for (const BoundaryLine& line : g.lines) {
    int claimed = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 &a = outline[i], &b = outline[(i + 1) % n];
      if (near_line(line, a) && near_line(line, b) && near_line(line, 0.5 * (a + b))) {
        groups[i] = line.group;
        ++claimed;
      }
    }
    if (claimed == 0) {
      double nearest = 1e300;
      for (std::size_t i = 0; i < n; ++i)
        nearest = std::min(
            nearest, distance_to_segment(line.points.front(), outline[i], outline[(i + 1) % n]));
      throw_input_error(
          "{}: the boundary line '{}' ({}) does not lie along the outline: no side of it is "
          "within {} m of the line (its first point is {:.3f} m from the outline)",
          source, line.group, line.name, tol, nearest);
    }
  }
  return groups;
}

int add_loop(const std::vector<Vec2>& ring, const Vec2& origin, const std::string& group,
             BoundaryGroups& groups, std::vector<int>* curves) {
  std::vector<int> points, sides;
  for (const Vec2& p : ring) points.push_back(add_point(p - origin));
  for (std::size_t i = 0; i < points.size(); ++i) {
    sides.push_back(geo::addLine(points[i], points[(i + 1) % points.size()]));
    groups.add(group, sides.back());
  }
  if (curves) curves->insert(curves->end(), sides.begin(), sides.end());
  return geo::addCurveLoop(sides);
}

}  // namespace

RawMesh generate_region_mesh(const RegionGeometry& g, const std::string& msh_path,
                             const MshFormat& format, int order) {
  for (auto [key, value] :
       {std::pair{"mesh_size", g.mesh_size}, std::pair{"building_mesh_size", g.building_mesh_size},
        std::pair{"pier_mesh_size", g.pier_mesh_size}})
    require_positive(source, key, value);
  NamedRing outline{cleaned(g.outline.points, g.merge()), g.outline.name};
  check_simple(outline);

  std::vector<Hole> holes;
  std::vector<NamedRing> islands, buildings, pier_outlines;
  for (const NamedRing& r : g.islands) {
    islands.push_back({cleaned(r.points, g.merge()), r.name});
    check_simple(islands.back());
    holes.push_back(make_hole(islands.back().points, islands.back().name));
  }
  std::vector<std::string> dropped;
  for (const NamedRing& r : g.buildings) {
    NamedRing b{cleaned(r.points, g.merge()), r.name};
    if (b.points.size() >= 3) check_simple(b);  // a crossed footprint is an error, not a sliver
    if (b.points.size() < 3 || std::abs(signed_area(b.points)) < g.smallest_building()) {
      dropped.push_back(b.name);
      continue;
    }
    holes.push_back(make_hole(b.points, b.name));
    buildings.push_back(std::move(b));
  }
  if (!dropped.empty())
    spdlog::warn(
        "{}: {} building footprint(s) smaller than {} m^2 left out (not meshed; "
        "mesh.region.min_building_area): {}",
        source, dropped.size(), g.smallest_building(), fmt::join(dropped, "; "));
  for (std::size_t k = 0; k < g.piers.size(); ++k) {
    const Pier& p = g.piers[k];
    require_positive(source, "a pier's radius", p.radius);
    std::vector<Vec2> polygon;  // the circle as a 64-gon, for the checks
    for (int i = 0; i < 64; ++i) {
      const double a = 2.0 * pi * i / 64;  // [rad]
      polygon.push_back(p.centre + p.radius * Vec2(std::cos(a), std::sin(a)));
    }
    holes.push_back(make_hole(polygon, fmt::format("pier_{} (centre ({}, {}) m, radius {} m)",
                                                   k + 1, p.centre.x(), p.centre.y(), p.radius)));
  }
  for (const NamedRing& r : g.pier_outlines) {
    pier_outlines.push_back({cleaned(r.points, g.merge()), r.name});
    check_simple(pier_outlines.back());
    holes.push_back(make_hole(pier_outlines.back().points, r.name));
  }
  check_holes(outline, holes);
  const std::vector<std::string> groups_of_sides = side_groups(outline.points, g);

  GmshSession session;
  set_common_options(g.mesh_size);
  const Vec2 origin = local_origin(outline.points);  // the model is built at p - origin
  BoundaryGroups groups;
  std::vector<int> loops, outline_points, outline_sides;
  for (const Vec2& p : outline.points) outline_points.push_back(add_point(p - origin));
  for (std::size_t i = 0; i < outline_points.size(); ++i) {
    outline_sides.push_back(
        geo::addLine(outline_points[i], outline_points[(i + 1) % outline_points.size()]));
    groups.add(groups_of_sides[i], outline_sides.back());
  }
  loops.push_back(geo::addCurveLoop(outline_sides));
  for (const NamedRing& r : islands)
    loops.push_back(add_loop(r.points, origin, g.default_group, groups, nullptr));
  std::vector<int> building_curves, pier_curves;
  for (const NamedRing& r : buildings)
    loops.push_back(add_loop(r.points, origin, "buildings", groups, &building_curves));
  for (std::size_t k = 0; k < g.piers.size(); ++k) {
    const auto arcs = add_circle(g.piers[k].centre - origin, g.piers[k].radius);
    for (int arc : arcs) groups.add(fmt::format("pier_{}", k + 1), arc);
    pier_curves.insert(pier_curves.end(), arcs.begin(), arcs.end());
    loops.push_back(geo::addCurveLoop(arcs));
  }
  for (std::size_t k = 0; k < pier_outlines.size(); ++k)
    loops.push_back(add_loop(pier_outlines[k].points, origin,
                             fmt::format("pier_{}", g.piers.size() + k + 1), groups, &pier_curves));
  geo::synchronize();
  namespace field = gmsh::model::mesh::field;
  std::vector<double> fields;
  if (!building_curves.empty())
    fields.push_back(add_distance_size_field(building_curves, g.building_mesh_size, g.mesh_size,
                                             g.refine_distance));
  if (!pier_curves.empty())
    fields.push_back(
        add_distance_size_field(pier_curves, g.pier_mesh_size, g.mesh_size, g.refine_distance));
  if (!fields.empty()) {
    const int smallest = field::add("Min");
    field::setNumbers(smallest, "FieldsList", fields);
    field::setAsBackgroundMesh(smallest);
  }
  if (g.size_at)
    gmsh::model::mesh::setSizeCallback([&g, origin](int, int, double x, double y, double) {
      return std::min(g.size_at(origin + Vec2(x, y)), g.mesh_size);
    });
  return mesh_current_model(source, loops, groups, msh_path, format, order, origin);
}

}  // namespace flotsam
