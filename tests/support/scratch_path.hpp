#pragma once
// Paths for the files a test writes: under a folder of the system's temporary folder named after
// this process (flotsam_tests_<pid>), so that two test runs side by side (the plain and the
// sanitizer build, or two users) never write into each other's files. The folder is removed when
// the test program ends.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace flotsam::test {

class ScratchFolder {
 public:
  ScratchFolder()
      : path_(std::filesystem::temp_directory_path() /
              ("flotsam_tests_" + std::to_string(getpid()))) {
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ignored;  // nothing to do about a folder that cannot be removed
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline std::filesystem::path scratch_path(const std::string& name) {
  static const ScratchFolder folder;
  return folder.path() / name;
}

/// An empty folder for the running test's files: <prefix>_<suite>_<test> in the scratch folder.
inline std::filesystem::path fresh_test_folder(const std::string& prefix) {
  const auto* info = testing::UnitTest::GetInstance()->current_test_info();
  const auto path = scratch_path(prefix + "_" + info->test_suite_name() + "_" + info->name());
  std::filesystem::remove_all(path);
  std::filesystem::create_directories(path);
  return path;
}

}  // namespace flotsam::test
