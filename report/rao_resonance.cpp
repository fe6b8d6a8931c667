// Resonance peaks and significant responses in the report's formats (report/rao_resonance.hpp).
#include "report/rao_resonance.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <nlohmann/json.hpp>
#include <numbers>
#include <vector>

#include "report/quantities.hpp"
#include "report/rao_charts.hpp"

namespace ffrf::report {
namespace {

using multibody::LinearOutput;

std::string name_of(int output) { return std::string(multibody::to_string(static_cast<LinearOutput>(output))); }
std::string unit_of(int output) { return std::string(multibody::unit_per_amplitude(static_cast<LinearOutput>(output))); }
// The unit of a response in a sea: "m/m" per metre of wave → "m".
std::string response_unit(int output) { return unit_of(output).substr(0, unit_of(output).find('/')); }

std::size_t unconverged(const study::ModelRao& model) {
  std::size_t count = 0;
  for (const study::ResonancePeak& peak : model.peaks) count += peak.converged ? 0 : 1;
  return count;
}

std::string peak_text(const study::ResonancePeak& peak) {
  return fmt::format("{} {:.4g} {} at {:.4g} s{}", name_of(peak.output), peak.amplitude, unit_of(peak.output),
                     period_of(peak.angular_frequency), peak.converged ? "" : fmt::format(" (not converged, {} vertices)", peak.steps));
}

}  // namespace

std::string resonance_peaks_csv(const study::RaoResult& result) {
  std::string out = "model,mode,natural_period_s,damping_ratio,dominant,output,peak_period_s,peak_angular_frequency_rad_per_s,"
                    "amplitude,unit,vertices,converged\n";
  for (const study::ModelRao& m : result.models) {
    for (const study::ResonancePeak& peak : m.peaks) {
      const study::NaturalMode& mode = m.modes.at(peak.mode);
      out += fmt::format("{},{},{:.10g},{:.8g},{},{},{:.10g},{:.10g},{:.10g},{},{},{}\n", m.choice.label(), peak.mode + 1, mode.period(),
                         mode.damping_ratio, mode.dominant, name_of(peak.output), period_of(peak.angular_frequency),
                         peak.angular_frequency, peak.amplitude, unit_of(peak.output), peak.steps, peak.converged ? "yes" : "no");
    }
  }
  return out;
}

std::string resonance_markdown(const study::RaoResult& result) {
  std::string out;
  if (result.peak_search) {
    out += fmt::format(
        "\n## Resonance peaks\n\nEach model's grid is refined around every resonant coupled mode (0 < ζ < 1/√2) whose "
        "one-degree-of-freedom peak ω_n √(1 − 2ζ²) lies in the band: frequencies at that peak ± 1, 2, {0:g} ζω_n, then, for "
        "every output with a local maximum there, at the vertex of the parabola through 1/|Y|² against ω² at the largest "
        "sample and its neighbours, until the response at the vertex is within {1:g} % of the largest sample (at most {2} "
        "vertices). The largest sample is the peak below; `resonance_peaks.csv` lists every output.\n\n"
        "| model | mode | T_n [s] | ζ | dominant | peaks (output, amplitude, period) |\n|---|---:|---:|---:|---|---|\n",
        result.peak_search->window, 100.0 * result.peak_search->tolerance, result.peak_search->max_steps);
    for (const study::ModelRao& m : result.models) {
      for (std::size_t j = 0; j < m.modes.size(); ++j) {
        std::vector<std::string> peaks;
        for (const study::ResonancePeak& peak : m.peaks) {
          if (peak.mode == j) peaks.push_back(peak_text(peak));
        }
        if (peaks.empty()) continue;
        out += fmt::format("| {} | {} | {:.4g} | {:.3g} % | {} | {} |\n", m.choice.label(), j + 1, m.modes[j].period(),
                           100.0 * m.modes[j].damping_ratio, m.modes[j].dominant, fmt::join(peaks, "; "));
      }
    }
  }
  if (result.sea) {
    out += fmt::format("\n## In the sea\n\nSea spectrum {}: m0 = {:.4g} m², of which {:.1f} % lies in the band of the "
                       "frequencies (only that part counts). Significant response 4 √(∫ |Y|² S dω), trapezoid rule over each "
                       "model's frequencies:\n\n| output |",
                       spectrum_label(result.sea->spectrum), result.sea->m0, 100.0 * result.sea->band_share());
    for (const study::ModelRao& m : result.models) out += fmt::format(" {} |", m.choice.label());
    out += "\n|---|";
    for (std::size_t m = 0; m < result.models.size(); ++m) out += "---:|";
    out += '\n';
    for (int k = 0; k < multibody::linear_output_count; ++k) {
      out += fmt::format("| {} [{}] |", name_of(k), response_unit(k));
      for (const study::ModelRao& m : result.models) {
        out += rao_drawn(m, static_cast<LinearOutput>(k)) ? fmt::format(" {:.4g} |", m.significant_response[static_cast<std::size_t>(k)])
                                                          : " 0 (rigid) |";
      }
      out += '\n';
    }
  }
  return out;
}

std::string resonance_text(const study::RaoResult& result) {
  std::string out;
  if (result.peak_search) {
    out += fmt::format("\nresonance peaks (grid refined until the vertex is within {:g} % of the peak):\n", 100.0 * result.peak_search->tolerance);
    for (const study::ModelRao& m : result.models) {
      out += fmt::format("  {}: {} frequencies added, {} peaks{}\n", m.choice.label(), m.added_frequencies, m.peaks.size(),
                         unconverged(m) == 0 ? "" : fmt::format(", {} not converged", unconverged(m)));
      for (const study::ResonancePeak& peak : m.peaks) {
        if (!peak.converged) out += fmt::format("warning: {} mode {}: {}\n", m.choice.label(), peak.mode + 1, peak_text(peak));
      }
    }
  }
  if (result.sea) {
    out += fmt::format("\nsignificant responses in {} ({:.1f} % of m0 in the band):\n", spectrum_label(result.sea->spectrum),
                       100.0 * result.sea->band_share());
    for (int k = 0; k < multibody::linear_output_count; ++k) {
      out += fmt::format("  {:<15}", name_of(k));
      for (const study::ModelRao& m : result.models) {
        if (rao_drawn(m, static_cast<LinearOutput>(k))) {
          out += fmt::format("  {} {:.4g} {}", m.choice.label(), m.significant_response[static_cast<std::size_t>(k)], response_unit(k));
        }
      }
      out += '\n';
    }
  }
  return out;
}

std::string check_diagnosis(const study::TimeDomainCheck& check, const std::string& prefix) {
  std::string out;
  for (const study::PeriodCheck& p : check.periods) {
    if (p.worst_deviation() <= check.request.tolerance) continue;
    out += fmt::format("{}{} T = {:g} s deviates {:.3f} %", prefix, check.choice.label(), p.period, 100.0 * p.worst_deviation());
    if (p.nearest_mode) {
      out += fmt::format("; the nearest resonant mode is {} (T_n = {:.4g} s, ζ = {:.3g} %), {} its half-power band", p.nearest_mode->dominant,
                         p.nearest_mode->period(), 100.0 * p.nearest_mode->damping_ratio, p.in_half_power_band ? "inside" : "outside");
    }
    if (p.probe) {
      out += fmt::format("; at half the wave height ({:g} m) it deviates {:.3f} %", p.probe->wave_height, 100.0 * p.probe->worst_deviation);
      out += p.amplitude_dependent()
                 ? fmt::format(" (∝ H^{:.2g}): the test wave is not small enough{} — the response is nonlinear in the wave height, "
                               "not a defect of the linearisation",
                               p.probe->exponent, p.in_half_power_band ? " near this resonance" : "")
                 : ": not an amplitude effect (look at the fit residual, the integrator tolerance, the model)";
    }
    out += '\n';
  }
  return out;
}

std::string check_hint(const study::TimeDomainCheck& check) {
  const std::optional<double> height = check.suggested_wave_height();
  return height ? fmt::format("rerun with --check-wave-height {:g} (the deviation shrinks with the wave height)", *height) : "";
}

void add_resonance_json(Json& model_json, const study::ModelRao& model, const study::RaoResult& result) {
  if (result.peak_search) {
    Json peaks = Json::array();
    for (const study::ResonancePeak& peak : model.peaks) {
      const study::NaturalMode& mode = model.modes.at(peak.mode);
      peaks.push_back({{"mode", peak.mode + 1}, {"natural_period_s", mode.period()}, {"damping_ratio", mode.damping_ratio},
                       {"output", name_of(peak.output)}, {"peak_period_s", period_of(peak.angular_frequency)},
                       {"amplitude", peak.amplitude}, {"unit", unit_of(peak.output)}, {"vertices", peak.steps},
                       {"converged", peak.converged}});
    }
    model_json["resonance_peaks"] = std::move(peaks);
  }
  if (result.sea) {
    Json significant = Json::object();
    for (int k = 0; k < multibody::linear_output_count; ++k) {
      significant[name_of(k)] = {{"value", model.significant_response[static_cast<std::size_t>(k)]}, {"unit", response_unit(k)}};
    }
    model_json["significant_response"] = std::move(significant);
  }
}

}  // namespace ffrf::report
