#include "flow/bed.hpp"

#include "core/error.hpp"

namespace flotsam {

namespace {

/// The raster's value at p, or an InputError saying why there is none (without the node).
double raster_elevation(const BedConfig& bed, const Vec2& p, const std::string& where) {
  const Raster& raster = *bed.raster;
  if (const auto z = raster.bilinear(p))
    return bed.expression.empty() ? *z : bed.expression(p.x(), p.y(), *z);
  const auto pixel = raster.pixel_of(p);
  throw_input_error("{}: the terrain raster '{}' has no value at {}(x, y) = ({:.3f}, {:.3f}) m: {}",
                    bed.origin, raster.path(), where, p.x(), p.y(),
                    pixel ? fmt::format("a pixel next to it (column {}, row {}) holds nodata",
                                        pixel->first, pixel->second)
                          : "the point lies outside the raster's extent");
}

}  // namespace

double bed_elevation(const BedConfig& bed, const Vec2& p) {
  switch (bed.kind) {
    case BedConfig::Kind::flat:
      return bed.level;
    case BedConfig::Kind::slope:
      return bed.level - bed.slope.dot(p);
    case BedConfig::Kind::table:
      return bed.profile_x(p.x());
    case BedConfig::Kind::expression:
      return bed.expression(p.x(), p.y());  // an InputError where the formula is not finite
    case BedConfig::Kind::raster:
      return raster_elevation(bed, p, "");
  }
  return bed.level;
}

BedFunction make_bed_function(const BedConfig& bed) {
  return [bed](const Vec2& p) { return bed_elevation(bed, p); };
}

std::vector<double> bed_at_nodes(const Mesh& mesh, const BedConfig& bed) {
  std::vector<double> z(mesh.nodes.size());
  if (bed.kind != BedConfig::Kind::raster) {
    for (std::size_t k = 0; k < z.size(); ++k) z[k] = bed_elevation(bed, mesh.nodes[k]);
    return z;
  }
  std::vector<int> element_of(mesh.nodes.size(), -1);  // one element holding each node
  for (int e = 0; e < mesh.element_count(); ++e)
    for (int k : mesh.elements[e]) element_of[k] = e;
  for (std::size_t k = 0; k < z.size(); ++k) {
    const int e = element_of[k];
    const std::string where = fmt::format(
        "node {}{} ", k < mesh.node_tags.size() ? mesh.node_tags[k] : static_cast<long>(k),
        e < 0 ? std::string()
              : fmt::format(" of element {}", static_cast<std::size_t>(e) < mesh.element_tags.size()
                                                  ? mesh.element_tags[e]
                                                  : static_cast<long>(e)));
    z[k] = raster_elevation(bed, mesh.nodes[k], where);
  }
  return z;
}

}  // namespace flotsam
