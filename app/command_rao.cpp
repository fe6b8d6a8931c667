// `ffrf rao SCENE`: the frequency domain, the second method that checks the time domain — RAOs of the crane linearised about its
// static equilibrium, rigid, nodal and modal booms side by side (or the one model the options
// name), the coupled natural modes, and with --check-time-domain the regular-wave time-domain runs
// judged against the RAOs (study/rao.hpp, study/rao_check.hpp). Text on stdout (--json: the JSON
// summary); --out DIR: per model rao_MODEL.csv, natural_modes.csv, resonance_peaks.csv (the grid
// refined at each resonance peak unless --no-refine-peaks), sea_spectrum.csv (with --spectrum or the
// scene's irregular sea), report.md, summary.json, the charts (with their gnuplot scripts) and
// time_domain_check.csv — written completely or not at all.
// Exit 0, 1 when the time-domain check fails, 2 bad input, 3 a solver failed.
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "app/option_checks.hpp"
#include "hydro/wave_spectrum.hpp"
#include "report/chart_notes.hpp"
#include "report/gnuplot.hpp"
#include "report/output_directory.hpp"
#include "report/rao_charts.hpp"
#include "report/rao_report.hpp"
#include "report/rao_resonance.hpp"
#include "scene/irregular_sea.hpp"
#include "study/rao.hpp"
#include "study/rao_check.hpp"

namespace ffrf::app {
namespace {

struct RaoOptions {
  std::string scene;
  std::vector<std::string> set;  // --set KEY=VALUE
  ModelOptions model;
  std::string periods;      // "a:b:n" [s]
  std::string frequencies;  // "w1,w2,..." [rad/s]
  bool check_time_domain = false;
  std::string check_periods = "8,10,14";
  double check_wave_height = 0.2;
  std::string tolerance = "1%";
  std::string spectrum;     // "jonswap:Hs:Tp[:gamma]", "pm:Hs:Tp", "none"; empty: the scene's sea
  bool no_refine_peaks = false;
  bool json = false;
  std::string out;
};

const std::string default_periods = fmt::format("{:g}:{:g}:{}", study::default_rao_shortest_period,
                                                study::default_rao_longest_period, study::default_rao_period_count);
constexpr double max_period = study::max_rao_period;        // [s]
constexpr double max_frequency = study::max_rao_frequency;  // [rad/s]

int bad_input(const std::string& message) { return app::bad_input("rao", message); }

double number(const std::string& option, const std::string& text, const std::string& field) {
  char* end = nullptr;
  const double value = std::strtod(field.c_str(), &end);
  if (field.empty() || end != field.c_str() + field.size() || !std::isfinite(value)) {
    throw BadOption(fmt::format("{} {}: '{}' is not a finite number", option, text, field));
  }
  return value;
}

std::vector<std::string> fields(const std::string& text, char separator) {
  std::vector<std::string> out;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, separator);) out.push_back(item);
  if (!text.empty() && text.back() == separator) out.emplace_back();
  return out;
}

// "a:b:n" periods [s], evenly spaced, as angular frequencies (longest period first).
std::vector<double> parse_period_range(const std::string& text) {
  const std::vector<std::string> parts = fields(text, ':');
  const std::string expected = fmt::format("expected a:b:n in s with 0 < a < b <= {:g} and an integer count n in [2, 10000]", max_period);
  if (parts.size() != 3) throw BadOption(fmt::format("--periods {}: malformed, not three fields separated by ':' ({})", text, expected));
  const double a = number("--periods", text, parts[0]), b = number("--periods", text, parts[1]), n = number("--periods", text, parts[2]);
  if (!(a > 0.0) || !(b > a) || b > max_period || n != std::floor(n) || n < 2.0 || n > 10000.0) {
    throw BadOption(fmt::format("--periods {}: out of range ({})", text, expected));
  }
  return study::period_grid(a, b, static_cast<int>(n));
}

// "x,y,..." positive numbers below `maximum`.
std::vector<double> parse_list(const std::string& option, const std::string& text, double maximum, const char* unit) {
  std::vector<double> values;
  for (const std::string& field : fields(text, ',')) {
    const double value = number(option, text, field);
    if (!(value > 0.0) || value > maximum) {
      throw BadOption(fmt::format("{} {}: {:g} is out of range (valid range (0, {:g}] {})", option, text, value, maximum, unit));
    }
    values.push_back(value);
  }
  if (values.empty()) throw BadOption(fmt::format("{} {}: no value given", option, text));
  return values;
}

