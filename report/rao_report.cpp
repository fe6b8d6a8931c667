// CSV, Markdown, JSON, text and gnuplot renderings of the frequency domain (report/rao_report.hpp).
#include "report/rao_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "report/gnuplot.hpp"
#include "report/json.hpp"
#include "report/quantities.hpp"
#include "report/rao_charts.hpp"
#include "report/rao_resonance.hpp"

namespace ffrf::report {
namespace {

using multibody::LinearOutput;

constexpr int shown_modes = 8;  // natural modes in the tables (the lowest)

LinearOutput output_at(int k) { return static_cast<LinearOutput>(k); }
std::string name_of(LinearOutput output) { return std::string(multibody::to_string(output)); }
std::string unit_slug(LinearOutput output) {  // "m/m" → "m_per_m"
  std::string unit(multibody::unit_per_amplitude(output));
  return unit.replace(unit.find('/'), 1, "_per_");
}
double phase_degrees(double radians) { return radians * 180.0 / std::numbers::pi; }
// The boom's element count as the model uses it ("rigid" for the rigid boom).
std::string boom_elements(const scene::BoomChoice& choice) {
  return choice.kind == scene::BoomKind::rigid ? std::string("rigid") : std::to_string(choice.elements);
}
Json boom_elements_json(const scene::BoomChoice& choice) {
  return choice.kind == scene::BoomKind::rigid ? Json(nullptr) : Json(choice.elements);
}
// "109" or "109 + 38" (the refinement's).
std::string frequency_count(const study::ModelRao& model) {
  const std::size_t requested = model.angular_frequencies.size() - model.added_frequencies;
  return model.added_frequencies > 0 ? fmt::format("{} + {}", requested, model.added_frequencies) : std::to_string(requested);
}

std::string percent(double fraction) { return fmt::format("{:.3f} %", 100.0 * fraction); }

}  // namespace

std::string model_slug(const scene::BoomChoice& choice) {
  switch (choice.kind) {
    case scene::BoomKind::rigid: return "rigid";
    case scene::BoomKind::nodal: return fmt::format("nodal_N{}", choice.elements);
    case scene::BoomKind::modal:
      return fmt::format("modal_k{}{}_N{}", choice.modes, choice.static_modes ? "_static" : "", choice.elements);
  }
  return "model";
}

std::string rao_csv(const study::RaoResult& result, std::size_t model) {
  const study::ModelRao& m = result.models.at(model);
  std::string out = "period_s,angular_frequency_rad_per_s";
  for (int k = 0; k < multibody::linear_output_count; ++k) {
    out += fmt::format(",{0}_amplitude_{1},{0}_phase_deg", name_of(output_at(k)), unit_slug(output_at(k)));
  }
  out += '\n';
  for (std::size_t f = 0; f < m.angular_frequencies.size(); ++f) {
    const double omega = m.angular_frequencies[f];
    out += fmt::format("{:.10g},{:.10g}", period_of(omega), omega);
    for (int k = 0; k < multibody::linear_output_count; ++k) {
      const std::complex<double> value = m.response[static_cast<std::size_t>(k)][f];
      out += fmt::format(",{:.10g},{:.6f}", std::abs(value), phase_degrees(std::arg(value)));
    }
    out += '\n';
  }
  return out;
}

std::string natural_modes_csv(const study::RaoResult& result) {
  std::string out = "model,mode,angular_frequency_rad_per_s,period_s,damping_ratio,dominant\n";
  for (const study::ModelRao& m : result.models) {
    for (std::size_t j = 0; j < m.modes.size(); ++j) {
      const study::NaturalMode& mode = m.modes[j];
      out += fmt::format("{},{},{:.10g},{:.10g},{:.8g},{}\n", m.choice.label(), j + 1, mode.angular_frequency, mode.period(),
                         mode.damping_ratio, mode.dominant);
    }
  }
  return out;
}

namespace {

// Where the hull's radiation (and excitation) came from, for the report's prose.
std::string hull_hydrodynamics(const study::RaoResult& result) {
  if (result.bem_radiation) {
    const std::string excitation = result.bem_excitation_file.empty()
                                       ? "wave excitation from the Froude–Krylov pressure on the wetted box"
                                       : fmt::format("wave excitation X(ω) of `{}` (linear between its frequencies)", result.bem_excitation_file);
    const std::string radiation =
        *result.bem_radiation == study::BemRadiationSource::file
            ? fmt::format("A(ω), B(ω) of `{}` (linear between its frequencies)", result.bem_radiation_file)
            : fmt::format("A(ω), B(ω) as the {} radiation model realises them", result.bem_radiation_model);
    return fmt::format("{}, moved to G1; {}; hydrostatic restoring of the calm-water pressure on the wetted box (the time "
                       "domain's); natural modes of the {} model's memory (roots of det(s²M + sC + K + Z(s)))",
                       radiation, excitation, result.bem_radiation_model);
  }
  return result.frequency_dependent_hydrodynamics ? "frequency-dependent coefficients from the provider"
                                                  : "the scene's constant added mass and damping";
}

}  // namespace

std::string time_domain_check_csv(const std::vector<study::TimeDomainCheck>& checks) {
  std::string out = "model,period_s,output,rao_amplitude,time_domain_amplitude,deviation,phase_difference_rad,fit_residual,"
                    "steps,wall_s,passed,model_rao_amplitude,model_deviation\n";
  for (const study::TimeDomainCheck& check : checks) {
    for (const study::PeriodCheck& p : check.periods) {
      for (const study::ChannelCheck& c : p.channels) {
        out += fmt::format("{},{:g},{},{:.10g},{:.10g},{:.6e},{:.6e},{:.3e},{},{:.4f},{},{}\n", check.choice.label(), p.period,
                           name_of(c.output), c.frequency_domain, c.time_domain, c.deviation(), c.phase_difference,
                           c.fit_residual, p.stats.steps, p.stats.wall_seconds,
                           std::abs(c.deviation()) <= check.request.tolerance ? "yes" : "no",
                           c.model_frequency_domain > 0.0 ? fmt::format("{:.10g},{:.6e}", c.model_frequency_domain, c.model_deviation())
                                                          : std::string(","));
      }
    }
  }
  return out;
}

namespace {

// The memory hull's modes Newton could not refine (study::NaturalMode::unrefined), one line each
// after `prefix`; empty when every mode asked to be refined was.
std::string unrefined_modes(const study::RaoResult& result, std::string_view prefix) {
  std::string out;
  for (const study::ModelRao& m : result.models) {
    for (std::size_t j = 0; j < m.modes.size(); ++j) {
      if (m.modes[j].unrefined.empty()) continue;
      out += fmt::format("{}{} mode {} (T = {:.4g} s) is the constant system's, not refined: {}\n", prefix, m.choice.label(), j + 1,
                         m.modes[j].period(), m.modes[j].unrefined);
    }
  }
  return out;
}

}  // namespace

std::string rao_markdown(const study::RaoResult& result, const std::vector<study::TimeDomainCheck>& checks,
                         const RaoContext& context, bool with_charts) {
  const auto& omegas = result.angular_frequencies;
  std::string out = fmt::format("# Frequency domain: {}\n\n", context.scene_name.empty() ? context.scene_file : context.scene_name);
  out += fmt::format("Scene `{}`. The crane linearised about its static equilibrium in calm water, in the time domain's "
                     "minimal coordinates (mass, damping and stiffness from the equations' own Newton blocks; wave "
                     "excitation as the derivative of the generalized forces in the wave amplitude, central difference "
                     "of ±{:g} m). Responses per metre of wave amplitude, phase relative to the elevation at x = 0. "
                     "{} frequencies, periods {:.4g}–{:.4g} s{}. Hull radiation: {}. Wall time {:.3g} s.\n\n",
                     context.scene_file, result.excitation_amplitude, omegas.size(), period_of(*std::max_element(omegas.begin(), omegas.end())),
                     period_of(*std::min_element(omegas.begin(), omegas.end())), result.peak_search ? " and the refinement's frequencies at the resonance peaks" : "",
                     hull_hydrodynamics(result), context.wall_seconds);
  out += "| model | boom elements | coordinates | frequencies | wall time [s] |\n|---|---:|---:|---:|---:|\n";
  for (const study::ModelRao& m : result.models) {
    out += fmt::format("| {} | {} | {} | {} | {:.3g} |\n", m.choice.label(), boom_elements(m.choice), m.coordinates,
                       frequency_count(m), m.wall_seconds);
  }
  out += "\n## Coupled natural modes\n\nPeriod [s], damping ratio and the coordinate holding most of the mode's kinetic "
         "energy, lowest modes first.\n\n| mode |";
  for (const study::ModelRao& m : result.models) out += fmt::format(" {} |", m.choice.label());
  out += "\n|---:|";
  for (std::size_t m = 0; m < result.models.size(); ++m) out += "---|";
  out += '\n';
  for (std::size_t j = 0; j < static_cast<std::size_t>(shown_modes); ++j) {
    out += fmt::format("| {} |", j + 1);
    for (const study::ModelRao& m : result.models) {
      out += j < m.modes.size() ? fmt::format(" {:.4g} s, ζ = {:.3g} %, {}{} |", m.modes[j].period(),
                                              100.0 * m.modes[j].damping_ratio, m.modes[j].dominant,
                                              m.modes[j].unrefined.empty() ? "" : " (not refined)")
                                : " – |";
    }
    out += '\n';
  }
  if (const std::string unrefined = unrefined_modes(result, "- "); !unrefined.empty()) {
    out += "\nModes of the memory hull that Newton's method on det D(s) did not refine (they are the constant "
           "system's roots):\n\n" + unrefined;
  }
  out += "\n## Largest response per output\n\n| output |";
  for (const study::ModelRao& m : result.models) out += fmt::format(" {} |", m.choice.label());
  out += "\n|---|";
  for (std::size_t m = 0; m < result.models.size(); ++m) out += "---|";
  out += '\n';
  for (int k = 0; k < multibody::linear_output_count; ++k) {
    out += fmt::format("| {} [{}] |", name_of(output_at(k)), multibody::unit_per_amplitude(output_at(k)));
    for (const study::ModelRao& m : result.models) {
      const auto& values = m.response[static_cast<std::size_t>(k)];
      const auto peak = std::max_element(values.begin(), values.end(),
                                         [](auto a, auto b) { return std::abs(a) < std::abs(b); });
      out += rao_drawn(m, output_at(k)) ? fmt::format(" {:.4g} at {:.4g} s |", std::abs(*peak),
                                                      period_of(m.angular_frequencies[static_cast<std::size_t>(peak - values.begin())]))
                                        : " 0 (rigid) |";
    }
    out += '\n';
  }
  out += resonance_markdown(result);
  if (with_charts) {
    out += "\n## Charts\n\nDashed vertical lines: the resonant coupled natural periods, in each model's colour";
    out += result.sea ? fmt::format("; dotted grey on the right axis: the sea spectrum ({}).\n\n", spectrum_label(result.sea->spectrum))
                      : ".\n\n";
    for (const std::string& name : rao_chart_names()) out += fmt::format("![{}]({}.png)\n\n", rao_chart_title(name), name);
  }
  out += "\n## Time-domain check\n\n";
  if (checks.empty()) return out + "Not run (`--check-time-domain` runs it).\n";
  const study::TimeDomainCheckRequest& request = checks.front().request;
  bool passed = true;
  double worst = 0.0;
  for (const auto& check : checks) {
    passed = passed && check.passed();
    worst = std::max(worst, check.worst_deviation());
  }
  out += fmt::format("**{}**: regular-wave runs (one run pipeline, CVODE BDF on the minimal coordinates, relative and "
                     "absolute tolerance {:g}, nonlinear hull pressure, wave height {:g} m ramped over {:g} periods, "
                     "amplitude fitted over the following {:g} periods with the free modes separated) against the RAOs: "
                     "worst amplitude deviation {} against the tolerance {}.\n\n",
                     passed ? "PASS" : "FAIL", request.relative_tolerance, request.wave_height, request.ramp_periods,
                     request.window_periods, percent(worst), percent(request.tolerance));
  const bool memory = checks.front().periods.front().channels.front().model_frequency_domain > 0.0;
  if (memory) {
    out += "A [bem] hull: the RAO is the files' (physical); the run's radiation model realises A(ω), B(ω) from its own "
           "kernel, whose RAO and the deviation from it are the last two columns (the consistent comparison; "
           "docs/hydrodynamics.md §6.1).\n\n";
  }
  out += "| model | period [s] | output | RAO | time domain | deviation | phase diff. [rad] | fit residual | steps | wall [s] | |";
  out += memory ? " RAO (model's radiation) | deviation from it |\n|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|\n"
                : "\n|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for (const auto& check : checks) {
    for (const auto& p : check.periods) {
      for (const auto& c : p.channels) {
        out += fmt::format("| {} | {:g} | {} | {:.6g} | {:.6g} | {:+.3f} % | {:+.2e} | {:.1e} | {} | {:.3g} | {} |\n",
                           check.choice.label(), p.period, name_of(c.output), c.frequency_domain, c.time_domain,
                           100.0 * c.deviation(), c.phase_difference, c.fit_residual, p.stats.steps, p.stats.wall_seconds,
                           std::abs(c.deviation()) <= request.tolerance ? "pass" : "**FAIL**");
        if (memory) {
          out.pop_back();
          out += fmt::format(" {:.6g} | {:+.3f} % |\n", c.model_frequency_domain, 100.0 * c.model_deviation());
        }
      }
    }
  }
  std::string diagnosis;
  for (const auto& check : checks) diagnosis += check_diagnosis(check, "- ");
  if (!diagnosis.empty()) out += "\nWhy the failed periods fail (each run again at half the wave height):\n\n" + diagnosis;
  return out;
}

