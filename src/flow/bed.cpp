#include "flow/bed.hpp"

namespace flotsam {

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
  }
  return bed.level;
}

BedFunction make_bed_function(const BedConfig& bed) {
  return [bed](const Vec2& p) { return bed_elevation(bed, p); };
}

}  // namespace flotsam
