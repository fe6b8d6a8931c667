// Wall-clock seconds of a study's stages (what each run records beside its solver counts).
#pragma once

#include <chrono>

namespace ffrf::study {

// Seconds of wall time since `start` (std::chrono::steady_clock: monotonic, unaffected by clock changes).
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace ffrf::study