std::string rao_json(const study::RaoResult& result, const std::vector<study::TimeDomainCheck>& checks, const RaoContext& context) {
  Json json{{"scene", context.scene_file},
            {"scene_name", context.scene_name},
            {"wall_s", context.wall_seconds},
            {"excitation_amplitude_m", result.excitation_amplitude},
            {"frequency_dependent_hydrodynamics", result.frequency_dependent_hydrodynamics},
            {"hull_hydrodynamics", hull_hydrodynamics(result)},
            {"angular_frequencies_rad_per_s", result.angular_frequencies}};
  if (result.peak_search) {
    json["peak_refinement"] = {{"tolerance", result.peak_search->tolerance}, {"max_steps", result.peak_search->max_steps},
                               {"window_zeta_omega", result.peak_search->window}};
  }
  if (result.sea) {
    json["sea"] = {{"spectrum", spectrum_label(result.sea->spectrum)}, {"m0_m2", result.sea->m0},
                   {"share_of_m0_in_band", result.sea->band_share()}};
  }
  json["models"] = Json::array();
  for (const study::ModelRao& m : result.models) {
    Json model{{"model", m.choice.label()}, {"boom_elements", boom_elements_json(m.choice)}, {"coordinates", m.coordinates},
               {"wall_s", m.wall_seconds}, {"angular_frequencies_rad_per_s", m.angular_frequencies},
               {"added_frequencies", m.added_frequencies}, {"natural_modes", Json::array()}};
    for (const study::NaturalMode& mode : m.modes) {
      model["natural_modes"].push_back({{"angular_frequency_rad_per_s", mode.angular_frequency},
                                        {"period_s", mode.period()},
                                        {"damping_ratio", mode.damping_ratio},
                                        {"dominant", mode.dominant}});
      if (!mode.unrefined.empty()) model["natural_modes"].back()["not_refined"] = mode.unrefined;
    }
    Json raos = Json::object();
    for (int k = 0; k < multibody::linear_output_count; ++k) {
      Json amplitude = Json::array(), phase = Json::array();
      for (const auto& value : m.response[static_cast<std::size_t>(k)]) {
        amplitude.push_back(std::abs(value));
        phase.push_back(phase_degrees(std::arg(value)));
      }
      raos[name_of(output_at(k))] = {{"unit", multibody::unit_per_amplitude(output_at(k))}, {"amplitude", amplitude}, {"phase_deg", phase}};
    }
    model["rao"] = std::move(raos);
    add_resonance_json(model, m, result);
    json["models"].push_back(std::move(model));
  }
  Json check_json = Json::array();
  for (const auto& check : checks) {
    Json entry{{"model", check.choice.label()}, {"tolerance", check.request.tolerance}, {"wave_height_m", check.request.wave_height},
               {"integrator_tolerance", check.request.relative_tolerance}, {"worst_deviation", check.worst_deviation()},
               {"passed", check.passed()}, {"periods", Json::array()}};
    if (const auto height = check.suggested_wave_height()) entry["suggested_wave_height_m"] = *height;
    for (const auto& p : check.periods) {
      Json period{{"period_s", p.period}, {"duration_s", p.duration}, {"window_start_s", p.window_start},
                  {"fitted_free_modes", p.fitted_modes}, {"steps", p.stats.steps},
                  {"function_evaluations", p.stats.function_evaluations}, {"wall_s", p.stats.wall_seconds},
                  {"channels", Json::array()}};
      if (p.nearest_mode) {
        period["nearest_resonant_mode"] = {{"dominant", p.nearest_mode->dominant}, {"period_s", p.nearest_mode->period()},
                                           {"damping_ratio", p.nearest_mode->damping_ratio},
                                           {"in_half_power_band", p.in_half_power_band}};
      }
      if (p.probe) {
        period["half_height_probe"] = {{"wave_height_m", p.probe->wave_height}, {"worst_deviation", p.probe->worst_deviation},
                                       {"exponent", p.probe->exponent}, {"amplitude_dependent", p.amplitude_dependent()}};
      }
      for (const auto& c : p.channels) {
        period["channels"].push_back({{"output", name_of(c.output)}, {"rao_amplitude", c.frequency_domain},
                                      {"time_domain_amplitude", c.time_domain}, {"deviation", c.deviation()},
                                      {"phase_difference_rad", c.phase_difference}, {"fit_residual", c.fit_residual},
                                      {"model_rao_amplitude", c.model_frequency_domain}, {"model_deviation", c.model_deviation()}});
      }
      entry["periods"].push_back(std::move(period));
    }
    check_json.push_back(std::move(entry));
  }
  json["time_domain_check"] = std::move(check_json);
  return json_text(json);
}

