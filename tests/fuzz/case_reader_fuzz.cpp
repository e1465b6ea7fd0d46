// Fuzzes the case reader (io/case_file.hpp): any text is a case or an InputError, never a crash,
// a hang or another exception.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/error.hpp"
#include "io/case_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    flotsam::parse_case(text, "fuzz/case.yaml");  // relative files are looked up in fuzz/
  } catch (const flotsam::InputError&) {
    // the expected answer to bad input
  }
  return 0;
}
