#include "io/record_checksum.hpp"

#include "io/checksum.hpp"
#include "io/xxh3_checksum.hpp"

namespace flotsam {

namespace {

class Fnv1aRecordChecksum final : public RecordChecksum {
 public:
  void reset() override { sum_ = Checksum(); }
  void add(const void* data, std::size_t bytes) override { sum_.add(data, bytes); }
  std::uint64_t value() const override { return sum_.value(); }

 private:
  Checksum sum_;
};

class Xxh3RecordChecksum final : public RecordChecksum {
 public:
  void reset() override { sum_.reset(); }
  void add(const void* data, std::size_t bytes) override { sum_.add(data, bytes); }
  std::uint64_t value() const override { return sum_.value(); }

 private:
  Xxh3Checksum sum_;
};

}  // namespace

std::unique_ptr<RecordChecksum> record_checksum_for(std::uint32_t version) {
  if (version == 2) return std::make_unique<Fnv1aRecordChecksum>();
  if (version == 3) return std::make_unique<Xxh3RecordChecksum>();
  return nullptr;
}

}  // namespace flotsam
