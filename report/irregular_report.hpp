// Irregular-sea statistics in `ffrf run` and `ffrf compare` reports: a text table
// (σ, 4σ, Tz, spectral peak, observed maximum and the Rayleigh / Weibull / Gumbel most probable
// maxima per response; the realised Hs of the incident wave; the wire tension's DAF), the same as
// JSON, the Welch response spectra as CSV, and the statistics-and-spectra errors of compare.
#pragma once

#include <string>
#include <vector>

#include "report/json.hpp"
#include "study/irregular_statistics.hpp"

namespace ffrf::report {

std::string irregular_text(const study::IrregularStatistics& statistics);
Json irregular_json(const study::IrregularStatistics& statistics);
// One row per frequency of the incident wave's spectrum: omega_rad_s, then S of the wave and of
// every response (each Welch spectrum has the same frequencies: same record, same segments).
std::string response_spectra_csv(const study::IrregularStatistics& statistics);

// compare: per model, the errors of its statistics and spectra against the reference.
std::string irregular_errors_text(const std::vector<std::string>& models,
                                  const std::vector<std::optional<study::IrregularErrors>>& errors);
Json irregular_errors_json(const study::IrregularErrors& errors);

}  // namespace ffrf::report
