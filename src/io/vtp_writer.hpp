#pragma once
// Bodies and the domain's boundary for ParaView, as VTK XML PolyData (.vtp) files with binary
// appended data. See docs/output-format.md.
#include <array>
#include <span>
#include <string>
#include <vector>

#include "bodies/body_set.hpp"
#include "core/vec.hpp"
#include "mesh/mesh.hpp"

namespace flotsam {

/// Extra per-body cell arrays (forces, contact counts, ...), one value per body INDEX
/// (bodies.size() values, gone bodies included; their values are skipped with them). The arrays
/// are views and must live until write_bodies_vtp returns. Names are free text with units.
class BodyFields {
 public:
  void add_scalar(std::string name, std::span<const double> values);
  /// Written with z = 0.
  void add_vector(std::string name, std::span<const Vec2> values);

  struct Scalar {
    std::string name;
    std::span<const double> values;
  };
  struct Vector {
    std::string name;
    std::span<const Vec2> values;
  };
  const std::vector<Scalar>& scalars() const { return scalars_; }
  const std::vector<Vector>& vectors() const { return vectors_; }

 private:
  std::vector<Scalar> scalars_;
  std::vector<Vector> vectors_;
};

/// The four corners of body i's rectangle [m], counter-clockwise: x_G + R(theta) c for c =
/// (-L/2, -l/2), (L/2, -l/2), (L/2, l/2), (-L/2, l/2) in body axes (long axis first).
std::array<Vec2, 4> body_corners(const BodySet& bodies, int i);

/// Writes every body that is not gone as a 4-point polygon, with cell data "id",
/// "state" (0 floating, 1 grounded), "velocity [m/s]" (3 components, z = 0),
/// "angular_velocity [rad/s]", "angle [rad]", "length [m]", "width [m]" and the extra arrays, and
/// the time [s] as FieldData "TimeValue". Throws std::invalid_argument when an extra array's
/// length differs from bodies.size(), InputError when the file cannot be written.
void write_bodies_vtp(const std::string& path, const BodySet& bodies, const BodyFields& extra,
                      double time);

/// Writes the mesh's boundary edges as 3-point polylines (vertex, mid node, vertex) with cell data
/// "group" (index into mesh.group_names) and the group names as FieldData "group_names".
void write_boundary_vtp(const std::string& path, const Mesh& mesh);

}  // namespace flotsam
