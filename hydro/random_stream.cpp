// SplitMix64 counter-based streams (see random_stream.hpp).
#include "hydro/random_stream.hpp"

#include <cmath>

namespace ffrf::hydro {

namespace {
constexpr std::uint64_t kGoldenGamma = 0x9E3779B97F4A7C15ULL;  // 2^64 / golden ratio, odd
}

std::uint64_t splitmix64_mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

// The key mixes the seed and the realisation through two rounds, so that neighbouring seeds or
// realisations give unrelated keys (a plain sum would make (s, r + 1) and (s + 1, r) collide).
RandomStream::RandomStream(std::uint64_t seed, std::uint64_t realisation)
    : key_(splitmix64_mix(splitmix64_mix(seed + kGoldenGamma) ^ (realisation * kGoldenGamma + 0x632BE59BD9B4E019ULL))) {}

std::uint64_t RandomStream::bits(std::uint64_t counter) const {
  return splitmix64_mix(key_ + (counter + 1) * kGoldenGamma);
}

double RandomStream::uniform(std::uint64_t counter) const {
  return static_cast<double>(bits(counter) >> 11) * 0x1.0p-53;
}

double RandomStream::uniform_open(std::uint64_t counter) const {
  return (static_cast<double>(bits(counter) >> 11) + 1.0) * 0x1.0p-53;
}

double RandomStream::exponential(std::uint64_t counter) const { return -std::log(uniform_open(counter)); }

}  // namespace ffrf::hydro
