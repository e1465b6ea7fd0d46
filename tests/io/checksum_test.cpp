// The archives' checksums against published test vectors: FNV-1a (the vectors of its authors'
// test suite) and XXH3-64 (those of xxHash's own sanity check, `xxhsum -b`), fed whole and in
// pieces.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "io/checksum.hpp"
#include "io/record_checksum.hpp"
#include "io/xxh3_checksum.hpp"

namespace flotsam {
namespace {

TEST(Checksum, Fnv1aMatchesPublishedVectors) {
  const auto fnv = [](const std::string& text) {
    Checksum sum;
    sum.add(text);
    return sum.value();
  };
  EXPECT_EQ(fnv(""), 0xcbf29ce484222325ull);  // the offset basis
  EXPECT_EQ(fnv("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(fnv("foobar"), 0x85944171f73967e8ull);
  Checksum pieces;
  pieces.add("foo");
  pieces.add("bar");
  EXPECT_EQ(pieces.value(), fnv("foobar"));
  EXPECT_EQ(pieces.hex(), "85944171f73967e8");
}

/// xxHash's sanity buffer: byte i is the top byte of 2654435761 * 11400714785074694797^i
/// (mod 2^64).
std::vector<unsigned char> sanity_buffer(std::size_t length) {
  std::vector<unsigned char> bytes(length);
  std::uint64_t generator = 2654435761ull;
  for (auto& byte : bytes) {
    byte = static_cast<unsigned char>(generator >> 56);
    generator *= 11400714785074694797ull;
  }
  return bytes;
}

TEST(Checksum, Xxh3MatchesPublishedVectors) {
  Xxh3Checksum sum;
  EXPECT_EQ(sum.value(), 0x2d06800538d394c2ull);  // nothing added
  for (const auto& [text, expected] :
       {std::pair<std::string, std::uint64_t>{"a", 0xe6c632b61e964e1full},
        {"abc", 0x78af5f94892f3950ull}}) {
    sum.reset();
    sum.add(text);
    EXPECT_EQ(sum.value(), expected) << text;
  }
  // Lengths that take each of XXH3's paths: 1-3, 4-8, 9-16, 17-32, 33-64, 65-96, 129-240 bytes,
  // one block, two, three with the last stripe overlapping.
  const std::vector<std::pair<std::size_t, std::uint64_t>> vectors = {
      {1, 0xc44bdff4074eecdbull},    {6, 0x27b56a84cd2d7325ull},    {12, 0xa713daf0dfbb77e7ull},
      {24, 0xa3fe70bf9d3510ebull},   {48, 0x397da259ecba1f11ull},   {80, 0xbcdefbbb2c47c90aull},
      {195, 0xcd94217ee362ec3aull},  {403, 0xcdeb804d65c6dea4ull},  {512, 0x617e49599013cb6bull},
      {2048, 0xdd59e2c3a5f038e0ull}, {2240, 0x6e73a90539cf2948ull}, {2367, 0xcb37aeb9e5d361edull}};
  const std::vector<unsigned char> buffer = sanity_buffer(2367);
  for (const auto& [length, expected] : vectors) {
    sum.reset();
    sum.add(buffer.data(), length);
    EXPECT_EQ(sum.value(), expected) << length << " bytes at once";
    sum.reset();  // in pieces of 1, 2, 3, ... bytes: the same
    for (std::size_t at = 0, piece = 1; at < length; at += piece, ++piece)
      sum.add(buffer.data() + at, std::min(piece, length - at));
    EXPECT_EQ(sum.value(), expected) << length << " bytes in pieces";
  }
}

TEST(Checksum, RecordChecksumsFollowTheArchiveVersion) {
  const std::string text = "foobar";
  const auto v2 = record_checksum_for(2), v3 = record_checksum_for(3);
  ASSERT_TRUE(v2 && v3);
  v2->add(text.data(), text.size());
  v3->add(text.data(), text.size());
  EXPECT_EQ(v2->value(), 0x85944171f73967e8ull);  // FNV-1a
  Xxh3Checksum xxh3;
  xxh3.add(text);
  EXPECT_EQ(v3->value(), xxh3.value());
  v3->reset();
  EXPECT_EQ(v3->value(), 0x2d06800538d394c2ull);
  EXPECT_EQ(record_checksum_for(1), nullptr);
  EXPECT_EQ(record_checksum_for(4), nullptr);
}

}  // namespace
}  // namespace flotsam
