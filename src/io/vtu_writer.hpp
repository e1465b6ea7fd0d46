#pragma once
// Flow fields for ParaView: the P2 mesh as a VTK XML UnstructuredGrid (.vtu) of quadratic
// triangles (VTK_QUADRATIC_TRIANGLE, type 22), whose node order v0 v1 v2 m01 m12 m20 is the
// mesh's own; or, for the finite-volume engine's cells, each element split into its four
// straight sub-triangles (VTK_TRIANGLE, type 5; flow/fv/cell_mesh.hpp order). Every P2 node is a
// point. See docs/output-format.md.
#include <span>
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

/// The arrays one .vtu file carries. The fields are views: the arrays they refer to must live
/// until write_vtu returns. Names are free text (units included, e.g. "H [m]").
class VtuFields {
 public:
  /// A P2 scalar: one value per mesh node (node_count).
  void add_point_scalar(std::string name, std::span<const double> values);
  /// A P2 vector: one value per mesh node, written with z = 0.
  void add_point_vector(std::string name, std::span<const Vec2> values);
  /// A P1 scalar: one value per vertex (vertex_count); mid nodes get the mean of their edge's
  /// two end vertices, i.e. the P1 field's own value there.
  void add_p1_scalar(std::string name, std::span<const double> values);
  /// One value per cell: per element, or per sub-triangle (VtuCells::split).
  void add_cell_scalar(std::string name, std::span<const double> values);
  void add_cell_vector(std::string name, std::span<const Vec2> values);
  // A temporary array would be gone before write_vtu: refused at compile time.
  void add_point_scalar(std::string, std::vector<double>&&) = delete;
  void add_point_vector(std::string, std::vector<Vec2>&&) = delete;
  void add_p1_scalar(std::string, std::vector<double>&&) = delete;
  void add_cell_scalar(std::string, std::vector<double>&&) = delete;
  void add_cell_vector(std::string, std::vector<Vec2>&&) = delete;

  enum class Kind { point_scalar, point_vector, p1_scalar, cell_scalar, cell_vector };
  struct Field {
    std::string name;
    Kind kind;
    std::span<const double> scalars;  // point_scalar, p1_scalar, cell_scalar
    std::span<const Vec2> vectors;    // point_vector, cell_vector
  };
  const std::vector<Field>& fields() const { return fields_; }

 private:
  std::vector<Field> fields_;
};

/// The cells of a .vtu file: the mesh's six-node elements, or each split into four triangles.
enum class VtuCells { quadratic, split };

/// Writes the mesh and the fields at time [s] (FieldData "TimeValue") to a .vtu file. Throws
/// std::invalid_argument when a field's length does not fit the mesh (a programming error, named
/// with the field), InputError when the file cannot be written.
void write_vtu(const std::string& path, const Mesh& mesh, const VtuFields& fields, double time,
               VtuCells cells = VtuCells::quadratic);

/// A P1 field (vertex_count values) extended to all P2 nodes: mid node of an edge = mean of the
/// edge's end vertices. The values write_vtu writes for an add_p1_scalar field.
std::vector<double> p1_to_p2(const Mesh& mesh, std::span<const double> vertex_values);

}  // namespace flotsam
