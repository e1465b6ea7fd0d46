#pragma once
// One data variable of a UGRID NetCDF result file (ugrid_writer.hpp): what the engines name when
// they give their fields (flow/result_fields.hpp), apart from the writer itself.
#include <string>

namespace flotsam {

enum class UgridLocation { node, face };

/// One data variable of the file.
struct UgridVariable {
  std::string name;           // NetCDF name, e.g. "depth"
  std::string long_name;      // unique; a vector's components end in ", x-component" and
                              // ", y-component" (the only pairing MDAL 0.9.4 makes)
  std::string standard_name;  // CF standard name, or "": none written
  std::string units;          // UDUNITS: "m", "m s-1", "1"
  UgridLocation location = UgridLocation::face;
  bool timed = true;  // (time, location) when true; (location) when false: a static field
                      // (envelopes), never a vector component (MDAL reads y as x)
};

}  // namespace flotsam
