#include "io/xxh3_checksum.hpp"

#include <xxhash.h>

#include <new>

namespace flotsam {

struct Xxh3Checksum::State {
  State() : xxh(XXH3_createState()) {
    if (xxh == nullptr) throw std::bad_alloc();
  }
  ~State() { XXH3_freeState(xxh); }
  XXH3_state_t* xxh;
};

Xxh3Checksum::Xxh3Checksum() : state_(std::make_unique<State>()) {
  reset();
}

Xxh3Checksum::~Xxh3Checksum() = default;

void Xxh3Checksum::reset() {
  XXH3_64bits_reset(state_->xxh);
}

void Xxh3Checksum::add(const void* data, std::size_t bytes) {
  if (bytes > 0) XXH3_64bits_update(state_->xxh, data, bytes);
}

std::uint64_t Xxh3Checksum::value() const {
  return XXH3_64bits_digest(state_->xxh);
}

}  // namespace flotsam
