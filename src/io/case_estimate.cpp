#include "io/case_estimate.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "mesh/msh_check.hpp"
#include "mesh/simple_polygon.hpp"

namespace flotsam {

namespace {

constexpr double largest_mesh = 5e7;         // [elements] several GB before the first step
constexpr double bytes_per_element = 600.0;  // [bytes] per output: .vtu, state and checkpoint
constexpr double triangle_factor = 0.4330127018922193;  // sqrt(3)/4: equilateral area / h^2

/// The domain's area [m^2] and its far-field mesh size [m]; area 0 when unknown.
std::pair<double, double> area_and_size(const MeshSource& m) {
  switch (m.kind) {
    case MeshSource::Kind::channel:
      return {m.channel.length * m.channel.width, m.channel.mesh_size};
    case MeshSource::Kind::bend: {
      const BendGeometry& b = m.bend;
      const double outer = b.inner_radius + b.width;
      return {b.width * (b.inlet_length + b.outlet_length) +
                  0.5 * pi * (outer * outer - b.inner_radius * b.inner_radius),
              b.mesh_size};
    }
    case MeshSource::Kind::polygon:
      return {std::abs(signed_area(m.polygon.points)), m.polygon.mesh_size};
    case MeshSource::Kind::region:
      return {std::abs(signed_area(m.region.outline.points)), m.region.mesh_size};
    default:
      return {0.0, 1.0};
  }
}

}  // namespace

RunEstimate estimate_run(const Case& c) {
  RunEstimate e;
  if (c.mesh.kind == MeshSource::Kind::file) {
    e.elements = static_cast<double>(check_msh(c.mesh.file).triangles);
    e.counted = true;
  } else {
    const auto [area, size] = area_and_size(c.mesh);
    e.elements = area / (triangle_factor * size * size);
  }
  e.steps = std::ceil(c.time.end / c.time.step);
  e.outputs = std::floor(c.time.end / c.output.interval) + 1.0;
  e.output_bytes = e.outputs * e.elements * bytes_per_element;
  return e;
}

bool is_large(const RunEstimate& e) {
  return e.elements > 2e5 || e.steps > 1e6 || e.output_bytes > 1e10;
}

std::string describe_estimate(const RunEstimate& e) {
  const std::string elements =
      e.counted ? fmt::format("{:.0f} elements, ", e.elements)
                : (e.elements > 0.0 ? fmt::format("about {:.2g} elements, ", e.elements) : "");
  return fmt::format(
      "{}{:.6g} steps, {:.6g} outputs{}", elements, e.steps, e.outputs,
      e.output_bytes > 0.0 ? fmt::format(", about {:.2g} GB of output", e.output_bytes / 1e9) : "");
}

void check_estimate(const Case& c, const RunEstimate& e) {
  if (e.elements <= largest_mesh) return;
  if (e.counted)
    throw_input_error(
        "{}: mesh.file: '{}' holds {:.0f} triangles, more than {:.0e} (several GB of "
        "memory before the first step)",
        c.file.empty() ? "case" : c.file, c.mesh.file, e.elements, largest_mesh);
  throw_input_error(
      "{}: mesh: the domain and its mesh_size make about {:.2g} elements, more than {:.0e} "
      "(several GB of memory, hours of meshing); give a larger mesh_size",
      c.file.empty() ? "case" : c.file, e.elements, largest_mesh);
}

}  // namespace flotsam
