#include "io/output_directory.hpp"

#include <cstdlib>
#include <fstream>
#include <system_error>
#include <vector>

#include "core/error.hpp"
#include "io/shared_file.hpp"

namespace fs = std::filesystem;

namespace flotsam {

namespace {

/// Absolute, with symlinks resolved as far as the path exists and no "." or "..".
fs::path resolved(const fs::path& path) {
  return fs::weakly_canonical(fs::absolute(path));
}

/// True when `inner` is `outer` or lies inside it.
bool is_within(const fs::path& inner, const fs::path& outer) {
  auto i = inner.begin();
  for (auto o = outer.begin(); o != outer.end(); ++o, ++i) {
    if (o->empty()) continue;  // trailing separator
    if (i == inner.end() || *i != *o) return false;
  }
  return true;
}

/// Refuses folders whose loss would be a disaster, whatever the overwrite flag.
void refuse_dangerous(const std::string& directory, const fs::path& folder,
                      const std::string& case_file, const std::vector<ProtectedInput>& inputs) {
  std::vector<std::pair<fs::path, const char*>> protected_paths = {
      {resolved(fs::current_path()), "the working directory"}};
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0')
    protected_paths.emplace_back(resolved(home), "the home folder");
  if (folder == folder.root_path())
    throw_input_error("output folder '{}' is the file system root; choose another folder",
                      directory);
  for (const auto& [path, what] : protected_paths)
    if (is_within(path, folder))
      throw_input_error("output folder '{}' is or contains {} ({}); choose another folder",
                        directory, what, path.string());
  if (!case_file.empty() && is_within(resolved(case_file), folder))
    throw_input_error("output folder '{}' contains the case file '{}'; choose another folder",
                      directory, case_file);
  for (const auto& [key, file] : inputs)
    if (is_within(resolved(file), folder))
      throw_input_error(
          "output folder '{}' contains '{}', which the case reads ({}); choose another folder",
          directory, file, key);
}

/// True when the folder holds nothing but (possibly) the marker: a run that stopped before its
/// first output left nothing worth protecting.
bool holds_only_marker(const fs::path& folder) {
  for (const fs::directory_entry& entry : fs::directory_iterator(folder))
    if (entry.path().filename() != output_marker) return false;
  return true;
}

void write_marker(const fs::path& folder, const fs::path& shared_folder) {
  const auto write = [&](const std::string& path) {
    std::ofstream marker(path);
    marker << "flotsam output folder: `flotsam run --overwrite` may delete everything in it.\n";
    if (!marker) throw_input_error("cannot write in output folder '{}'", folder.string());
  };
  if (shared_folder.empty())
    write((folder / output_marker).string());
  else
    write_shared_file(shared_folder, output_marker, folder / output_marker, write);
}

}  // namespace

fs::path prepare_output_directory(const std::string& directory, bool overwrite,
                                  const std::string& case_file,
                                  const std::vector<ProtectedInput>& inputs,
                                  const fs::path& shared_folder) {
  if (directory.empty()) throw_input_error("output folder: the name is empty");
  const fs::path folder = resolved(directory);
  refuse_dangerous(directory, folder, case_file, inputs);

  std::error_code error;
  if (fs::exists(folder) && !fs::is_directory(folder))
    throw_input_error("output folder '{}' exists and is not a folder; choose another name",
                      directory);
  if (!fs::exists(folder)) {
    fs::create_directories(folder, error);
    if (error)
      throw_input_error("cannot create output folder '{}': {}", directory, error.message());
  } else if (!holds_only_marker(folder)) {
    if (!overwrite)
      throw_input_error(
          "output folder '{}' exists and is not empty; pass --overwrite (or output.overwrite: "
          "true) to replace its contents, or choose another folder",
          directory);
    if (!fs::exists(folder / output_marker))
      throw_input_error(
          "output folder '{}' is not empty and was not made by flotsam (no '{}' file in it), so "
          "--overwrite will not delete it; empty or remove it yourself, or choose another folder",
          directory, output_marker);
    for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
      fs::remove_all(entry.path(), error);  // does not follow symbolic links
      if (error)
        throw_input_error("cannot clear output folder '{}': {}: {}", directory,
                          entry.path().string(), error.message());
    }
  }
  write_marker(folder, shared_folder);
  return folder;
}

}  // namespace flotsam
