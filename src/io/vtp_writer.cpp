#include "io/vtp_writer.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <map>
#include <stdexcept>

#include "core/footprint_corners.hpp"
#include "io/vtk_xml.hpp"

namespace flotsam {

void BodyFields::add_scalar(std::string name, std::span<const double> values) {
  scalars_.push_back({std::move(name), values});
}

void BodyFields::add_vector(std::string name, std::span<const Vec2> values) {
  vectors_.push_back({std::move(name), values});
}

std::array<Vec2, 4> body_corners(const BodySet& bodies, int i) {
  return footprint_corners(bodies.position[i], bodies.half_extents(i), bodies.angle[i]);
}

namespace {

/// Connectivity and offsets of `count` cells of `points_per_cell` points each, numbered in order
/// (cell c uses points c * points_per_cell ...).
std::string poly_cells(AppendedData& data, std::size_t count, int points_per_cell) {
  std::vector<std::int64_t> connectivity(count * points_per_cell), offsets(count);
  for (std::size_t k = 0; k < connectivity.size(); ++k)
    connectivity[k] = static_cast<std::int64_t>(k);
  for (std::size_t c = 0; c < count; ++c)
    offsets[c] = static_cast<std::int64_t>((c + 1) * points_per_cell);
  return data.add_int64("connectivity", connectivity) + "\n" + data.add_int64("offsets", offsets) +
         "\n";
}

template <class T>
void check_size(const std::string& name, std::span<const T> values, int body_count) {
  if (values.size() != static_cast<std::size_t>(body_count))
    throw std::invalid_argument(
        fmt::format("write_bodies_vtp: body array '{}' has {} values; expected {} (one per body)",
                    name, values.size(), body_count));
}

/// values[i] for the bodies kept, in order.
template <class T>
std::vector<T> pick(std::span<const T> values, const std::vector<int>& kept) {
  std::vector<T> out;
  out.reserve(kept.size());
  for (const int i : kept) out.push_back(values[i]);
  return out;
}

}  // namespace

void write_bodies_vtp(const std::string& path, const BodySet& bodies, const BodyFields& extra,
                      double time) {
  for (const auto& s : extra.scalars()) check_size(s.name, s.values, bodies.size());
  for (const auto& v : extra.vectors()) check_size(v.name, v.values, bodies.size());
  std::vector<int> kept;
  for (int i = 0; i < bodies.size(); ++i)
    if (bodies.state[i] != BodyState::gone) kept.push_back(i);

  std::vector<Vec2> points;
  points.reserve(4 * kept.size());
  std::vector<std::int64_t> ids;
  std::vector<std::uint8_t> states;
  for (const int i : kept) {
    const auto corners = body_corners(bodies, i);
    points.insert(points.end(), corners.begin(), corners.end());
    ids.push_back(bodies.id[i]);
    states.push_back(static_cast<std::uint8_t>(bodies.state[i]));
  }

  AppendedData data;
  std::string cell_data = data.add_int64("id", ids) + "\n" + data.add_uint8("state", states) + "\n";
  cell_data += data.add_vec2_as_3d("velocity [m/s]", pick<Vec2>(bodies.velocity, kept)) + "\n";
  cell_data +=
      data.add_float64("angular_velocity [rad/s]", 1, pick<double>(bodies.angular_velocity, kept)) +
      "\n";
  cell_data += data.add_float64("angle [rad]", 1, pick<double>(bodies.angle, kept)) + "\n";
  cell_data += data.add_float64("length [m]", 1, pick<double>(bodies.length, kept)) + "\n";
  cell_data += data.add_float64("width [m]", 1, pick<double>(bodies.width, kept)) + "\n";
  for (const auto& s : extra.scalars())
    cell_data += data.add_float64(s.name, 1, pick(s.values, kept)) + "\n";
  for (const auto& v : extra.vectors())
    cell_data += data.add_vec2_as_3d(v.name, pick(v.values, kept)) + "\n";

  std::string body = "<PolyData>\n" + data.field_data_time(time);
  body += fmt::format(
      "<Piece NumberOfPoints=\"{}\" NumberOfVerts=\"0\" NumberOfLines=\"0\" "
      "NumberOfStrips=\"0\" NumberOfPolys=\"{}\">\n",
      points.size(), kept.size());
  body += "<CellData>\n" + cell_data + "</CellData>\n";
  body += "<Points>\n" + data.add_vec2_as_3d("Points", points) + "\n</Points>\n";
  body += "<Polys>\n" + poly_cells(data, kept.size(), 4) + "</Polys>\n";
  body += "</Piece>\n</PolyData>\n";
  write_vtk_xml_file(path, "PolyData", body, data);
}

void write_boundary_vtp(const std::string& path, const Mesh& mesh) {
  std::vector<Vec2> points;
  std::vector<std::int32_t> groups;
  points.reserve(3 * mesh.boundary.size());
  for (const BoundaryEdge& edge : mesh.boundary) {
    const auto [a, b, mid] = mesh.edge_nodes(edge.element, edge.local_edge);
    points.insert(points.end(), {mesh.nodes[a], mesh.nodes[mid], mesh.nodes[b]});
    groups.push_back(edge.group);
  }
  AppendedData data;
  std::string body = "<PolyData>\n<FieldData>" + data.add_strings("group_names", mesh.group_names) +
                     "</FieldData>\n";
  body += fmt::format(
      "<Piece NumberOfPoints=\"{}\" NumberOfVerts=\"0\" NumberOfLines=\"{}\" "
      "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n",
      points.size(), groups.size());
  body += "<CellData>\n" + data.add_int32("group", groups) + "\n</CellData>\n";
  body += "<Points>\n" + data.add_vec2_as_3d("Points", points) + "\n</Points>\n";
  body += "<Lines>\n" + poly_cells(data, groups.size(), 3) + "</Lines>\n";
  body += "</Piece>\n</PolyData>\n";
  write_vtk_xml_file(path, "PolyData", body, data);
}

}  // namespace flotsam
