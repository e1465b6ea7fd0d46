#pragma once
// For tests of the case reader: the message of the InputError that parsing a case's text raises.
#include <string>

#include "core/error.hpp"
#include "io/case_file.hpp"

namespace flotsam::test {

/// The message of the InputError parsing `text` (read as the file `file`) throws, or "no error".
inline std::string error_of(const std::string& text, const std::string& file = "case.yaml") {
  try {
    parse_case(text, file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace flotsam::test
