// The sea of an operability cell's records, before anything runs: whether it can exist (its
// significant steepness against DNV-RP-C205's breaking limit, hydro/sea_steepness.hpp), the band its
// synthesis keeps — chosen from the cell's own spectrum by hydro::variance_band, the band holding a
// stated share of m0 with the rest split equally between the tails — the wave components a record
// gets, and how often the synthesized sea repeats: components on ω_n = n Δω repeat after
// T_rep = 2π/Δω, Δω = band / K with K components (or 2π / record length, which never repeats within
// the record). A record longer than T_rep counts the same waves again: its statistics rest on the
// wave cycles of one repeat, (min(T_rep, record after the ramp)) / Tz with Tz = 2π sqrt(m0/m2)
// over the band, not on the record length.
#pragma once

#include <cstddef>
#include <string>

#include "hydro/sea_steepness.hpp"
#include "hydro/wave_spectrum.hpp"

namespace ffrf::study {

struct CellSea {
  hydro::SeaSteepness steepness;
  hydro::FrequencyBand band;             // [rad/s] the synthesis band
  double variance_share = 0.0;           // m0 within the band / m0 of the spectrum (by quadrature)
  double frequency_step = 0.0;           // Δω [rad/s]
  std::size_t components = 0;            // per record
  double repeat_period = 0.0;            // 2π/Δω [s]
  double record_repeats = 0.0;           // record length / repeat period (≤ 1: the sea never repeats)
  double zero_crossing_period = 0.0;     // Tz over the band [s]
  double independent_wave_cycles = 0.0;  // min(repeat period, record − ramp) / Tz
  bool physical() const { return !steepness.breaking(); }
  bool repeats() const { return record_repeats > 1.0 + 1e-12; }
};

// The sea of one cell: `spectrum` (parametric), records of `record_length` seconds whose statistics
// start after `ramp` seconds, `components` per record (0: Δω = 2π / record length), the band holding
// `variance_share` of m0. Throws std::invalid_argument (from hydro) for parameters out of range.
CellSea cell_sea(const hydro::WaveSpectrum& spectrum, double gravity, double record_length, double ramp, int components,
                 double variance_share);

// "Hs = 3 m at Tp = 5 s is steeper than a sea can be: Hs/λp = 0.077 > 1/15 (DNV-RP-C205); at most 2.6 m"
std::string not_physical_reason(double significant_height, double peak_period, const hydro::SeaSteepness& steepness);

}  // namespace ffrf::study
