#include "mesh/gmsh_model.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "core/error.hpp"
#include "mesh/gmsh_session.hpp"
#include "mesh/msh_reader.hpp"

namespace flotsam {

namespace geo = gmsh::model::geo;

namespace {

constexpr int frontal_delaunay = 6;    // Gmsh Mesh.Algorithm
constexpr int distance_samples = 200;  // [-] points per curve for the Distance fields

}  // namespace

int add_arc(int from, int centre, int to) {
  return geo::addCircleArc(from, centre, to);
}

int add_point(const Vec2& p) {
  return geo::addPoint(p.x(), p.y(), 0.0);
}

std::vector<int> add_circle(const Vec2& centre, double radius) {
  const int c = add_point(centre);
  std::vector<int> points;
  for (const Vec2& direction : {Vec2(1, 0), Vec2(0, 1), Vec2(-1, 0), Vec2(0, -1)})
    points.push_back(add_point(centre + radius * direction));
  std::vector<int> arcs;
  for (int k = 0; k < 4; ++k) arcs.push_back(add_arc(points[k], c, points[(k + 1) % 4]));
  return arcs;
}

void BoundaryGroups::add(const std::string& name, int curve) {
  auto found = std::find_if(groups_.begin(), groups_.end(),
                            [&](const auto& group) { return group.first == name; });
  if (found == groups_.end()) {
    groups_.push_back({name, {}});
    found = groups_.end() - 1;
  }
  found->second.push_back(curve);
}

void BoundaryGroups::create(int surface) const {
  for (const auto& [name, curves] : groups_)
    gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, curves), name);
  gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {surface}), "water");
}

void set_common_options(double mesh_size) {
  gmsh::option::setNumber("Mesh.Algorithm", frontal_delaunay);
  gmsh::option::setNumber("Mesh.MeshSizeMax", mesh_size);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.SecondOrderLinear", 0);  // mid nodes on the curves
  gmsh::option::setNumber("Mesh.HighOrderOptimize", 0);
}

void write_current_model(const std::string& msh_path, const MshFormat& format) {
  if (format.version != 2.2 && format.version != 4.1)
    throw_input_error("{}: MSH format version {} is not supported; expected 2.2 or 4.1", msh_path,
                      format.version);
  try {
    gmsh::option::setNumber("Mesh.MshFileVersion", format.version);
    gmsh::option::setNumber("Mesh.Binary", format.binary ? 1 : 0);
    gmsh::option::setNumber("Mesh.SaveAll", 0);  // only elements in physical groups
    gmsh::write(msh_path);
  } catch (...) {
    throw_input_error("{}: Gmsh cannot write the mesh: {}", msh_path, current_gmsh_error());
  }
  if (!std::ifstream(msh_path).good())
    throw_input_error("{}: the mesh file could not be written (does its folder exist?)", msh_path);
}

Vec2 local_origin(const std::vector<Vec2>& points) {
  constexpr double step = 1e4;  // [m]
  Vec2 lo = points.empty() ? Vec2::Zero() : points.front();
  for (const Vec2& p : points) lo = lo.cwiseMin(p);
  return {step * std::trunc(lo.x() / step), step * std::trunc(lo.y() / step)};
}

/// Steps 2-4 after the boundary is built: surface, groups, mesh, write, extract.
RawMesh mesh_current_model(const std::string& source, const std::vector<int>& loops,
                           const BoundaryGroups& groups, const std::string& msh_path,
                           const MshFormat& format, int order, const Vec2& origin) {
  try {
    const int surface = geo::addPlaneSurface(loops);
    geo::synchronize();
    groups.create(surface);
    gmsh::model::mesh::generate(2);
    if (order == 2) gmsh::model::mesh::setOrder(2);
    if (origin != Vec2::Zero()) {  // back to the caller's coordinates
      std::vector<std::size_t> tags;
      std::vector<double> xyz, uvw;
      gmsh::model::mesh::getNodes(tags, xyz, uvw, -1, -1, false, false);
      for (std::size_t k = 0; k < tags.size(); ++k)
        gmsh::model::mesh::setNode(
            tags[k], {xyz[3 * k] + origin.x(), xyz[3 * k + 1] + origin.y(), xyz[3 * k + 2]}, {});
    }
  } catch (...) {
    throw_input_error("{}: Gmsh cannot mesh the geometry: {}", source, current_gmsh_error());
  }
  if (!msh_path.empty()) write_current_model(msh_path, format);
  return raw_mesh_from_gmsh_model(source);
}

void require_positive(const std::string& source, const char* key, double value) {
  if (!(value > 0)) throw_input_error("{}: {} must be positive; got {}", source, key, value);
}

int add_distance_size_field(const std::vector<int>& curves, double size_near, double size_far,
                            double distance) {
  namespace field = gmsh::model::mesh::field;
  const int d = field::add("Distance");
  field::setNumbers(d, "CurvesList", {curves.begin(), curves.end()});
  field::setNumber(d, "NNodesByEdge", distance_samples);
  const int threshold = field::add("Threshold");
  field::setNumber(threshold, "InField", d);
  field::setNumber(threshold, "LcMin", size_near);
  field::setNumber(threshold, "LcMax", size_far);
  field::setNumber(threshold, "DistMin", 0.0);
  field::setNumber(threshold, "DistMax", distance);
  return threshold;
}

}  // namespace flotsam
