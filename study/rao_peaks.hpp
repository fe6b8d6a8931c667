// Resonance peaks of the RAOs resolved by refining the frequency grid around each coupled natural
// mode (`ffrf rao`; docs/user-guide.md). An evenly spaced period grid steps over a lightly damped
// peak: its width is the half-power band 2ζω_n, a few per cent of ω_n or less. For every resonant
// mode (0 < ζ < 1/√2) whose peak ω_n√(1 − 2ζ²) lies inside the grid's band:
//   1. seed frequencies at ω_n√(1 − 2ζ²) + {0, ±1, ±2, ±4} ζω_n (within the band);
//   2. for every output with a local maximum of |Y| strictly inside that window, place a frequency at
//      the vertex of the parabola through 1/|Y|² against ω² at the largest sample and its two
//      neighbours (exact for one degree of freedom, whose 1/|H|² = (k − mω²)² + (cω)² is quadratic in
//      ω²; the midpoint of the wider side when the three samples do not bracket a minimum);
//   3. stop when the amplitude at the new vertex differs from the largest sample before it by less
//      than `tolerance` (0.1 %): the interpolant and the response agree, so the largest sample is the
//      peak within that tolerance; else repeat 2 (at most `max_steps` vertices per output and mode).
// The peak of an output is then the largest sample in the mode's window. The outputs are complex
// responses per frequency (any number of them); the response function is called once per new
// frequency, and the frequencies of the grid are kept.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <vector>

#include "study/natural_mode.hpp"

namespace ffrf::study {

// The outputs' complex responses at ω [rad/s] (the same length at every ω).
using OutputResponse = std::function<Eigen::VectorXcd(double angular_frequency)>;

struct PeakSearch {
  double tolerance = 1e-3;    // relative amplitude change between the vertex and the largest sample
  int max_steps = 30;         // vertices per output and mode
  double window = 4.0;        // half-width of a mode's window in ζω_n
};

// The peak of one output at one mode.
struct ResonancePeak {
  std::size_t mode = 0;  // index into the modes given
  int output = 0;        // index into the response vector
  double angular_frequency = 0.0;  // of the largest sample [rad/s]
  double amplitude = 0.0;          // |Y| there
  int steps = 0;         // vertices placed
  bool converged = false;  // false: max_steps reached before the tolerance
};

struct RefinedResponse {
  std::vector<double> angular_frequencies;  // ascending: the grid's and the refinement's [rad/s]
  std::vector<Eigen::VectorXcd> responses;  // at each of them
  std::vector<ResonancePeak> peaks;         // by mode, then output
  std::size_t added = 0;                    // frequencies the refinement added to the grid
};

// `grid` and `responses` (the outputs at each grid frequency, in any order) are kept; `refined[k]`
// false leaves output k out of the search (e.g. an output identically zero). Throws
// std::invalid_argument when the sizes disagree or the grid is empty.
RefinedResponse refine_resonance_peaks(const std::vector<double>& grid, const std::vector<Eigen::VectorXcd>& responses,
                                       const std::vector<NaturalMode>& modes, const OutputResponse& response_at,
                                       const std::vector<bool>& refined, const PeakSearch& search = {});

}  // namespace ffrf::study
