// Counter-based random numbers for reproducible sea realisations (docs/hydrodynamics.md §2.3).
// Every number is a pure function of (seed, realisation, counter): the SplitMix64 finaliser
// (Steele, Lea & Flood 2014, "Fast splittable pseudorandom number generators", OOPSLA; the mix
// function of Java's SplittableRandom) applied to a key derived from the seed and the realisation
// index, plus the counter times the golden-ratio increment. No global or thread state is read or
// written, so a realisation is the same whatever the thread or process that computes it and in
// whatever order realisations are drawn.
#pragma once

#include <cstdint>

namespace ffrf::hydro {

// SplitMix64's output function: a bijective 64-bit mix (avalanches every input bit).
std::uint64_t splitmix64_mix(std::uint64_t z);

// One stream of independent draws: draw(counter) depends only on (seed, realisation, counter).
class RandomStream {
 public:
  RandomStream(std::uint64_t seed, std::uint64_t realisation);
  std::uint64_t bits(std::uint64_t counter) const;  // 64 random bits
  double uniform(std::uint64_t counter) const;      // in [0, 1), 53-bit resolution
  double uniform_open(std::uint64_t counter) const; // in (0, 1]: safe for log
  double exponential(std::uint64_t counter) const;  // unit-mean exponential, −ln U, U in (0, 1]
  std::uint64_t key() const { return key_; }

 private:
  std::uint64_t key_;
};

}  // namespace ffrf::hydro