// --spectrum: "jonswap:Hs:Tp[:gamma]" or "pm:Hs:Tp" (Hs in m, Tp in s), "none"; empty: the scene's own
// parametric irregular sea when it has one (a sea of given components has no spectrum to draw).
std::optional<hydro::WaveSpectrum> sea_spectrum(const std::string& text, const scene::Scene& scene) {
  if (text.empty()) return study::default_sea_spectrum(scene);
  if (text == "none") return std::nullopt;
  const std::vector<std::string> parts = fields(text, ':');
  const std::string expected = "expected jonswap:Hs:Tp[:gamma] or pm:Hs:Tp with 0 < Hs <= 30 m, 0 < Tp <= 100 s, 1 <= gamma <= 20, or none";
  const bool jonswap = !parts.empty() && parts[0] == "jonswap", pm = !parts.empty() && parts[0] == "pm";
  if (!(jonswap && (parts.size() == 3 || parts.size() == 4)) && !(pm && parts.size() == 3)) {
    throw BadOption(fmt::format("--spectrum {}: malformed ({})", text, expected));
  }
  const double hs = number("--spectrum", text, parts[1]), tp = number("--spectrum", text, parts[2]);
  const double gamma = parts.size() == 4 ? number("--spectrum", text, parts[3]) : 3.3;
  if (!(hs > 0.0 && hs <= 30.0) || !(tp > 0.0 && tp <= 100.0) || !(gamma >= 1.0 && gamma <= 20.0)) {
    throw BadOption(fmt::format("--spectrum {}: out of range ({})", text, expected));
  }
  return jonswap ? hydro::jonswap(hs, tp, gamma) : hydro::pierson_moskowitz(hs, tp);
}

bool model_given(const ModelOptions& m) {
  return !m.boom.empty() || m.elements || m.modes || m.static_modes || m.no_static_modes || !m.stiffening.empty();
}

void write_outputs(report::StagedDirectory& out, const study::RaoResult& result,
                   const std::vector<study::TimeDomainCheck>& checks, const report::RaoContext& context) {
  const std::string terminal = report::png_terminal();
  for (std::size_t m = 0; m < result.models.size(); ++m) {
    out.write(fmt::format("rao_{}.csv", report::model_slug(result.models[m].choice)), report::rao_csv(result, m));
  }
  out.write("natural_modes.csv", report::natural_modes_csv(result));
  if (result.peak_search) out.write("resonance_peaks.csv", report::resonance_peaks_csv(result));
  if (result.sea) out.write("sea_spectrum.csv", report::sea_spectrum_csv(result));
  if (!checks.empty()) out.write("time_domain_check.csv", report::time_domain_check_csv(checks));
  for (const std::string& name : report::rao_chart_names()) report::draw_chart(out, name, report::rao_chart_script(name, result, terminal));
  out.write("report.md", report::rao_markdown(result, checks, context, true) + report::charts_markdown(out));
  out.write("summary.json", report::with_charts_json(report::rao_json(result, checks, context), out));
  out.commit();
  fmt::print(stderr, "{}", report::chart_notes_text("rao", out));
}

