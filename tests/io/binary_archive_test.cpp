#include "io/binary_archive.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../support/file_size_limit.hpp"
#include "../support/scratch_path.hpp"
#include "core/error.hpp"
#include "core/vec.hpp"
#include "io/record_checksum.hpp"

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

/// An archive of `version` in the layout of io/binary_archive.hpp, written here byte by byte with
/// that version's record checksum: one record "x" of `values`, then "end".
std::string archive_bytes(std::uint32_t version, const std::vector<double>& values) {
  std::string bytes = "FLOTSAM-ARCHIVE\n";
  bytes.append(reinterpret_cast<const char*>(&version), 4);
  const auto record = [&](const std::string& name, std::uint32_t size, std::uint64_t count,
                          const void* data) {
    const std::size_t start = bytes.size();
    const auto length = static_cast<std::uint32_t>(name.size());
    bytes.append(reinterpret_cast<const char*>(&length), 4);
    bytes += name;
    bytes.append(reinterpret_cast<const char*>(&size), 4);
    bytes.append(reinterpret_cast<const char*>(&count), 8);
    bytes.append(static_cast<const char*>(data), size * count);
    const auto sum = record_checksum_for(version);
    if (sum) sum->add(bytes.data() + start, bytes.size() - start);
    const std::uint64_t check = sum ? sum->value() : 0;
    bytes.append(reinterpret_cast<const char*>(&check), 8);
  };
  record("x", 8, values.size(), values.data());
  record("end", 1, 0, nullptr);
  return bytes;
}

// Archives of version 2 (FNV-1a checksums, written before version 3's XXH3) are still read, and
// still checked; the checksums of the version written now are XXH3-64 of each record.
TEST(BinaryArchive, ReadsVersionTwoAndWritesVersionThree) {
  const std::string path = temp_file("flotsam_archive_v2.bin");
  const std::vector<double> x = {0.5, -2.0, 1e-300};
  { std::ofstream(path, std::ios::binary) << archive_bytes(2, x); }
  {
    ArchiveReader r(path);
    EXPECT_EQ(r.read<double>("x"), x);
    r.finish();
  }
  std::string damaged = archive_bytes(2, x);
  damaged[16 + 4 + 4 + 1 + 4 + 8 + 3] ^= 1;  // a bit of x[0]
  { std::ofstream(path, std::ios::binary) << damaged; }
  {
    ArchiveReader r(path);
    try {
      r.read<double>("x");
      FAIL() << "a damaged version 2 record was read";
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr("record 'x' is damaged"));
    }
  }
  {
    ArchiveWriter w(path);
    w.write("x", x);
    w.close();
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  const std::string written = bytes.str();
  EXPECT_EQ(archive_version, 3u);
  EXPECT_EQ(written, archive_bytes(3, x));  // the same bytes, XXH3 checksums included
  std::filesystem::remove(path);
}

TEST(BinaryArchive, AnotherVersionIsRefusedNamingIt) {
  const std::string path = temp_file("flotsam_archive_v4.bin");
  { std::ofstream(path, std::ios::binary) << archive_bytes(4, {1.0}); }
  try {
    ArchiveReader r(path);
    FAIL() << "a version 4 archive was opened";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("is a flotsam state file of version 4; this flotsam reads "
                                    "versions 2 to 3"));
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
