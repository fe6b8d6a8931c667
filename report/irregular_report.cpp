// Text, JSON and CSV of irregular-sea statistics (see irregular_report.hpp).
#include "report/irregular_report.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace ffrf::report {

namespace {

// A number, or "-" where there is none (a spectral peak the record is too short to resolve: NaN).
std::string value(double x, int digits = 5) { return std::isfinite(x) ? fmt::format("{:.{}g}", x, digits) : "-"; }
// A zero up-crossing period: "-" when the record has no up-crossing to measure it (Tz = 0).
std::string period(double x, int digits = 5) { return x > 0.0 ? value(x, digits) : "-"; }
std::string percent(double x) { return std::isfinite(x) ? fmt::format("{:+.2f}%", 100.0 * x) : "-"; }

std::string row(const study::ResponseStatistics& r) {
  return fmt::format("  {:<20} {:>11} {:>11} {:>8} {:>8} {:>11} {:>11} {:>11} {:>11}\n", r.column, value(r.standard_deviation),
                     value(r.significant), period(r.zero_crossing_period), value(r.peak_frequency),
                     value(r.observed_maximum), r.extremes ? value(r.rayleigh) : "-", r.extremes ? value(r.weibull) : "-",
                     r.extremes ? value(r.gumbel) : "-");
}

Json response_json(const study::ResponseStatistics& r) {
  Json json{{"unit", r.unit},
            {"mean", r.mean},
            {"standard_deviation", r.standard_deviation},
            {"significant_4_sigma", r.significant},
            {"zero_crossing_period_s", r.zero_crossing_period},
            {"spectral_peak_rad_s", r.peak_frequency},
            {"observed_maximum", r.observed_maximum}};
  if (r.extremes) {
    json["most_probable_maximum"] = Json{{"rayleigh", r.rayleigh},
                                         {"weibull", r.weibull},
                                         {"weibull_shape", r.weibull_shape},
                                         {"gumbel", r.gumbel}};
  }
  return json;
}

}  // namespace

std::string irregular_text(const study::IrregularStatistics& s) {
  const std::string window =
      s.after_ramp ? fmt::format("statistics over {:g} s after the ramp (t > {:g} s)", s.record_length, s.window_start)
                   : fmt::format("statistics over the whole {:g}-s run, which ends within the wave ramp (t < {:g} s): "
                                 "they include the growing waves of the ramp",
                                 s.record_length, s.ramp_end);
  std::string text = fmt::format(
      "\nirregular sea: {}, sampled every {:g} s\n"
      "  {} components over [{:.4g}, {:.4g}] rad/s, holding {:.2f} % of the spectrum's m0\n"
      "  incident wave at G1: realised Hs = 4σ = {} m, Tz {} s, spectral peak {} rad/s\n"
      "  most probable maxima (MPM) over the record, as levels: Rayleigh (narrow-band Gaussian), Weibull fit to the\n"
      "  peaks, Gumbel fit to 10 block maxima; motions about static equilibrium\n",
      window, s.sample_interval, s.components, s.band_lower, s.band_upper, 100.0 * s.band_share,
      value(s.elevation.significant, 4), period(s.elevation.zero_crossing_period, 4),
      value(s.elevation.peak_frequency, 4));
  text += fmt::format("  {:<20} {:>11} {:>11} {:>8} {:>8} {:>11} {:>11} {:>11} {:>11}\n", "output", "sigma", "4 sigma",
                      "Tz [s]", "peak w", "max", "MPM Rayl.", "MPM Weib.", "MPM Gumb.");
  for (const study::ResponseStatistics& r : s.responses) text += row(r);
  if (s.wire.static_tension > 0.0) {
    text += fmt::format("  wire tension DAF: observed max / static {:.4f}, Rayleigh-MPM / static {:.4f}, min / static {:.4f}, "
                        "slack {:.3g}% of the samples\n",
                        s.wire.maximum_factor, s.wire.most_probable_factor, s.wire.minimum_factor, 100.0 * s.wire.slack_fraction);
  }
  if (!s.note.empty()) text += "  note: " + s.note + "\n";
  return text;
}

