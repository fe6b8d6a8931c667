// Most probable maximum (MPM) of a response over a record, three ways (docs/hydrodynamics.md §5.2;
// DNV-RP-C205 §3.5.8–3.5.11; Naess & Moan 2013, Stochastic Dynamics of Marine Structures, ch. 9):
//  * Rayleigh: a narrow-band Gaussian process with standard deviation σ and N = T/Tz cycles has
//    peaks with P(X > x) = exp(−x²/2σ²); the largest of N has density N f F^{N−1}, whose mode is
//    the MPM (solved exactly by Newton), ≈ σ sqrt(2 ln N) for large N;
//  * Weibull: a two-parameter Weibull F = 1 − exp(−(x/α)^β) fitted to the record's peaks above the
//    mean by maximum likelihood; MPM ≈ the level exceeded once in N peaks, α (ln N)^{1/β} (the
//    Rayleigh case is α = √2 σ, β = 2);
//  * Gumbel: F = exp(−exp(−(x − μ)/β)) fitted by maximum likelihood to the maxima of `blocks`
//    equal sub-records; the record's maximum is then Gumbel(μ + β ln blocks, β), whose mode
//    μ + β ln(blocks) is the MPM.
// All above the record mean; add the mean for levels.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace ffrf::hydro {

double rayleigh_most_probable_maximum(double sigma, double cycles);        // exact mode, cycles ≥ 1
double rayleigh_most_probable_maximum_asymptotic(double sigma, double cycles);  // σ sqrt(2 ln N)

struct WeibullFit {
  double scale = 0.0, shape = 0.0;  // α, β
  double exceeded_once_in(double count) const;  // α (ln N)^{1/β}
};
// Throws std::invalid_argument with fewer than 10 positive samples.
WeibullFit fit_weibull(const std::vector<double>& samples);

struct GumbelFit {
  double location = 0.0, scale = 0.0;  // μ, β
  double mode_of_maximum_of(double count) const { return location + scale * std::log(count); }
};
// Throws std::invalid_argument with fewer than 5 samples or all equal.
GumbelFit fit_gumbel(const std::vector<double>& samples);

struct ExtremeEstimates {
  double observed = 0.0;       // largest value above the mean in the record
  double cycles = 0.0;         // N: zero up-crossing waves
  double rayleigh = 0.0, weibull = 0.0, gumbel = 0.0;
  WeibullFit weibull_fit;
  GumbelFit gumbel_fit;
};
// Of a record sampled at dt; `blocks` sub-records for the Gumbel fit (≥ 5). Throws
// std::invalid_argument on a record with fewer than 10 waves or bad arguments.
ExtremeEstimates most_probable_maxima(const std::vector<double>& record, double dt, std::size_t blocks = 10);

// Wire tension's dynamic amplification (DNV-ST-N001 / DNV-RP-H103 §3.4: DAF = dynamic / static
// load): max T / T_static, the Rayleigh-MPM value (T_static + MPM of T − mean) / T_static, the
// smallest T / T_static and the share of samples with T ≤ 0 (slack).
struct TensionAmplification {
  double static_tension = 0.0;
  double maximum_factor = 0.0, most_probable_factor = 0.0, minimum_factor = 0.0, slack_fraction = 0.0;
};
TensionAmplification tension_amplification(const std::vector<double>& tension, double dt, double static_tension);

}  // namespace ffrf::hydro
