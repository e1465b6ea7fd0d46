#include "io/shared_file.hpp"

#include <system_error>

#include "core/error.hpp"

namespace fs = std::filesystem;

namespace flotsam {

void link_or_copy(const fs::path& from, const fs::path& to) {
  std::error_code error;
  fs::remove(to, error);
  fs::create_hard_link(from, to, error);
  if (!error) return;
  const fs::path part = to.string() + ".part";
  fs::copy_file(from, part, fs::copy_options::overwrite_existing, error);
  if (!error) fs::rename(part, to, error);
  if (error) {
    std::error_code ignored;
    fs::remove(part, ignored);
    throw_input_error("cannot link or copy '{}' to '{}': {}", from.string(), to.string(),
                      error.message());
  }
}

void write_shared_file(const fs::path& shared_folder, const std::string& name, const fs::path& path,
                       const std::function<void(const std::string&)>& write) {
  const fs::path shared = shared_folder / name;
  std::error_code error;
  if (fs::exists(shared, error)) {
    link_or_copy(shared, path);
    return;
  }
  write(path.string());
  // The first run to write it shares it; a link that fails (another run shared it first, the
  // folder is gone or on another device) leaves this run's file as it is.
  fs::create_hard_link(path, shared, error);
}

}  // namespace flotsam