Json irregular_json(const study::IrregularStatistics& s) {
  Json responses = Json::object();
  for (const study::ResponseStatistics& r : s.responses) responses[std::string(r.column)] = response_json(r);
  Json json{{"window_start_s", s.window_start},
            {"record_length_s", s.record_length},
            {"ramp_end_s", s.ramp_end},
            {"after_ramp", s.after_ramp},
            {"sample_interval_s", s.sample_interval},
            {"band_rad_per_s", Json::array({s.band_lower, s.band_upper})},
            {"components", s.components},
            {"band_share_of_m0", s.band_share},
            {"incident_wave", response_json(s.elevation)},
            {"responses", std::move(responses)}};
  if (s.wire.static_tension > 0.0) {
    json["wire_tension_daf"] = Json{{"static_tension_N", s.wire.static_tension},
                                    {"maximum_over_static", s.wire.maximum_factor},
                                    {"rayleigh_mpm_over_static", s.wire.most_probable_factor},
                                    {"minimum_over_static", s.wire.minimum_factor},
                                    {"slack_fraction", s.wire.slack_fraction}};
  }
  if (!s.note.empty()) json["note"] = s.note;
  return json;
}

std::string response_spectra_csv(const study::IrregularStatistics& s) {
  std::string csv = "omega_rad_s,wave_elevation_m2_s_rad";
  for (const study::ResponseStatistics& r : s.responses) csv += fmt::format(",{}_spectrum", r.column);
  csv += '\n';
  const std::vector<double>& omega = s.elevation.spectrum.frequency;
  for (std::size_t k = 0; k < omega.size(); ++k) {
    csv += fmt::format("{:.8g},{:.8g}", omega[k], s.elevation.spectrum.density[k]);
    for (const study::ResponseStatistics& r : s.responses) {
      csv += k < r.spectrum.density.size() ? fmt::format(",{:.8g}", r.spectrum.density[k]) : std::string(",0");
    }
    csv += '\n';
  }
  return csv;
}

std::string irregular_errors_text(const std::vector<std::string>& models,
                                  const std::vector<std::optional<study::IrregularErrors>>& errors) {
  const std::vector<std::string_view> columns = study::statistics_columns();
  std::string text =
      "\nirregular sea: statistics and spectra against the reference (relative errors of σ and of the Rayleigh MPM;\n"
      "spectral distance D = ∫|S − S_ref| dω / ∫S_ref dω), worst statistic over σ, MPM, m0, m2, Tz and the peak\n";
  text += fmt::format("  {:<30} {:>10}", "model", "worst stat");
  for (std::string_view c : columns) text += fmt::format(" {:>17}", c.substr(0, 17));
  text += "\n";
  for (std::size_t m = 0; m < models.size() && m < errors.size(); ++m) {
    if (!errors[m]) continue;
    text += fmt::format("  {:<30} {:>10}", models[m], percent(errors[m]->worst_statistic));
    for (const hydro::IrregularComparison& c : errors[m]->responses) {
      text += fmt::format(" {:>17}", fmt::format("{}/{}/D{:.2f}", percent(c.sigma_error),
                                                 percent(c.most_probable_maximum_error), c.spectral_distance));
    }
    text += "\n";
  }
  return text;
}

Json irregular_errors_json(const study::IrregularErrors& errors) {
  Json json{{"worst_statistic", errors.worst_statistic}};
  const std::vector<std::string_view> columns = study::statistics_columns();
  Json responses = Json::object();
  for (std::size_t i = 0; i < columns.size() && i < errors.responses.size(); ++i) {
    const hydro::IrregularComparison& c = errors.responses[i];
    responses[std::string(columns[i])] = Json{{"time_history_nrms", c.time_history_nrms},
                                              {"sigma_error", c.sigma_error},
                                              {"rayleigh_mpm_error", c.most_probable_maximum_error},
                                              {"m0_error", c.m0_error},
                                              {"m2_error", c.m2_error},
                                              {"zero_crossing_period_error", c.zero_crossing_period_error},
                                              {"peak_frequency_error", c.peak_frequency_error},
                                              {"spectral_distance", c.spectral_distance}};
  }
  json["responses"] = std::move(responses);
  return json;
}

}  // namespace ffrf::report