std::string rao_text(const study::RaoResult& result, const std::vector<study::TimeDomainCheck>& checks, const RaoContext& context) {
  std::string out = fmt::format("scene      {}{}\nfrequencies {} (periods {:.4g}-{:.4g} s), wall time {:.3g} s\nhull       {}\n", context.scene_file,
                                context.scene_name.empty() ? "" : " (" + context.scene_name + ")", result.angular_frequencies.size(),
                                period_of(*std::max_element(result.angular_frequencies.begin(), result.angular_frequencies.end())),
                                period_of(*std::min_element(result.angular_frequencies.begin(), result.angular_frequencies.end())),
                                context.wall_seconds, hull_hydrodynamics(result));
  for (const study::ModelRao& m : result.models) {
    out += fmt::format("\n{} ({} coordinates, boom elements {}, frequencies {}): coupled natural modes\n", m.choice.label(),
                       m.coordinates, boom_elements(m.choice), frequency_count(m));
    for (std::size_t j = 0; j < std::min<std::size_t>(shown_modes, m.modes.size()); ++j) {
      const study::NaturalMode& mode = m.modes[j];
      out += fmt::format("  {:>2}  T = {:>9.4f} s  omega = {:>9.4f} rad/s  zeta = {:>7.3f} %  {}{}\n", j + 1, mode.period(),
                         mode.angular_frequency, 100.0 * mode.damping_ratio, mode.dominant,
                         mode.unrefined.empty() ? "" : "  (not refined)");
    }
  }
  if (const std::string unrefined = unrefined_modes(result, "warning: "); !unrefined.empty()) out += "\n" + unrefined;
  out += resonance_text(result);
  for (const auto& check : checks) {
    out += fmt::format("\ntime-domain check {}: {} (worst amplitude deviation {} against {})\n", check.choice.label(),
                       check.passed() ? "PASS" : "FAIL", percent(check.worst_deviation()), percent(check.request.tolerance));
    out += check_diagnosis(check, "  ");
  }
  return out;
}

}  // namespace ffrf::report
