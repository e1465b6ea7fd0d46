// Fuzzes the mesh reader (mesh/msh_reader.hpp: the structure check of mesh/msh_check.hpp, then
// Gmsh's parser on what passed it, then build_mesh's checks): any file is a mesh or an InputError,
// never a crash or another exception. The corpus holds one small mesh in each of the four MSH
// flavours (2.2 / 4.1, ASCII / binary).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "mesh/msh_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = "/tmp/flotsam_fuzz_" + std::to_string(getpid()) + ".msh";
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    flotsam::read_msh(path);
  } catch (const flotsam::InputError&) {
    // the expected answer to bad input
  }
  return 0;
}
