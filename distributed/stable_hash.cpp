// FNV-1a 64 (see stable_hash.hpp).
#include "distributed/stable_hash.hpp"

#include <fmt/format.h>

namespace ffrf::distributed {

StableHash& StableHash::add(std::string_view bytes) {
  constexpr std::uint64_t fnv_prime = 0x100000001b3ULL;
  for (const char c : bytes) {
    state_ ^= static_cast<unsigned char>(c);
    state_ *= fnv_prime;
  }
  return *this;
}

StableHash& StableHash::add_field(std::string_view text) {
  add(text);
  return add(std::string_view("\x1f", 1));  // the ASCII unit separator
}

std::uint64_t stable_hash(std::string_view bytes) { return StableHash().add(bytes).value(); }

std::string hex(std::uint64_t value) { return fmt::format("{:016x}", value); }

}  // namespace ffrf::distributed
