// Fuzzes the vector reader (geo/vector_layer.hpp: OGR's drivers, then flotsam's checks of the
// polygons, lines and attributes): any file is a layer or an InputError, never a crash or another
// exception. The corpus holds small GeoPackages and GeoJSON files of polygons (with a value
// attribute) and of named lines, as the region, zone and boundary keys read them.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "geo/vector_layer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // GDAL picks the driver from the content (a GeoPackage's SQLite header, GeoJSON's braces).
  static const std::string path = "/tmp/flotsam_fuzz_" + std::to_string(getpid()) + ".vector";
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    (void)flotsam::read_vector_layer(path, "", "fuzz: mesh.region.buildings", "n", "name");
  } catch (const flotsam::InputError&) {
    // the expected answer to bad input
  }
  return 0;
}
