#include "io/vtu_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include "io/vtk_xml.hpp"

namespace flotsam {

namespace {

constexpr std::uint8_t vtk_quadratic_triangle = 22;  // VTK cell types
constexpr std::uint8_t vtk_triangle = 5;

void check_size(const VtuFields::Field& field, std::size_t size, std::size_t expected,
                const char* what) {
  if (size != expected)
    throw std::invalid_argument(fmt::format("write_vtu: field '{}' has {} values; expected {} ({})",
                                            field.name, size, expected, what));
}

}  // namespace

void VtuFields::add_point_scalar(std::string name, std::span<const double> values) {
  fields_.push_back({std::move(name), Kind::point_scalar, values, {}});
}

void VtuFields::add_point_vector(std::string name, std::span<const Vec2> values) {
  fields_.push_back({std::move(name), Kind::point_vector, {}, values});
}

void VtuFields::add_p1_scalar(std::string name, std::span<const double> values) {
  fields_.push_back({std::move(name), Kind::p1_scalar, values, {}});
}

void VtuFields::add_cell_scalar(std::string name, std::span<const double> values) {
  fields_.push_back({std::move(name), Kind::cell_scalar, values, {}});
}

void VtuFields::add_cell_vector(std::string name, std::span<const Vec2> values) {
  fields_.push_back({std::move(name), Kind::cell_vector, {}, values});
}

std::vector<double> p1_to_p2(const Mesh& mesh, std::span<const double> vertex_values) {
  if (vertex_values.size() != static_cast<std::size_t>(mesh.vertex_count))
    throw std::invalid_argument(fmt::format("p1_to_p2: {} values for {} vertices",
                                            vertex_values.size(), mesh.vertex_count));
  std::vector<double> values(mesh.nodes.size());
  std::copy(vertex_values.begin(), vertex_values.end(), values.begin());
  for (const auto& element : mesh.elements)
    for (int k = 0; k < 3; ++k)  // mid node 3+k of edge (k, k+1): linear interpolation
      values[element[3 + k]] =
          0.5 * (vertex_values[element[k]] + vertex_values[element[(k + 1) % 3]]);
  return values;
}

void write_vtu(const std::string& path, const Mesh& mesh, const VtuFields& fields, double time,
               VtuCells cells) {
  const std::size_t nodes = mesh.nodes.size();
  const bool split = cells == VtuCells::split;
  const std::size_t elements = mesh.elements.size() * (split ? 4 : 1);
  const char* per_cell = split ? "one per sub-triangle" : "one per element";
  AppendedData data;
  std::string point_data, cell_data;
  for (const VtuFields::Field& field : fields.fields()) {
    switch (field.kind) {
      case VtuFields::Kind::point_scalar:
        check_size(field, field.scalars.size(), nodes, "one per P2 node");
        point_data += data.add_float64(field.name, 1, field.scalars) + "\n";
        break;
      case VtuFields::Kind::point_vector:
        check_size(field, field.vectors.size(), nodes, "one per P2 node");
        point_data += data.add_vec2_as_3d(field.name, field.vectors) + "\n";
        break;
      case VtuFields::Kind::p1_scalar:
        check_size(field, field.scalars.size(), static_cast<std::size_t>(mesh.vertex_count),
                   "one per P1 vertex");
        point_data += data.add_float64(field.name, 1, p1_to_p2(mesh, field.scalars)) + "\n";
        break;
      case VtuFields::Kind::cell_scalar:
        check_size(field, field.scalars.size(), elements, per_cell);
        cell_data += data.add_float64(field.name, 1, field.scalars) + "\n";
        break;
      case VtuFields::Kind::cell_vector:
        check_size(field, field.vectors.size(), elements, per_cell);
        cell_data += data.add_vec2_as_3d(field.name, field.vectors) + "\n";
        break;
    }
  }

  std::vector<std::int64_t> connectivity, offsets;
  connectivity.reserve((split ? 3 : 6) * elements);
  offsets.reserve(elements);
  for (const auto& element : mesh.elements) {
    if (split) {
      for (const auto& corners : Mesh::sub_triangles) {
        for (int k : corners) connectivity.push_back(element[k]);
        offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
      }
    } else {
      connectivity.insert(connectivity.end(), element.begin(), element.end());
      offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
    }
  }
  const std::vector<std::uint8_t> types(elements, split ? vtk_triangle : vtk_quadratic_triangle);

  std::string body = "<UnstructuredGrid>\n" + data.field_data_time(time);
  body += fmt::format("<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", nodes, elements);
  body += "<PointData>\n" + point_data + "</PointData>\n";
  body += "<CellData>\n" + cell_data + "</CellData>\n";
  body += "<Points>\n" + data.add_vec2_as_3d("Points", mesh.nodes) + "\n</Points>\n";
  body += "<Cells>\n" + data.add_int64("connectivity", connectivity) + "\n" +
          data.add_int64("offsets", offsets) + "\n" + data.add_uint8("types", types) + "\n";
  body += "</Cells>\n</Piece>\n</UnstructuredGrid>\n";
  write_vtk_xml_file(path, "UnstructuredGrid", body, data);
}

}  // namespace flotsam
