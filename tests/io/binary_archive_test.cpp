#include "io/binary_archive.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "../support/file_size_limit.hpp"
#include "../support/scratch_path.hpp"
#include "core/error.hpp"
#include "core/vec.hpp"

namespace flotsam {
namespace {

using ::testing::HasSubstr;

std::string temp_file(const std::string& name) {
  return test::scratch_path(name).string();
}

TEST(BinaryArchive, RoundTripIsBitExact) {
  const std::string path = temp_file("flotsam_archive_roundtrip.bin");
  const std::vector<double> x = {0.1, -1e-300, 3.14159265358979, 1e308};
  const std::vector<Vec2> p = {Vec2(1.5, -2.25), Vec2(1.0 / 3.0, 2.0 / 7.0)};
  {
    ArchiveWriter w(path);
    w.write("x", x);
    w.write("p", p);
    w.write_value("step", 42L);
    w.write_text("note", "hello");
    w.close();
  }
  ArchiveReader r(path);
  EXPECT_EQ(r.read<double>("x"), x);
  const auto q = r.read<Vec2>("p");
  ASSERT_EQ(q.size(), 2u);
  EXPECT_EQ(q[1].x(), p[1].x());
  EXPECT_EQ(q[1].y(), p[1].y());
  EXPECT_EQ(r.read_value<long>("step"), 42L);
  EXPECT_EQ(r.read_text("note"), "hello");
  std::filesystem::remove(path);
}

// A checkpoint or state write that fails (a full disk, imitated by a file size limit) stops with
// the file named and leaves no .part file behind (issue 20 item 5).
TEST(BinaryArchive, AFailedWriteLeavesNoPartFile) {
  const std::string path = temp_file("flotsam_archive_full.bin");
  const std::vector<double> x(10000, 1.0);  // 80 kB
  try {
    const test::FileSizeLimit full_disk(4096);  // [bytes]
    ArchiveWriter w(path);
    w.write("x", x);
    w.close();
    ADD_FAILURE() << "the write past the limit succeeded";
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), ::testing::HasSubstr("cannot write '" + path + "'"));
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(path + ".part"));
}

TEST(BinaryArchive, WrongRecordOrTruncationIsAnErrorNamingTheFile) {
  const std::string path = temp_file("flotsam_archive_wrong.bin");
  {
    ArchiveWriter w(path);
    w.write("eta", std::vector<double>(100, 1.0));
    w.close();
  }
  {
    ArchiveReader r(path);
    try {
      r.read<double>("u");
      FAIL();
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr("expected record 'u'"));
      EXPECT_THAT(e.what(), HasSubstr("found 'eta'"));
    }
  }
  std::filesystem::resize_file(path, 200);
  ArchiveReader r(path);
  try {
    r.read<double>("eta");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("truncated"));
  }
  std::filesystem::remove(path);
}

TEST(BinaryArchive, NotAnArchiveIsAnError) {
  const std::string path = temp_file("flotsam_archive_not.bin");
  { std::ofstream(path) << "name: case\n"; }
  EXPECT_THROW(ArchiveReader r(path), InputError);
  try {
    ArchiveReader r(path);
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("is not a flotsam state file"));
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace flotsam
