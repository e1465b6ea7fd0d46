#pragma once
// For tests of the case reader: a case's text with one piece replaced, and the message of the
// InputError that parsing a case's text raises.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "io/case_file.hpp"

namespace flotsam::test {

/// `text` with `from` replaced by `to` (`from` must occur).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

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
