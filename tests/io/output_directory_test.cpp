// Verifies that prepare_output_directory follows the output folder policy: create when missing,
// refuse a non-empty folder without overwrite, empty only folders flotsam made, and never touch
// "/", the home folder, the working directory or the case file's folder; each message is checked.
#include "io/output_directory.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "../support/scratch_path.hpp"
#include "core/error.hpp"

namespace flotsam {
namespace {

namespace fs = std::filesystem;

class OutputDirectory : public ::testing::Test {
 protected:
  void SetUp() override { root_ = test::fresh_test_folder("flotsam_outdir"); }
  void TearDown() override { fs::remove_all(root_); }

  static void touch(const fs::path& path) { std::ofstream(path) << "x\n"; }

  /// The message of the InputError that prepare_output_directory throws.
  static std::string refusal(const std::string& dir, bool overwrite,
                             const std::string& case_file = "") {
    try {
      prepare_output_directory(dir, overwrite, case_file);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  }

  fs::path root_;
};

TEST_F(OutputDirectory, MissingFolderIsCreatedWithItsParentsAndMarked) {
  const fs::path dir = root_ / "a" / "b";
  const fs::path made = prepare_output_directory(dir.string(), false);
  EXPECT_EQ(made, fs::weakly_canonical(dir));
  EXPECT_TRUE(fs::is_directory(dir));
  EXPECT_TRUE(fs::exists(dir / output_marker));
}

TEST_F(OutputDirectory, EmptyFolderIsUsed) {
  const fs::path dir = root_ / "empty";
  fs::create_directories(dir);
  EXPECT_NO_THROW(prepare_output_directory(dir.string(), false));
}

TEST_F(OutputDirectory, FolderWithOnlyTheMarkerCountsAsEmpty) {
  const fs::path dir = root_ / "out";
  prepare_output_directory(dir.string(), false);
  EXPECT_NO_THROW(prepare_output_directory(dir.string(), false));
}

TEST_F(OutputDirectory, NonEmptyFolderNeedsOverwrite) {
  const fs::path dir = root_ / "out";
  prepare_output_directory(dir.string(), false);
  touch(dir / "flow.pvd");
  EXPECT_EQ(refusal(dir.string(), false),
            "output folder '" + dir.string() +
                "' exists and is not empty; pass --overwrite (or output.overwrite: true) to "
                "replace its contents, or choose another folder");
  EXPECT_TRUE(fs::exists(dir / "flow.pvd"));
}

TEST_F(OutputDirectory, OverwriteEmptiesAFolderFlotsamMade) {
  const fs::path dir = root_ / "out";
  prepare_output_directory(dir.string(), false);
  touch(dir / "flow.pvd");
  fs::create_directories(dir / "sub");
  touch(dir / "sub" / "f.vtu");
  prepare_output_directory(dir.string(), true);
  int entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1);  // only the marker
  EXPECT_TRUE(fs::exists(dir / output_marker));
}

TEST_F(OutputDirectory, OverwriteDoesNotFollowSymbolicLinks) {
  const fs::path dir = root_ / "out", precious = root_ / "precious";
  prepare_output_directory(dir.string(), false);
  fs::create_directories(precious);
  touch(precious / "keep.txt");
  fs::create_directory_symlink(precious, dir / "link");
  prepare_output_directory(dir.string(), true);
  EXPECT_FALSE(fs::exists(dir / "link"));
  EXPECT_TRUE(fs::exists(precious / "keep.txt"));
}

TEST_F(OutputDirectory, OverwriteRefusesAFolderFlotsamDidNotMake) {
  const fs::path dir = root_ / "src";
  fs::create_directories(dir);
  touch(dir / "main.cpp");
  EXPECT_EQ(refusal(dir.string(), true),
            "output folder '" + dir.string() +
                "' is not empty and was not made by flotsam (no '.flotsam-output' file in it), "
                "so --overwrite will not delete it; empty or remove it yourself, or choose "
                "another folder");
  EXPECT_TRUE(fs::exists(dir / "main.cpp"));
}

TEST_F(OutputDirectory, RootIsRefused) {
  EXPECT_EQ(refusal("/", true), "output folder '/' is the file system root; choose another folder");
}

TEST_F(OutputDirectory, WorkingDirectoryAndItsParentsAreRefused) {
  const std::string cwd = fs::weakly_canonical(fs::current_path()).string();
  EXPECT_EQ(refusal(".", true), "output folder '.' is or contains the working directory (" + cwd +
                                    "); choose another folder");
  EXPECT_EQ(refusal("..", false), "output folder '..' is or contains the working directory (" +
                                      cwd + "); choose another folder");
}

TEST_F(OutputDirectory, HomeFolderIsRefused) {
  const fs::path home = root_ / "home";
  fs::create_directories(home);
  const char* saved = std::getenv("HOME");
  const std::string saved_home = saved ? saved : "";
  setenv("HOME", home.c_str(), 1);
  const std::string message = refusal(home.string(), true);
  if (saved) setenv("HOME", saved_home.c_str(), 1);
  EXPECT_EQ(message, "output folder '" + home.string() + "' is or contains the home folder (" +
                         fs::weakly_canonical(home).string() + "); choose another folder");
}

TEST_F(OutputDirectory, FolderHoldingTheCaseFileIsRefused) {
  const fs::path dir = root_ / "cases";
  fs::create_directories(dir);
  touch(dir / "bridge.yaml");
  const std::string case_file = (dir / "bridge.yaml").string();
  EXPECT_EQ(refusal(dir.string(), true, case_file), "output folder '" + dir.string() +
                                                        "' contains the case file '" + case_file +
                                                        "'; choose another folder");
  EXPECT_TRUE(fs::exists(dir / "bridge.yaml"));
}

TEST_F(OutputDirectory, FileInTheWayIsRefused) {
  const fs::path file = root_ / "out";
  touch(file);
  EXPECT_EQ(refusal(file.string(), true), "output folder '" + file.string() +
                                              "' exists and is not a folder; choose another name");
}

}  // namespace
}  // namespace flotsam

namespace flotsam {
namespace {

// A mesh file (or raster, vector file) the case reads, kept in an earlier output folder:
// --overwrite must not delete it (issue 20 item 5).
TEST(OutputDirectoryInputs, RefusesAFolderHoldingAFileTheCaseReads) {
  const fs::path root = test::fresh_test_folder("flotsam_outdir_inputs");
  const fs::path folder = root / "run";
  prepare_output_directory(folder.string(), false);
  std::ofstream(folder / "mesh.msh") << "$MeshFormat\n";
  try {
    prepare_output_directory(folder.string(), true, "",
                             {{"mesh.file", (folder / "mesh.msh").string()}});
    FAIL() << "emptied a folder holding the mesh file";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "output folder '" + folder.string() + "' contains '" +
                  (folder / "mesh.msh").string() +
                  "', which the case reads (mesh.file); choose another folder");
  }
  EXPECT_TRUE(fs::exists(folder / "mesh.msh"));
  fs::remove_all(root);
}

}  // namespace
}  // namespace flotsam
