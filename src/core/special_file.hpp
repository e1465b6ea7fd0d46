#pragma once
// Inputs are read whole from regular files: a named pipe would block the run until something
// writes to it, and a device never ends. What a path is when it is not a regular file or a
// folder, for the messages that refuse it.
#include <filesystem>
#include <string>

namespace flotsam {

/// "a named pipe", "a socket", "a device" for such a path; empty for a regular file, a folder, a
/// path that does not exist (its reader says so) or one that cannot be examined.
inline std::string special_file_kind(const std::filesystem::path& path) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error) return "";
  switch (status.type()) {
    case std::filesystem::file_type::fifo:
      return "a named pipe";
    case std::filesystem::file_type::socket:
      return "a socket";
    case std::filesystem::file_type::block:
    case std::filesystem::file_type::character:
      return "a device";
    default:
      return "";
  }
}

}  // namespace flotsam
