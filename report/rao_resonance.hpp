// The resonance peaks and the sea of `ffrf rao` (study/rao_peaks.hpp, study/rao_spectrum.hpp) in
// the report's formats: resonance_peaks.csv, the Markdown sections, the terminal lines and the JSON
// fields of one model. Formatting only; every function writes nothing when the result has no
// refinement (or no sea).
#pragma once

#include <string>

#include "report/json.hpp"
#include "study/rao.hpp"
#include "study/rao_check.hpp"

namespace ffrf::report {

// model, mode, natural_period_s, damping_ratio, dominant, output, peak_period_s,
// peak_angular_frequency_rad_per_s, amplitude, unit, vertices, converged
std::string resonance_peaks_csv(const study::RaoResult& result);
// "## Resonance peaks" and "## In the sea" (each when there is something to say).
std::string resonance_markdown(const study::RaoResult& result);
std::string resonance_text(const study::RaoResult& result);
// The time-domain check's failed periods of one model, one line each after `prefix`: the nearest
// resonant mode (inside its half-power band or not), the deviation at half the wave height and what
// it means (amplitude-dependent: the test wave is not small enough; suggest --check-wave-height).
// Empty when the check passed.
std::string check_diagnosis(const study::TimeDomainCheck& check, const std::string& prefix);
// "rerun with --check-wave-height H" when a failed period is amplitude-dependent, else empty.
std::string check_hint(const study::TimeDomainCheck& check);
// "resonance_peaks" and "significant_response" of one model.
void add_resonance_json(Json& model_json, const study::ModelRao& model, const study::RaoResult& result);

}  // namespace ffrf::report
