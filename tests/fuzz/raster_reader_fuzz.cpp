// Fuzzes the raster reader (geo/raster.hpp: GDAL's drivers, then flotsam's checks of the grid,
// the size and the pixels): any file is a raster or an InputError, never a crash or another
// exception. The corpus holds small GeoTIFFs: Float32 with a nodata value, Int16, a DEFLATE one,
// one without georeferencing.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "geo/raster.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = "/tmp/flotsam_fuzz_" + std::to_string(getpid()) + ".tif";
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    (void)flotsam::Raster::read(path, "fuzz: bed.raster");
  } catch (const flotsam::InputError&) {
    // the expected answer to bad input
  }
  return 0;
}
