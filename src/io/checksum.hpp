#pragma once
// A 64-bit FNV-1a checksum (Fowler, Noll, Vo), fed piece by piece: for the integrity of archive
// records (io/binary_archive.hpp) and the digests of a case's input files (io/case_digest.hpp).
// Not cryptographic: it finds damage and changes, not forgery.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace flotsam {

class Checksum {
 public:
  void add(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    std::uint64_t h = hash_;
    for (std::size_t k = 0; k < bytes; ++k) h = (h ^ p[k]) * prime;
    hash_ = h;
  }
  void add(std::string_view text) { add(text.data(), text.size()); }
  std::uint64_t value() const { return hash_; }
  /// 16 hexadecimal digits.
  std::string hex() const;

 private:
  static constexpr std::uint64_t offset_basis = 14695981039346656037ull;
  static constexpr std::uint64_t prime = 1099511628211ull;
  std::uint64_t hash_ = offset_basis;
};

/// The checksum of a whole file's bytes, as hex digits; an InputError naming `what` (and the
/// file) when it cannot be read.
std::string file_checksum(const std::string& path, const std::string& what);

}  // namespace flotsam
