// Refinement of the RAO grid around the resonance peaks (study/rao_peaks.hpp).
#include "study/rao_peaks.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <stdexcept>

namespace ffrf::study {
namespace {

using Samples = std::map<double, Eigen::VectorXcd>;

// The samples, with `response_at` called for a frequency not yet sampled.
class SampledResponse {
 public:
  SampledResponse(const std::vector<double>& grid, const std::vector<Eigen::VectorXcd>& responses, const OutputResponse& response_at)
      : response_at_(response_at) {
    for (std::size_t i = 0; i < grid.size(); ++i) samples_.emplace(grid[i], responses[i]);
  }
  void sample(double omega) {
    if (samples_.count(omega) != 0) return;
    samples_.emplace(omega, response_at_(omega));
    ++added_;
  }
  const Samples& samples() const { return samples_; }
  std::size_t added() const { return added_; }

 private:
  Samples samples_;
  const OutputResponse& response_at_;
  std::size_t added_ = 0;
};

double amplitude(Samples::const_iterator at, int output) { return std::abs(at->second(output)); }

// The largest |Y_k| among the samples in [low, high]; end() when there are fewer than three or the
// largest is the first or last of them (no local maximum inside).
Samples::const_iterator interior_maximum(const Samples& samples, double low, double high, int output) {
  const auto first = samples.lower_bound(low), last = samples.upper_bound(high);
  if (std::distance(first, last) < 3) return samples.end();
  auto best = first;
  for (auto it = first; it != last; ++it) {
    if (amplitude(it, output) > amplitude(best, output)) best = it;
  }
  if (best == first || std::next(best) == last || amplitude(best, output) == 0.0) return samples.end();
  return best;
}

// The next frequency to sample at a maximum `b` between its neighbours: the vertex of the parabola
// through 1/|Y|² against ω², or the midpoint of the wider side when the vertex is not strictly
// between the neighbours.
double next_frequency(Samples::const_iterator b, int output) {
  const auto a = std::prev(b), c = std::next(b);
  const double ua = a->first * a->first, ub = b->first * b->first, uc = c->first * c->first;
  const auto inverse_square = [&](Samples::const_iterator at) { return 1.0 / std::pow(amplitude(at, output), 2); };
  const double fa = inverse_square(a), fb = inverse_square(b), fc = inverse_square(c);
  const double numerator = (ub - ua) * (ub - ua) * (fb - fc) - (ub - uc) * (ub - uc) * (fb - fa);
  const double denominator = (ub - ua) * (fb - fc) - (ub - uc) * (fb - fa);
  if (denominator != 0.0) {
    const double vertex = ub - 0.5 * numerator / denominator;
    if (std::isfinite(vertex) && vertex > ua && vertex < uc) return std::sqrt(vertex);
  }
  return b->first - a->first > c->first - b->first ? 0.5 * (a->first + b->first) : 0.5 * (b->first + c->first);
}

}  // namespace

RefinedResponse refine_resonance_peaks(const std::vector<double>& grid, const std::vector<Eigen::VectorXcd>& responses,
                                       const std::vector<NaturalMode>& modes, const OutputResponse& response_at,
                                       const std::vector<bool>& refined, const PeakSearch& search) {
  if (grid.empty() || grid.size() != responses.size()) {
    throw std::invalid_argument("refine_resonance_peaks: the grid is empty or its responses are not one per frequency");
  }
  const auto outputs = static_cast<int>(responses.front().size());
  if (refined.size() != static_cast<std::size_t>(outputs)) {
    throw std::invalid_argument("refine_resonance_peaks: one refinement flag per output is needed");
  }
  const auto [low_it, high_it] = std::minmax_element(grid.begin(), grid.end());
  const double low = *low_it, high = *high_it;
  SampledResponse sampled(grid, responses, response_at);
  RefinedResponse result;
  for (std::size_t j = 0; j < modes.size(); ++j) {
    const NaturalMode& mode = modes[j];
    if (!mode.resonant()) continue;
    const double centre = mode.peak_frequency(), width = mode.damping_ratio * mode.angular_frequency;
    if (centre < low || centre > high) continue;
    const double window_low = std::max(low, centre - search.window * width);
    const double window_high = std::min(high, centre + search.window * width);
    for (const double offset : {0.0, -1.0, 1.0, -2.0, 2.0, -search.window, search.window}) {
      const double omega = centre + offset * width;
      if (omega >= window_low && omega <= window_high) sampled.sample(omega);
    }
    for (int k = 0; k < outputs; ++k) {
      if (!refined[static_cast<std::size_t>(k)]) continue;
      ResonancePeak peak;
      peak.mode = j;
      peak.output = k;
      auto best = interior_maximum(sampled.samples(), window_low, window_high, k);
      if (best == sampled.samples().end()) continue;  // no local maximum of this output at this mode
      while (peak.steps < search.max_steps) {
        const double omega = next_frequency(best, k);
        if (omega == best->first || sampled.samples().count(omega) != 0) {  // resolved to the last bit
          peak.converged = true;
          break;
        }
        const double largest = amplitude(best, k);
        sampled.sample(omega);
        ++peak.steps;
        const double at_vertex = amplitude(sampled.samples().find(omega), k);
        best = interior_maximum(sampled.samples(), window_low, window_high, k);
        if (std::abs(at_vertex - largest) <= search.tolerance * largest) {
          peak.converged = true;
          break;
        }
      }
      peak.angular_frequency = best->first;
      peak.amplitude = amplitude(best, k);
      result.peaks.push_back(peak);
    }
  }
  result.added = sampled.added();
  for (const auto& [omega, response] : sampled.samples()) {
    result.angular_frequencies.push_back(omega);
    result.responses.push_back(response);
  }
  return result;
}

}  // namespace ffrf::study
