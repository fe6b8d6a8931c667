// A hash that is the same on every machine, compiler and run (unlike std::hash): 64-bit FNV-1a
// (Fowler, Noll & Vo; the parameters of the IETF draft "The FNV Non-Cryptographic Hash
// Algorithm"), for journal fingerprints, line checksums and task seeds. It detects mix-ups and
// torn writes; it is not a cryptographic hash and does not resist deliberate collisions.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace ffrf::distributed {

class StableHash {
 public:
  StableHash& add(std::string_view bytes);
  // Adds the text and a separator, so that ("ab", "c") and ("a", "bc") hash differently.
  StableHash& add_field(std::string_view text);
  std::uint64_t value() const { return state_; }

 private:
  std::uint64_t state_ = 0xcbf29ce484222325ULL;  // the FNV-1a 64-bit offset basis
};

std::uint64_t stable_hash(std::string_view bytes);
// 16 lower-case hexadecimal digits.
std::string hex(std::uint64_t value);

}  // namespace ffrf::distributed