int run_rao(const RaoOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const std::optional<scene::Scene> scene = load_scene(options.scene, options.set, "rao", true);
  if (!scene) return exit_bad_input;
  study::RaoRequest request;
  study::TimeDomainCheckRequest check_request;
  try {
    if (model_given(options.model)) request.models = {boom_choice(options.model, default_boom_choice(*scene))};
    request.angular_frequencies =
        options.frequencies.empty() ? (options.periods.empty() ? study::default_rao_frequencies() : parse_period_range(options.periods))
                                    : parse_list("--frequencies", options.frequencies, max_frequency, "rad/s");
    check_request.periods = parse_list("--check-periods", options.check_periods, max_period, "s");
    check_request.wave_height = options.check_wave_height;
    check_request.tolerance = parse_tolerance(options.tolerance);
    request.refine_peaks = study::default_refine_peaks && !options.no_refine_peaks;
    request.sea_spectrum = sea_spectrum(options.spectrum, *scene);
  } catch (const BadOption& error) {
    return bad_input(error.what());
  }
  if (!scene->is_crane()) {
    return bad_input(fmt::format("{}: the frequency domain needs a floating crane ([hull], [cargo], [wire]); this scene has a [hub] "
                                 "and no water", options.scene));
  }
  std::optional<report::StagedDirectory> out;
  if (!options.out.empty()) {
    report::png_terminal();  // fail before the computation when gnuplot is missing
    out.emplace(options.out, "summary.json");
  }
  std::string running;
  study::RaoResult result;
  std::vector<study::TimeDomainCheck> checks;
  try {
    modal::ModeCache modes;
    result = study::response_amplitude_operators(*scene, request, [&](const std::string& label) {
      running = label;
      progress("rao", "linearising " + label + " ...");
    }, &modes);
    if (options.check_time_domain) {
      for (const study::ModelRao& model : result.models) {
        running = model.choice.label();
        checks.push_back(study::check_time_domain(*scene, model.choice, check_request, [&](double period, double height) {
          progress("rao", fmt::format("time-domain check {}: {:g} s wave, {:g} m high ...", running, period, height));
        }, &modes));
      }
    }
    progress("rao", "");
  } catch (const scene::SceneError& error) {
    return scene_error("rao", options.scene, error, "the " + running + " crane");
  } catch (const solve::SolverFailure& failure) {
    return solver_failure("rao", running, failure, options.out);
  } catch (const study::SettingError& error) {
    return bad_input(option_message(error));
  }
  report::RaoContext context{options.scene, scene->name,
                             std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
  if (out) write_outputs(*out, result, checks, context);
  fmt::print("{}", options.json ? report::rao_json(result, checks, context) : report::rao_text(result, checks, context));
  if (!options.out.empty() && !options.json) fmt::print("\nwrote {} (report.md)\n", options.out);
  for (const study::TimeDomainCheck& check : checks) {
    if (!check.passed()) {
      const std::string hint = report::check_hint(check);
      fmt::print(stderr, "ffrf rao: the time-domain check failed: {} deviates {:.3f} % from its RAO (tolerance {:.3f} %){}\n",
                 check.choice.label(), 100.0 * check.worst_deviation(), 100.0 * check.request.tolerance,
                 hint.empty() ? "" : "; " + hint);
      return exit_failure;
    }
  }
  return exit_ok;
}

}  // namespace

Command add_rao_command(CLI::App& parent) {
  auto options = std::make_shared<RaoOptions>();
  CLI::App* sub = parent.add_subcommand(
      "rao", "Frequency domain: RAOs and coupled natural modes of the crane linearised about its static equilibrium, rigid, "
             "nodal and modal k = 2 + static booms (the scene's boom.elements) side by side, the grid refined at the resonance "
             "peaks, a sea spectrum over the charts; --check-time-domain against regular-wave runs");
  sub->add_option("scene", options->scene, "Scene file (TOML) with [hull], [boom], [cargo] and [wire]")->required();
  add_set_option(*sub, options->set);
  add_model_options(*sub, options->model);
  auto* periods = sub->add_option("--periods", options->periods,
                                  fmt::format("Wave periods a:b:n [s], n evenly spaced from a to b (default {})", default_periods));
  auto* frequencies = sub->add_option("--frequencies", options->frequencies, "Angular frequencies w1,w2,... [rad/s] instead of --periods");
  periods->excludes(frequencies);
  sub->add_flag("--check-time-domain", options->check_time_domain,
                "Run regular-wave time-domain runs of every model at --check-periods and judge their amplitudes (hull heave, "
                "hull pitch, cargo heave) against the RAOs within --tolerance");
  sub->add_option("--check-periods", options->check_periods, "Wave periods of the time-domain check [s]")->capture_default_str();
  sub->add_option("--check-wave-height", options->check_wave_height, "Wave height of the time-domain check [m] (small: linear)")
      ->capture_default_str()
      ->check(finite_number(0.0, 10.0, "m", true));
  add_tolerance_option(*sub, options->tolerance, "the time-domain amplitudes pass when within it of the RAOs");
  sub->add_option("--spectrum", options->spectrum,
                  "Sea spectrum drawn over the RAO charts (second axis), with each output's significant response "
                  "4 sqrt(int |RAO|^2 S dw): jonswap:Hs:Tp[:gamma] (gamma 3.3 unless given) or pm:Hs:Tp; none: no spectrum "
                  "(default: the scene's own irregular sea when it has a JONSWAP or Pierson-Moskowitz one)");
  sub->add_flag("--no-refine-peaks", options->no_refine_peaks,
                "Evaluate the requested frequencies only (default: each model's grid is refined around its resonance peaks "
                "until the peak amplitude is within 0.1 %)");
  sub->add_flag("--json", options->json, "Print the JSON summary on stdout instead of the text summary");
  sub->add_option("--out", options->out,
                  "Write rao_MODEL.csv per model, natural_modes.csv, report.md, summary.json, the PNG charts (with their "
                  "gnuplot scripts) and time_domain_check.csv into this directory");
  return {sub, [options] { return run_rao(*options); }};
}

}  // namespace ffrf::app
