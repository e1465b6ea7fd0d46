#pragma once
// A 64-bit XXH3 checksum (xxHash, Debian's libxxhash), fed piece by piece: the checksum of the
// records of archives of version 3 (io/binary_archive.hpp). It reads its input a block of words
// at a time, where FNV-1a (io/checksum.hpp) multiplies once per byte: about 20 times faster on
// the megabytes of flow states an ensemble's members read back. Not cryptographic.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>

namespace flotsam {

class Xxh3Checksum {
 public:
  Xxh3Checksum();
  ~Xxh3Checksum();
  Xxh3Checksum(const Xxh3Checksum&) = delete;
  Xxh3Checksum& operator=(const Xxh3Checksum&) = delete;

  /// Starts afresh (seed 0): as newly made.
  void reset();
  void add(const void* data, std::size_t bytes);
  void add(std::string_view text) { add(text.data(), text.size()); }
  /// XXH3-64 of everything added since the start, as one call over the concatenated pieces.
  std::uint64_t value() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace flotsam
