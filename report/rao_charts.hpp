// The gnuplot charts of `ffrf rao --out`: per chart (hull, cargo, boom tip and wire) a 2 × 3 grid of
// amplitude (log scale) and phase against the wave period, models overlaid, every model's resonant
// natural periods marked by dashed vertical lines in its colour and labelled (a period within 1 % of
// one already labelled is drawn, not labelled again), and with a sea spectrum (RaoResult::sea) S(ω)
// on the amplitude panels' second y axis from sea_spectrum.csv. Formatting only.
#pragma once

#include <string>
#include <vector>

#include "hydro/wave_spectrum.hpp"
#include "study/rao.hpp"

namespace ffrf::report {

// The chart names (without .gp/.png), their titles and scripts.
std::vector<std::string> rao_chart_names();
std::string rao_chart_title(const std::string& name);
std::string rao_chart_script(const std::string& name, const study::RaoResult& result, const std::string& terminal);

// Whether an output is drawn for a model: the tip outputs are the boom's elastic deflection,
// identically zero for the rigid boom.
bool rao_drawn(const study::ModelRao& model, multibody::LinearOutput output);

// "JONSWAP Hs 1.5 m, Tp 9 s, γ 3.3", "Pierson–Moskowitz Hs 2 m, Tp 8 s", "tabulated".
std::string spectrum_label(const hydro::WaveSpectrum& spectrum);
// sea_spectrum.csv: period_s, angular_frequency_rad_per_s, density_m2_s_per_rad at 400 periods evenly
// spaced over the result's band (the charts' second axis).
std::string sea_spectrum_csv(const study::RaoResult& result);

}  // namespace ffrf::report
