#pragma once
// Files that several runs write the same, byte for byte (the flow fields of an ensemble's
// members that replay one shared flow, coupling/shared_flow.hpp): written once into a shared
// folder and given to each run as a hard link, so that every run's folder still holds the file
// itself (a member rerun alone, or read by ParaView, finds it there) at the cost of one directory
// entry instead of a file's writing.
#include <filesystem>
#include <functional>
#include <string>

namespace flotsam {

/// Puts the file `name` of `shared_folder` at `path`: a hard link to the shared copy when there
/// is one (a copy when the two are on different devices); else `write(path)` writes the file and
/// it becomes the shared copy for the runs after (when the folder exists; runs racing to share
/// the same file each keep their own, all the same). The caller vouches that every run writing
/// `name` into this folder writes the same bytes.
void write_shared_file(const std::filesystem::path& shared_folder, const std::string& name,
                       const std::filesystem::path& path,
                       const std::function<void(const std::string&)>& write);

/// A hard link to `from` at `to` (replacing a file there); a copy when a link cannot be made
/// (another device, a file system without hard links), through a temporary name and a rename.
/// InputError naming both when neither works.
void link_or_copy(const std::filesystem::path& from, const std::filesystem::path& to);

}  // namespace flotsam
