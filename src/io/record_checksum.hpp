#pragma once
// The checksum of each record of an archive (io/binary_archive.hpp), chosen by the archive's
// version: version 2 (written before issue 17's ensembles were made faster) checks its records
// with FNV-1a (io/checksum.hpp), byte by byte; version 3 with XXH3-64 (io/xxh3_checksum.hpp), a
// block of words at a time. Archives are written in the newest version and read in either.
#include <cstddef>
#include <cstdint>
#include <memory>

namespace flotsam {

class RecordChecksum {
 public:
  virtual ~RecordChecksum() = default;
  /// Starts the next record's checksum.
  virtual void reset() = 0;
  virtual void add(const void* data, std::size_t bytes) = 0;
  virtual std::uint64_t value() const = 0;
};

/// The record checksum of archives of `version` (2 or 3); nullptr for any other version.
std::unique_ptr<RecordChecksum> record_checksum_for(std::uint32_t version);

}  // namespace flotsam
